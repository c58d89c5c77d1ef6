// How the bench writes its measured numbers: a fixed count of decimals (a
// table's column lines up), in the run's language (a decimal comma in Polish).
#pragma once

#include <string>

#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/wrap.hpp"

namespace promyk::bench {

inline std::string fixed(double value, int decimals) { return number_text(value, ui_language(), decimals); }

// A message as the bench prints it below a title: every line of it indented
// by two spaces, a line too long for 80 columns continued four spaces in.
// A message breaks its own lines where a number of varying length would
// otherwise move the break (docs/bench.md compares runs by their lines).
inline std::string indented(const std::string& text) {
    std::string out = "  ";
    for (const char c : text) out += c == '\n' ? std::string("\n  ") : std::string(1, c);
    return wrap_text(out, 4);
}

}  // namespace promyk::bench
