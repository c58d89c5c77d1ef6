// Checking a student's numbers: `promyk lesson NAME --answers FILE`.
//
// The file is what a student types: `key = value` lines (C = 6,4,
// P = (0,132; 0,132; 2,116)), `#` comments, `[i,j]` headings when the lesson
// has several pixels; or a flat JSON object {"C": 6.4}, or a whole trace as
// `promyk trace --format json` prints it. Numbers are kept as typed: an answer
// is right when it equals the trace's value rounded (halves away from zero)
// to the digits the student wrote, compared exactly in decimal; or, with more
// digits than the run's type holds, or as a fraction (1/2), when it lies at
// least as near the exact value (the same pixel and formula in quad) as the
// computed value does.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lesson/lesson.hpp"
#include "math/decimal.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {


// The most bytes an answer file may have: a lesson of 10^5 pixels, every
// number of each, fits many times over.
constexpr std::size_t max_answer_bytes = 64u << 20;

// The value rounded half away from zero to `scale` decimals, as the digits of
// ±N (N × 10^-scale), exactly: the double's binary value is expanded in full.
TypedNumber round_exactly(double value, int scale);


enum class Verdict {
    right,        // equals the value rounded to the digits written (a fraction: equals the value)
    right_more_digits,  // more digits than the run's type holds, at least as near the exact value as the computed one
    right_nearer,       // a fraction at least as near the exact value as the computed one
    wrong_way,    // the other neighbour: rounded down where it rounds up, or up where it rounds down
    wrong,
    not_reached,  // the pixel's computation never reached this value (t for a miss)
    wrong_shape,  // three numbers for a single number, or one for a point or vector
    blank,        // "key =" with nothing after it: not answered
    unreadable,   // a line the checker cannot read (Answer::unreadable says why)
};

// The significant digits `real` (float, double, long-double, quad) holds
// faithfully (std::numeric_limits<T>::digits10): typed beyond them, a
// number is judged by its distance to the exact value.
int digits_held(const std::string& real);

// Significant digits as typed: "0,0120" has 3, "1.3667504955662156" 17.
int significant_digits(const TypedNumber& number);

// The settings qualifier of the exact value of a key in `settings` ("",
// "float", "geometric"): the same formula in quad ("quad", "quad,geometric").
std::string exact_settings(const std::string& settings);

// `typed` against the exact value: right, wrong_way or wrong; `expected` is
// the value at the student's precision.
Verdict compare_number(double reference, const TypedNumber& typed, TypedNumber& expected);
// The same against an exact value (a float's, long double's or quad's).
Verdict compare_number(const TypedNumber& reference, const TypedNumber& typed, TypedNumber& expected);

struct Answer {
    int line = 0;        // 0 in JSON
    std::string key;     // a vocabulary key
    char component = 0;  // key.x, key.y, key.z
    std::string text;    // as typed (trimmed)
    std::vector<TypedNumber> numbers;  // 1, or 3 for a point or vector; empty: blank (a fraction's numerator)
    // Each number's denominator when one is a fraction ("1/2", "−3/4"); empty: no fractions.
    std::vector<TypedNumber> over;
    std::string pointer;     // JSON: where the answer stands ("/C")
    std::string unreadable;  // not empty: why the answer cannot be read (then key may be empty, text is the line)
    // From a whole trace of a non-double type: each number's real_text (the
    // value's text in its own type), beside `numbers` (its double value).
    std::vector<std::string> real_text;
};

struct PixelAnswers {
    LessonPixel pixel;
    std::vector<Answer> answers;
};

// What a whole trace, read as answers, says of itself.
struct TraceSummary {
    std::string real = "double";  // numeric.real: float, double, long-double, quad
    std::string formula;
    std::string scene;
    std::string scene_hash;  // empty when the trace has none
    int w = 0;
    std::string branch;  // miss, dark, lit, ... (empty when the trace has none)
    std::string hit;     // the object hit ("sphere 0"), when the trace says
    // Steps with no finite number: read, but with nothing to compare.
    struct NonFinite {
        std::string path;
        std::string text;        // "nan", "-inf", "[1, inf, 2]"
        std::size_t before = 0;  // how many answers come before it in the trace
    };
    std::vector<NonFinite> non_finite;
};

