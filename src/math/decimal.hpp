// Exact decimals: a number as a student typed it, or a real type's binary
// value expanded in full (every float, double, long double and quad is a
// finite binary fraction, so its decimal expansion ends). The answer checker
// and `promyk diff` compare numbers in this form, never through a rounding.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "math/real.hpp"

namespace promyk {

// ±digits × 10^-scale. "6,40" is {false, "640", 2}; "−4.5e-3" is
// {true, "45", 4}; "1e3" is {false, "1", -3}.
struct TypedNumber {
    bool negative = false;
    std::string digits;  // at least one digit; leading zeros kept
    int scale = 0;       // digits after the decimal point (negative: whole tens, hundreds ...)
};

// A number in either language's style: a decimal comma or point, a minus
// '-', '−' (U+2212) or '–', an optional exponent (1.5e-3). Nothing if it is not one.
std::optional<TypedNumber> parse_typed_number(std::string_view text);

// The value's exact decimal expansion (digits without leading zeros; "0" for
// zero). The value must be finite.
TypedNumber exact_decimal(double value);
#if PROMYK_HAS_X87_LONG_DOUBLE
TypedNumber exact_decimal(long double value);
#endif
TypedNumber exact_decimal(quad value);

// `text` (a real_text, "0.1", "-1.5e-3") read in `type` (correctly rounded,
// as the C library reads it) and expanded exactly: float's 0.1 is
// 0.100000001490116119384765625. Nothing for a non-finite or unreadable text.
std::optional<TypedNumber> exact_value_of(const std::string& text, RealType type);

// The digits without leading zeros ("0" for none but zeros).
std::string strip_zeros(const std::string& digits);

// |a − b|, exactly.
TypedNumber absolute_difference(const TypedNumber& a, const TypedNumber& b);

// a × b, exactly (a fraction's denominator times a value).
TypedNumber multiply(const TypedNumber& a, const TypedNumber& b);

// −1, 0 or 1 as |a| is less than, equal to or greater than |b|.
int compare_magnitude(const TypedNumber& a, const TypedNumber& b);

// True when the number is zero.
bool is_zero(const TypedNumber& number);

// The number in quad (rounded once): for ratios that need no exactness.
quad to_quad(const TypedNumber& number);

// x rounded to the x87 long double's 64-bit significand (half to even), for
// reading a long-double trace where there is no x87 (wasm). Subnormal x87
// values are not treated apart (a trace's values are far from them).
quad x87_rounded(quad x);

}  // namespace promyk
