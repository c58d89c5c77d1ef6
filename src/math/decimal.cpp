#include "math/decimal.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

namespace promyk {

namespace {

__extension__ typedef unsigned __int128 uint128;

// m × 2^e2 exactly, m < 2^113: multiply the decimal digits of m by 2^e2, or
// by 5^-e2 and move the point -e2 places (m × 2^-k = m × 5^k / 10^k).
TypedNumber expand(bool negative, uint128 m, int e2) {
    TypedNumber out;
    out.negative = negative;
    if (m == 0) {
        out.digits = "0";
        return out;
    }
    while ((m & 1U) == 0) {
        m >>= 1U;
        ++e2;
    }
    std::vector<std::uint32_t> little;  // little-endian decimal digits
    for (; m != 0; m /= 10) little.push_back(static_cast<std::uint32_t>(m % 10));
    const auto multiply = [&little](std::uint64_t factor) {
        std::uint64_t carry = 0;
        for (std::uint32_t& digit : little) {
            const std::uint64_t product = digit * factor + carry;
            digit = static_cast<std::uint32_t>(product % 10);
            carry = product / 10;
        }
        for (; carry != 0; carry /= 10) little.push_back(static_cast<std::uint32_t>(carry % 10));
    };
    // Powers in chunks (2^30, 5^13 fit with room for the carry).
    const std::uint64_t factor = e2 >= 0 ? 2 : 5;
    const int chunk = e2 >= 0 ? 30 : 13;
    std::uint64_t power = 1;
    for (int k = 0; k < chunk; ++k) power *= factor;
    int left = e2 >= 0 ? e2 : -e2;
    for (; left >= chunk; left -= chunk) multiply(power);
    for (; left > 0; --left) multiply(factor);
    out.scale = e2 >= 0 ? 0 : -e2;
    for (auto it = little.rbegin(); it != little.rend(); ++it) out.digits += static_cast<char>('0' + *it);
    return out;
}

// Aligned digit strings of |a| and |b| at their common scale.
std::pair<std::string, std::string> aligned(const TypedNumber& a, const TypedNumber& b, int& scale) {
    scale = std::max(a.scale, b.scale);
    std::string x = strip_zeros(a.digits) + std::string(static_cast<std::size_t>(scale - a.scale), '0');
    std::string y = strip_zeros(b.digits) + std::string(static_cast<std::size_t>(scale - b.scale), '0');
    x = strip_zeros(x);
    y = strip_zeros(y);
    return {x, y};
}

int compare_digits(const std::string& x, const std::string& y) {
    if (x.size() != y.size()) return x.size() < y.size() ? -1 : 1;
    const int c = x.compare(y);
    return c < 0 ? -1 : c > 0 ? 1 : 0;
}

// x + y and x − y (x ≥ y) of digit strings without leading zeros.
std::string add_digits(const std::string& x, const std::string& y) {
    std::string sum;
    int carry = 0;
    for (std::size_t k = 0; k < std::max(x.size(), y.size()) || carry; ++k) {
        const int dx = k < x.size() ? x[x.size() - 1 - k] - '0' : 0;
        const int dy = k < y.size() ? y[y.size() - 1 - k] - '0' : 0;
        const int d = dx + dy + carry;
        sum += static_cast<char>('0' + d % 10);
        carry = d / 10;
    }
    std::reverse(sum.begin(), sum.end());
    return strip_zeros(sum);
}

std::string subtract_digits(const std::string& x, const std::string& y) {
    std::string difference;
    int borrow = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        int d = (x[x.size() - 1 - k] - '0') - (k < y.size() ? y[y.size() - 1 - k] - '0' : 0) - borrow;
        borrow = d < 0;
        if (d < 0) d += 10;
        difference += static_cast<char>('0' + d);
    }
    std::reverse(difference.begin(), difference.end());
    return strip_zeros(difference);
}

}  // namespace

TypedNumber exact_decimal(double value) {
    int exponent = 0;
    const double mantissa = std::frexp(std::fabs(value), &exponent);
    return expand(std::signbit(value), static_cast<std::uint64_t>(std::ldexp(mantissa, 53)), exponent - 53);
}

#if PROMYK_HAS_X87_LONG_DOUBLE
TypedNumber exact_decimal(long double value) {
    int exponent = 0;
    const long double mantissa = std::frexp(std::fabs(value), &exponent);
    constexpr int bits = std::numeric_limits<long double>::digits;  // 64 on x86, 53 or 113 elsewhere
    if constexpr (bits > 64) {
        return exact_decimal(static_cast<quad>(value));
    } else {
        return expand(std::signbit(value), static_cast<std::uint64_t>(std::ldexp(mantissa, bits)), exponent - bits);
    }
}

#endif

TypedNumber exact_decimal(quad value) {
    int exponent = 0;
    const quad mantissa = quad_math::frexp(quad_math::fabs(value), &exponent);
    return expand(quad_math::signbit(value), static_cast<uint128>(quad_math::ldexp(mantissa, 113)), exponent - 113);
}

