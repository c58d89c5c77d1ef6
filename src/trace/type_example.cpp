#include "trace/type_example.hpp"

#include <cmath>
#include <optional>

#include "math/decimal.hpp"
#include "math/real.hpp"
#include "trace/number_text.hpp"

namespace promyk {

namespace {

constexpr double article_z_S = 3.2;  // the article's sphere centre's z: the example when the scene has none
constexpr std::size_t shown_digits = 20;
constexpr std::size_t short_digits = 6;  // a number the reader types: 3.2, 0.125, 1.05

// A number as the reader types it: a plain decimal (no exponent) of at
// most short_digits significant digits.
bool short_decimal(const std::string& text, TypedNumber& number) {
    const std::optional<TypedNumber> typed = parse_typed_number(text);
    if (!typed || text.find('e') != std::string::npos || strip_zeros(typed->digits).size() > short_digits)
        return false;
    number = *typed;
    return true;
}

// ±digits × 10^-scale as a plain decimal with a point: "0.016", "10.24".
std::string plain_text(std::string digits, int scale) {
    return typed_number_text(TypedNumber{false, std::move(digits), scale}, Language::en);
}

// The stored value's first digits, cut, not rounded: the "…" after them
// stands for the rest.
template <class Real, class Square>
TypeExample example_in(Real stored, std::string type, const std::string& text, const TypedNumber& typed,
                       Square square) {
    TypeExample example;
    example.type = std::move(type);
    example.number = text;
    const TypedNumber exact = exact_decimal(stored);
    const std::string digits = strip_zeros(exact.digits);
    const int cut_digits = digits.size() > shown_digits ? static_cast<int>(digits.size() - shown_digits) : 0;
    example.stored = plain_text(digits.substr(0, digits.size() - static_cast<std::size_t>(cut_digits)),
                                exact.scale - cut_digits);
    example.cut = cut_digits > 0;
    example.square = square(stored);
    const TypedNumber exact_square = multiply(typed, typed);
    example.exact_square = plain_text(exact_square.digits, exact_square.scale);
    return example;
}

// The example for x (> 0) in the trace's type; false when the type holds
// x's decimal exactly.
bool example_of(double x, const std::string& real, TypeExample& example) {
    const std::string text = real_text(x);
    TypedNumber typed;
    if (!short_decimal(text, typed)) return false;
    const auto differs = [&](const TypedNumber& stored) { return !is_zero(absolute_difference(stored, typed)); };
    if (real == "float") {
        const float z = static_cast<float>(x);
        if (!differs(exact_decimal(static_cast<double>(z)))) return false;
        example = example_in(static_cast<double>(z), "float", text, typed,
                             [&](double) { return real_text(z * z); });
        return true;
    }
    if (real == "long-double") {
#if PROMYK_HAS_X87_LONG_DOUBLE
        const long double z = x;
        if (!differs(exact_decimal(z))) return false;
        example = example_in(z, "long double", text, typed, [](long double v) { return real_text(v * v); });
#else
        // No x87 here (the wasm): the square rounded to its 64-bit significand.
        const quad z = x;
        if (!differs(exact_decimal(z))) return false;
        example = example_in(z, "long double", text, typed, [](quad v) { return real_text(x87_rounded(v * v)); });
#endif
        return true;
    }
    if (real == "quad") {
        const quad z = x;
        if (!differs(exact_decimal(z))) return false;
        example = example_in(z, "quad", text, typed, [](quad v) { return real_text(v * v); });
        return true;
    }
    if (!differs(exact_decimal(x))) return false;
    example = example_in(x, "double", text, typed, [](double v) { return real_text(v * v); });
    return true;
}

// 0.3 is no binary fraction, yet 0.3² prints as 0.09 in double: the
// square's shortest text is the decimal square, and shows nothing.
bool square_looks_exact(const TypeExample& example) {
    const std::optional<TypedNumber> square = parse_typed_number(example.square);
    const std::optional<TypedNumber> exact_square = parse_typed_number(example.exact_square);
    return square && exact_square && is_zero(absolute_difference(*square, *exact_square));
}

}  // namespace

TypeExample type_example(const std::string& real, const std::vector<double>& given) {
    TypeExample example;
    for (double value : given) {
        const double x = std::fabs(value);
        if (!(x >= 0.01 && x <= 10000)) continue;  // NaN too
        if (example_of(x, real, example) && !square_looks_exact(example)) return example;
    }
    example_of(article_z_S, real, example);
    return example;
}

}  // namespace promyk
