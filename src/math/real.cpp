#include "math/real.hpp"

#include <cstdio>
#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include "math/decimal.hpp"

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
#if PROMYK_HAS_X87_LONG_DOUBLE
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
#else
// The same search with the project's own "%.*Qg" (tested against
// libquadmath's in the native build: tests/quad_text_tests.cpp).
std::string real_text(quad x) {
    if (!(x * 0 == 0)) return non_finite(x);
    std::string text;
    for (int digits = 1; digits <= 36; ++digits) {
        text = quad_g_text(x, digits);
        if (quad_math::from_text(text.c_str(), nullptr) == x) break;
    }
    return text;
}
#endif

std::string quad_g_text(quad x, int digits) {
    digits = std::max(1, std::min(digits, 40));
    const TypedNumber exact = exact_decimal(x);  // ±digits × 10^-scale
    std::string all = strip_zeros(exact.digits);
    const bool negative = exact.negative;
    if (all == "0") {
        // %g of zero: "0" ("-0" for negative zero).
        return negative ? "-0" : "0";
    }
    // The decimal exponent X of the leading digit: value = 0.d1d2... × 10^(size - scale).
    int X = static_cast<int>(all.size()) - exact.scale - 1;
    // Round to `digits` significant digits, half to even (the exact value
    // is a finite decimal: a tie is a true tie).
    if (static_cast<int>(all.size()) > digits) {
        const std::size_t keep = static_cast<std::size_t>(digits);
        const char next = all[keep];
        const bool rest_zero = all.find_first_not_of('0', keep + 1) == std::string::npos;
        std::string kept = all.substr(0, keep);
        const bool up = next > '5' || (next == '5' && (!rest_zero || (kept.back() - '0') % 2 == 1));
        if (up) {
            std::size_t k = kept.size();
            while (k > 0 && kept[k - 1] == '9') kept[--k] = '0';
            if (k == 0) {
                kept.insert(kept.begin(), '1');
                kept.pop_back();
                ++X;
            } else {
                ++kept[k - 1];
            }
        }
        all = kept;
    }
    all.resize(static_cast<std::size_t>(digits), '0');
    // %g: the fixed form when -4 <= X < digits, else the exponent form;
    // trailing zeros (and a trailing point) removed.
    auto trimmed = [](std::string s) {
        if (s.find('.') == std::string::npos) return s;
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
        return s;
    };
    std::string out;
    if (X >= -4 && X < digits) {
        if (X >= 0) {
            out = all.substr(0, static_cast<std::size_t>(X) + 1);
            if (static_cast<int>(all.size()) > X + 1) out += "." + all.substr(static_cast<std::size_t>(X) + 1);
        } else {
            out = "0." + std::string(static_cast<std::size_t>(-X - 1), '0') + all;
        }
        out = trimmed(out);
    } else {
        out = trimmed(all.substr(0, 1) + "." + all.substr(1));
        const int e = X < 0 ? -X : X;
        out += fmt::format("e{}{:02}", X < 0 ? '-' : '+', e);
    }
    return negative ? "-" + out : out;
}

}  // namespace promyk
