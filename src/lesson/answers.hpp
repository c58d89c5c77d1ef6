// Checking a student's numbers: `promyk lesson NAME --answers FILE`.
//
// The file is what a student types: `key = value` lines (C = 6,4,
// P = (0,132; 0,132; 2,116)), `#` comments, `[i,j]` headings when the lesson
// has several pixels; or a flat JSON object {"C": 6.4}, or a whole trace as
// `promyk trace --format json` prints it. Numbers are kept as typed: an answer
// is right when it equals the trace's value rounded (halves away from zero)
// to the digits the student wrote, compared exactly in decimal.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lesson/lesson.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

// A number as typed: ±digits × 10^-scale. "6,40" is {false, "640", 2};
// "−4.5e-3" is {true, "45", 4}; "1e3" is {false, "1", -3}.
struct TypedNumber {
    bool negative = false;
    std::string digits;  // at least one digit; leading zeros kept
    int scale = 0;       // digits after the decimal point (negative: whole tens, hundreds ...)
};

// A number in either language's style: a decimal comma or point, a minus
// '-', '−' (U+2212) or '–', an optional exponent (1.5e-3). Nothing if it is not one.
std::optional<TypedNumber> parse_typed_number(std::string_view text);

// The value rounded half away from zero to `scale` decimals, as the digits of
// ±N (N × 10^-scale), exactly: the double's binary value is expanded in full.
TypedNumber round_exactly(double value, int scale);

// The number as text in a language's style (decimal comma and '−' in Polish).
std::string typed_number_text(const TypedNumber& number, Language language);

enum class Verdict {
    right,        // equals the value rounded to the digits written
    wrong_way,    // the other neighbour: rounded down where it rounds up, or up where it rounds down
    wrong,
    not_reached,  // the pixel's computation never reached this value (t for a miss)
    wrong_shape,  // three numbers for a single number, or one for a point or vector
    blank,        // "key =" with nothing after it: not answered
};

// `typed` against the exact value: right, wrong_way or wrong; `expected` is
// the value at the student's precision.
Verdict compare_number(double reference, const TypedNumber& typed, TypedNumber& expected);

struct Answer {
    int line = 0;        // 0 in JSON
    std::string key;     // a vocabulary key
    char component = 0;  // key.x, key.y, key.z
    std::string text;    // as typed (trimmed)
    std::vector<TypedNumber> numbers;  // 1, or 3 for a point or vector; empty: blank
};

struct PixelAnswers {
    LessonPixel pixel;
    std::vector<Answer> answers;
};

// Reads an answer file. Lines before any [i,j] heading belong to `first`.
// InputError (exit 3) naming `file` and the line (or JSON pointer) of a
// fault, worded in `language`.
// `scene_hash`, when not empty, is the lesson's scene's: a whole trace of
// another scene (its "scene_hash" differs) is refused.
std::vector<PixelAnswers> parse_answers(std::string_view text, const std::string& file, const Vocabulary& vocabulary,
                                        Language language, LessonPixel first, int w, const std::string& scene_hash = "");

struct AnswerCheck {
    LessonPixel pixel;
    Answer answer;
    Verdict verdict = Verdict::right;
    std::vector<TypedNumber> expected;  // at the student's precision, one per number typed
};

// Checks each answer against the trace of its pixel (`traces` must hold one
// for every pixel the answers name), in derivation order within each pixel.
std::vector<AnswerCheck> check_answers(const std::vector<PixelAnswers>& answers, const std::vector<PixelTrace>& traces);

// The report, step by step, in `language`; ends with a count.
std::string answers_report(const std::vector<AnswerCheck>& checks, const std::vector<PixelTrace>& traces,
                           const Vocabulary& vocabulary, Language language);

// True when nothing checked is wrong (blank answers do not count).
bool all_right(const std::vector<AnswerCheck>& checks);

}  // namespace promyk
