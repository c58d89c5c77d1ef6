// A trace for the terminal. The default layout fits 80 columns (a terminal,
// a projector): each step is its formula on one line and its value on the
// next. The wide layout is one aligned row a step. Both end with the branch
// taken, the result, the pixel's grey level, and a note on reading numbers.
#pragma once

#include <string>

#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

enum class TraceLayout { narrow, wide };

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary,
                              TraceLayout layout = TraceLayout::narrow);

// "a 7 × 7 pane", "an 8 × 8 pane", "an 11 × 11 pane": English's article for a number.
std::string pane_phrase(int w);

}  // namespace promyk
