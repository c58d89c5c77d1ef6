// A trace as an aligned table for the terminal: step, key, symbol, formula,
// value; then the branch taken and the result.
#pragma once

#include <string>

#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary);

}  // namespace promyk
