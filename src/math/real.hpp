// The real types the engine computes in (`--real`): float, double, long
// double and quad (GCC's __float128, libquadmath). Every stage is written over
// a Real type; RealTraits gives each type the few things the standard library
// does not give all four alike in strict C++17 (numeric_limits and sqrt are
// not defined for __float128 there).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include <quadmath.h>

namespace promyk {

using quad = __float128;

enum class RealType { float_, double_, long_double, quad_ };

constexpr std::string_view real_type_name(RealType type) {
    switch (type) {
        case RealType::float_:
            return "float";
        case RealType::double_:
            return "double";
        case RealType::long_double:
            return "long-double";
        case RealType::quad_:
            return "quad";
    }
    return "?";
}

template <class Real>
struct RealTraits {
    static constexpr RealType type = std::is_same_v<Real, float>    ? RealType::float_
                                     : std::is_same_v<Real, double> ? RealType::double_
                                                                    : RealType::long_double;
    static Real max() { return std::numeric_limits<Real>::max(); }
    static Real lowest() { return std::numeric_limits<Real>::lowest(); }
    static Real infinity() { return std::numeric_limits<Real>::infinity(); }
    static Real quiet_nan() { return std::numeric_limits<Real>::quiet_NaN(); }
    static Real sqrt(Real x) { return std::sqrt(x); }
    static Real fma(Real a, Real b, Real c) { return std::fma(a, b, c); }
};

template <>
struct RealTraits<quad> {
    static constexpr RealType type = RealType::quad_;
    // The largest finite quad: the value just below infinity (FLT128_MAX is
    // spelled with a GNU literal suffix that strict C++17 does not accept).
    static quad max() { return nextafterq(infinity(), 0); }
    static quad lowest() { return -max(); }
    static quad infinity() { return quad(std::numeric_limits<double>::infinity()); }
    static quad quiet_nan() { return nanq(""); }
    // libquadmath's sqrtq is faithful, not correctly rounded (about one
    // result in five is the other neighbour): corrected here, so that quad
    // rounds like every other type. The remainder r = x - s^2 of a faithful
    // s is exact in quad (and fmaq computes it exactly); s is the correctly
    // rounded root when x lies between (s - u/2)^2 and (s + u/2)^2 (u the
    // spacing of quads at s, the same both sides unless s is a power of two),
    // that is when -s u + u^2/4 <= r <= s u + u^2/4; ties cannot happen.
    static quad sqrt(quad x) {
        const quad s = sqrtq(x);
        if (!(s > 0) || !(s < max())) return s;  // 0, NaN, infinity, negative
        const quad up = nextafterq(s, infinity());
        const quad down = nextafterq(s, quad(0));
        const quad r = fmaq(-s, s, x);
        // Compare x with the midpoints exactly: (s + up)/2 squared against x
        // is the sign of x - ((s + up)/2)^2 = r - (up - s)(s + (up - s)/4).
        const quad u_up = up - s, u_down = s - down;  // exact: neighbours
        if (r > 0 && r - u_up * s > u_up * u_up / 4) return up;
        if (r < 0 && r + u_down * s < u_down * u_down / 4) return down;
        return s;
    }
    static quad fma(quad a, quad b, quad c) { return fmaq(a, b, c); }
};

// The correctly rounded square root in the value's own type.
template <class Real>
Real square_root(Real x) {
    return RealTraits<Real>::sqrt(x);
}

// a * b + c with one rounding (a fused multiply-add), in the value's own type.
template <class Real>
Real fused_multiply_add(Real a, Real b, Real c) {
    return RealTraits<Real>::fma(a, b, c);
}

// The shortest decimal text that reads back to the same value in its own
// type ("inf", "-inf", "nan" for non-finite values).
std::string real_text(float x);
std::string real_text(double x);
std::string real_text(long double x);
std::string real_text(quad x);

// |x| in any real type, quad included (std::fabs does not take one).
template <class Real>
Real magnitude(Real x) {
    return x < 0 ? -x : x;
}

}  // namespace promyk