struct AnswerFile {
    std::vector<PixelAnswers> pixels;
    std::optional<TraceSummary> trace;  // when the file is a whole trace
};

struct AnswerLimits {
    // Pixel headings and a trace's pixel must lie in the w × w pane, and a
    // trace must be of that pane; 0: any pane.
    int w = 0;
    // Not empty: a whole trace of another scene (its "scene_hash" differs) is refused.
    std::string scene_hash;
    // A lesson's answers may qualify a key with other settings ("delta@float",
    // lesson.hpp); `promyk diff`'s may not.
    bool settings = false;
    // A lesson's reader forgives: a bad line (unknown key, not a number,
    // a key given twice, ...) is an unreadable answer and the rest are read;
    // fractions are numbers. Without it (`promyk diff`) the first fault is an
    // InputError. A forgiving read refuses (InputError) only a file that is not
    // UTF-8, is larger than max_answer_bytes, is broken JSON, or has no readable answer.
    bool forgiving = false;
    // The lesson's own keys (lesson_check.hpp: lesson_keys), named with the nearest when a key is unknown.
    std::vector<std::string> keys;
};

// Reads an answer file: `key = value` lines, a flat JSON object or a whole
// trace (`promyk lesson --answers` and `promyk diff` read the same files).
// Lines before any [i,j] heading belong to `first`. InputError (exit 3)
// naming `file` and the line (or JSON pointer) of a fault, worded in `language`.
AnswerFile read_answers(std::string_view text, const std::string& file, const Vocabulary& vocabulary, Language language,
                        LessonPixel first, const AnswerLimits& limits);

// Reads an answer file for a lesson: read_answers in its w × w pane;
// `scene_hash`, when not empty, is the lesson's scene's.
std::vector<PixelAnswers> parse_answers(std::string_view text, const std::string& file, const Vocabulary& vocabulary,
                                        Language language, LessonPixel first, int w, const std::string& scene_hash = "",
                                        bool settings = false);

struct AnswerCheck {
    LessonPixel pixel;
    Answer answer;
    Verdict verdict = Verdict::right;
    std::vector<TypedNumber> expected;  // at the student's precision, one per number typed
    // Judged wrong with no exact value at hand (`others` had no quad trace of
    // the pixel), where the exact value could make it right: a fraction, or
    // more digits than the type holds. Tracing the pixel in quad (exact_settings)
    // and checking again settles it; only these need the quad trace.
    bool needs_exact = false;
};

// Checks each answer against the trace of its pixel (`traces` must hold one
// for every pixel the answers name), in derivation order within each pixel.
// An answer's key may name other settings ("delta@float"): `others` holds
// the traces of the pixels in those settings (lesson_render.hpp: lesson_number).
std::vector<AnswerCheck> check_answers(const std::vector<PixelAnswers>& answers, const std::vector<PixelTrace>& traces,
                                       const std::vector<PixelTrace>& others = {});

// The report, step by step, in `language`; ends with a count.
std::string answers_report(const std::vector<AnswerCheck>& checks, const std::vector<PixelTrace>& traces,
                           const Vocabulary& vocabulary, Language language, const std::vector<PixelTrace>& others = {});

// One answer's mark as the report words it (without its indent and
// wrapping): the message id ("answers_right", "answers_wrong_way", ...) and
// its text in `language`. `trace` is the trace of the answer's pixel.
struct AnswerMark {
    std::string id;
    std::string text;
};
AnswerMark answer_mark(const AnswerCheck& check, const PixelTrace* trace, const Vocabulary& vocabulary, Language language,
                       const std::vector<PixelTrace>& others = {});

// True when nothing checked is wrong (blank answers do not count).
bool all_right(const std::vector<AnswerCheck>& checks);

}  // namespace promyk
