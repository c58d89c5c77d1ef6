// `promyk diff A B`: two readings of one pixel compared step by step. Each
// side is an answer file (answers.hpp): a whole trace (`promyk trace --format
// json`, any real type) or a student's numbers (`key = value` lines, a flat
// JSON object). Steps are matched by their path (t, light[0].D,
// sphere[1].t) and compared as exact decimals: a trace's value in its own
// type (its real_text read back in that type, else its double value), a
// student's number as typed.
//
// How many digits agree: the most significant digits n such that the two
// differ by at most half a unit in the n-th significant digit of the larger
// (3.14159 and 3.14160 agree to 5 digits; 0.1 and float's 0.1,
// 0.100000001490116…, to 8).
//
// Tolerance: by default the less precise side's precision, step by step. A
// trace in a type of p bits carries a relative error of at most 2^-p per
// rounding (float 2^-24 ≈ 10^-7.2, double 2^-53 ≈ 10^-15.9, long double
// 2^-64 ≈ 10^-19.3, quad 2^-113 ≈ 10^-34); a typed number is good to half a
// unit in its last digit. Two numbers agree when their difference is within
// either side's tolerance. With a relative tolerance (--tol) instead, they
// agree when |a − b| ≤ tol · max(|a|, |b|).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lesson/answers.hpp"

namespace promyk {

// One input, read.
struct DiffInput {
    std::string file;    // as shown in messages ("(stdin)" for -)
    AnswerFile answers;  // read with read_answers(…, diff_first_pixel, {})
};

// The pixel that lines before any [i,j] heading belong to, when a file is
// read for diff: the pixel of the other side's trace, whichever it is.
inline constexpr LessonPixel diff_first_pixel{-1, -1};

// A number of one side, as compared.
struct DiffNumber {
    std::string text;   // as the side writes it: a trace's real_text or value, a student's number as typed
    TypedNumber exact;  // the exact value compared
    int bits = 0;       // a trace: its type's precision in bits (24, 53, 64, 113); 0: typed
    int scale = 0;      // typed: digits after the decimal point
};

struct DiffComponent {
    char component = 0;  // 'x', 'y', 'z' (a point or vector), 'r', 'g', 'b' (a colour); 0 for one number
    DiffNumber a, b;
    std::optional<int> digits;  // significant digits that agree; nothing when the two are equal
    TypedNumber difference;     // |a − b|, exactly
    double relative = 0;        // |a − b| / max(|a|, |b|) (0 when both are 0)
    double tolerance = 0;       // the relative tolerance applied (|a − b| allowed / max(|a|, |b|))
    bool within = true;
};

enum class DiffStatus {
    agree,       // every component within tolerance
    differ,      // some component beyond it
    shape,       // one number on one side, three on the other
    non_finite,  // no finite number on one side or both (NaN, infinity), and not the same
    only_a,      // a step only A has
    only_b,
};

struct DiffStep {
    std::string path;  // t, P, light[0].D
    DiffStatus status = DiffStatus::agree;
    std::vector<DiffComponent> components;  // agree, differ: the components both sides give
    std::string a_text, b_text;             // each side's value as written (empty where absent)
};

struct DiffOptions {
    std::optional<double> relative_tolerance;  // --tol; nothing: each side's precision
};

struct DiffResult {
    std::vector<DiffStep> steps;       // in derivation order
    std::optional<std::size_t> first;  // the first step that differs (differ, shape or non_finite)
    std::size_t common = 0;            // steps both sides give
    LessonPixel pixel{-1, -1};         // the pixel compared ({-1, -1}: no trace says)
};

// Compares the two inputs. The pixel is a trace's (A's when both are
// traces); a student's file contributes its lines for that pixel and those
// before any heading. InputError when neither side is a trace and a file
// heads several pixels (which one to compare?), worded in `language`.
DiffResult diff_inputs(const DiffInput& a, const DiffInput& b, const Vocabulary& vocabulary, const DiffOptions& options,
                       Language language);

// The significant digits a and b agree to (nothing when they are equal).
std::optional<int> digits_agreeing(const TypedNumber& a, const TypedNumber& b);

// The bits of precision of a real type's name (float 24, double 53,
// long-double 64, quad 113); nothing for a name promyk does not know.
std::optional<int> real_type_bits(const std::string& real);

// The report for a terminal, in `language`.
std::string diff_report(const DiffResult& result, const DiffInput& a, const DiffInput& b, const DiffOptions& options,
                        const Vocabulary& vocabulary, Language language);

// The result as one JSON object (documented by src/trace/diff.schema.json).
std::string diff_json(const DiffResult& result, const DiffInput& a, const DiffInput& b, const DiffOptions& options);

}  // namespace promyk
