// A trace for the terminal, in Polish or English. The default layout fits 80
// columns (a terminal, a projector): each step is its formula on one line and
// its value on the next. The wide layout is one aligned row a step. Both end
// with the branch taken, the result, the pixel's grey level, and a note on
// reading numbers. The words come from lessons/messages.json.
#pragma once

#include <string>

#include "trace/number_text.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

enum class TraceLayout { narrow, wide };

struct TraceTextOptions {
    TraceLayout layout = TraceLayout::narrow;
    Language language = Language::en;
    bool explain = false;  // each step's description from the vocabulary under its formula
    int digits = 0;        // significant digits shown (0: every digit, the record)
};

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary,
                              const TraceTextOptions& options = {});

// "a 7 × 7 pane", "an 8 × 8 pane", "an 11 × 11 pane": English's article for a number.
std::string pane_phrase(int w);

}  // namespace promyk
