// A trace for the terminal, in Polish or English. The default layout fits 80
// columns (a terminal, a projector): each step is its formula on one line and
// its value on the next. The wide layout is one aligned row a step. Both end
// with the branch taken, the result, the pixel's grey level, and a note on
// reading numbers. The words come from lessons/messages.json.
#pragma once

#include <string>
#include <vector>

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

// The pieces of the text trace the web page shows as well (one definition
// for both):
// the pixel's intensities when they follow from the steps (lit, shadowed, samples);
std::vector<double> trace_intensities(const PixelTrace& trace);
// whether a step's digits lost deserve the ⚠ mark (trace/digits_alarm.hpp);
bool trace_step_alarm(const Step& step, const PixelTrace& trace);
// "⚠ 9.1 digits lost …", "3.0 digits lost …", or "" below the count's threshold;
std::string trace_digits_lost_mark(const Step& step, const PixelTrace& trace, Language language);
// a step's value rounded to `digits` significant digits (0: every digit),
// from its exact text in its own real type when it has one;
std::string trace_step_value_text(const Step& step, const Vocabulary& vocabulary, const std::string& key,
                                  Language language, const std::string& real, int digits);
// a key's symbol in the language; a key's kind ("scalar", "point", ...).
std::string trace_symbol(const Vocabulary& vocabulary, const std::string& key, Language language);
std::string trace_kind(const Vocabulary& vocabulary, const std::string& key);

// "a 7 × 7 pane", "an 8 × 8 pane", "an 11 × 11 pane": English's article for a number.
std::string pane_phrase(int w);

}  // namespace promyk
