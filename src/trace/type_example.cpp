#include "trace/type_example.hpp"

#include "math/decimal.hpp"
#include "math/real.hpp"

namespace promyk {

namespace {

constexpr double z_S = 3.2;  // the article's sphere centre's z
constexpr std::size_t shown_digits = 20;

// The exact decimal's first digits, cut, not rounded: the "…" after them
// stands for the rest. 3.2 in any type has one digit before the point.
TypeExample stored_as(const TypedNumber& exact, std::string type, std::string square) {
    const std::string digits = strip_zeros(exact.digits);
    const std::string kept = digits.substr(0, shown_digits);
    return {std::move(type), kept.substr(0, 1) + "." + kept.substr(1), digits.size() > kept.size(), std::move(square)};
}

}  // namespace

TypeExample type_example(const std::string& real) {
    if (real == "float") {
        const float z = static_cast<float>(z_S);
        return stored_as(exact_decimal(static_cast<double>(z)), "float", real_text(z * z));
    }
    if (real == "long-double") {
#if PROMYK_HAS_X87_LONG_DOUBLE
        const long double z = z_S;
        return stored_as(exact_decimal(z), "long double", real_text(z * z));
#else
        // No x87 here (the wasm): the square rounded to its 64-bit significand.
        const quad z = z_S;
        return stored_as(exact_decimal(z), "long double", real_text(x87_rounded(z * z)));
#endif
    }
    if (real == "quad") {
        const quad z = z_S;
        return stored_as(exact_decimal(z), "quad", real_text(z * z));
    }
    return stored_as(exact_decimal(z_S), "double", real_text(z_S * z_S));
}

}  // namespace promyk
