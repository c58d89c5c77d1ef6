#include "math/real.hpp"

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

namespace promyk {

namespace {

template <class Real>
std::string non_finite(Real x) {
    if (x != x) return "nan";
    return x < 0 ? "-inf" : "inf";
}

}  // namespace

// float and double: fmt's shortest round-trip form (Dragonbox).
std::string real_text(float x) {
    if (!(x * 0 == 0)) return non_finite(x);
    return fmt::format("{}", x);
}

std::string real_text(double x) {
    if (!(x * 0 == 0)) return non_finite(x);
    return fmt::format("{}", x);
}

// long double and quad: the fewest significant digits whose text reads back
// to the same value (at most 21 and 36 digits always do).
std::string real_text(long double x) {
    if (!(x * 0 == 0)) return non_finite(x);
    char text[64];
    for (int digits = 1; digits <= 21; ++digits) {
        std::snprintf(text, sizeof text, "%.*Lg", digits, x);
        if (std::strtold(text, nullptr) == x) break;
    }
    return text;
}

std::string real_text(quad x) {
    if (!(x * 0 == 0)) return non_finite(x);
    char text[64];
    for (int digits = 1; digits <= 36; ++digits) {
        quadmath_snprintf(text, sizeof text, "%.*Qg", digits, x);
        if (strtoflt128(text, nullptr) == x) break;
    }
    return text;
}

}  // namespace promyk