std::optional<TypedNumber> exact_value_of(const std::string& text, RealType type) {
    const char* begin = text.c_str();
    char* end = nullptr;
    if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos) return std::nullopt;
    std::optional<TypedNumber> out;
    switch (type) {
        case RealType::float_: {
            const float x = std::strtof(begin, &end);
            if (std::isfinite(x)) out = exact_decimal(static_cast<double>(x));
            break;
        }
        case RealType::double_: {
            const double x = std::strtod(begin, &end);
            if (std::isfinite(x)) out = exact_decimal(x);
            break;
        }
        case RealType::long_double: {
#if PROMYK_HAS_X87_LONG_DOUBLE
            const long double x = std::strtold(begin, &end);
            if (std::isfinite(x)) out = exact_decimal(x);
#else
            // No x87 here (wasm): the text read in quad, rounded to the x87's 64 bits.
            const quad x = x87_rounded(quad_math::from_text(begin, &end));
            if (quad_math::finite(x)) out = exact_decimal(x);
#endif
            break;
        }
        case RealType::quad_: {
            const quad x = quad_math::from_text(begin, &end);
            if (quad_math::finite(x)) out = exact_decimal(x);
            break;
        }
    }
    if (end != begin + text.size()) return std::nullopt;
    return out;
}

std::string strip_zeros(const std::string& digits) {
    const std::size_t first = digits.find_first_not_of('0');
    return first == std::string::npos ? "0" : digits.substr(first);
}

bool is_zero(const TypedNumber& number) { return number.digits.find_first_not_of('0') == std::string::npos; }

int compare_magnitude(const TypedNumber& a, const TypedNumber& b) {
    int scale = 0;
    const auto [x, y] = aligned(a, b, scale);
    return compare_digits(x, y);
}

TypedNumber absolute_difference(const TypedNumber& a, const TypedNumber& b) {
    TypedNumber out;
    const auto [x, y] = aligned(a, b, out.scale);
    const bool same_sign = a.negative == b.negative || is_zero(a) || is_zero(b);
    if (!same_sign)
        out.digits = add_digits(x, y);
    else
        out.digits = compare_digits(x, y) >= 0 ? subtract_digits(x, y) : subtract_digits(y, x);
    return out;
}

TypedNumber multiply(const TypedNumber& a, const TypedNumber& b) {
    const std::string x = strip_zeros(a.digits), y = strip_zeros(b.digits);
    std::vector<int> sum(x.size() + y.size(), 0);
    for (std::size_t p = x.size(); p-- > 0;)
        for (std::size_t q = y.size(); q-- > 0;) sum[p + q + 1] += (x[p] - '0') * (y[q] - '0');
    for (std::size_t k = sum.size(); k-- > 1;) {
        sum[k - 1] += sum[k] / 10;
        sum[k] %= 10;
    }
    TypedNumber out;
    for (const int digit : sum) out.digits += static_cast<char>('0' + digit);
    out.digits = strip_zeros(out.digits);
    out.scale = a.scale + b.scale;
    out.negative = a.negative != b.negative && out.digits != "0";
    return out;
}

quad to_quad(const TypedNumber& number) {
    const std::string text = (number.negative ? "-" : "") + strip_zeros(number.digits) + "e" + std::to_string(-number.scale);
    return quad_math::from_text(text.c_str(), nullptr);
}

quad x87_rounded(quad x) {
    if (!quad_math::finite(x) || x == 0) return x;
    int exponent = 0;
    const quad m = quad_math::frexp(quad_math::fabs(x), &exponent);  // [1/2, 1)
    // m × 2^64 rounded to an integer, half to even (the default rounding):
    // adding and subtracting 2^112 leaves no fraction bits in quad.
    const quad big = quad_math::ldexp(quad(1), 112);
    const quad rounded = (quad_math::ldexp(m, 64) + big) - big;
    const quad magnitude = quad_math::ldexp(rounded, exponent - 64);
    return quad_math::signbit(x) ? -magnitude : magnitude;
}

namespace {
constexpr int max_typed_scale = 1100;  // parse_typed_number's bound on a number's decimals
}  // namespace

std::optional<TypedNumber> parse_typed_number(std::string_view text) {
    TypedNumber number;
    std::size_t at = 0;
    for (const std::string_view sign : {"-", "\u2212", "\u2013", "+"}) {
        if (text.substr(0, sign.size()) == sign) {
            number.negative = sign != "+";
            at = sign.size();
            break;
        }
    }
    bool point = false;
    int after_point = 0;
    for (; at < text.size(); ++at) {
        const char c = text[at];
        if (c >= '0' && c <= '9') {
            number.digits += c;
            if (point) ++after_point;
        } else if ((c == '.' || c == ',') && !point) {
            point = true;
        } else {
            break;
        }
    }
    if (number.digits.empty() || (point && after_point == 0)) return std::nullopt;
    int exponent = 0;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        bool negative = false;
        if (at < text.size() && (text[at] == '-' || text[at] == '+')) negative = text[at++] == '-';
        const std::size_t start = at;
        for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at)
            if (at - start < 6) exponent = exponent * 10 + (text[at] - '0');
        if (at == start || at - start > 4) return std::nullopt;
        if (negative) exponent = -exponent;
    }
    if (at != text.size()) return std::nullopt;
    number.scale = after_point - exponent;
    // A double's exact decimal expansion has at most 1074 decimals; beyond some
    // such bound a "precision" is a typo (1e-9999), not a claim worth expanding.
    if (number.scale > max_typed_scale || number.scale < -max_typed_scale) return std::nullopt;
    return number;
}

}  // namespace promyk
