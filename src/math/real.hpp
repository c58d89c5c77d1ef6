// The real types the engine computes in (`--real`): float, double, long
// double and quad (GCC's __float128, libquadmath). In WebAssembly (emscripten)
// quad is `long double`, which is IEEE binary128 there, and the x87 long
// double does not exist (PROMYK_HAS_X87_LONG_DOUBLE is 0). Every stage is written over
// a Real type; RealTraits gives each type the few things the standard library
// does not give all four alike in strict C++17 (numeric_limits and sqrt are
// not defined for __float128 there).
#pragma once

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#if !defined(__EMSCRIPTEN__)
#include <quadmath.h>
#endif

namespace promyk {

// quad's functions beyond + - * /, the same names in both builds.
#if defined(__EMSCRIPTEN__)
#define PROMYK_HAS_X87_LONG_DOUBLE 0
using quad = long double;  // binary128 in wasm, rounded like __float128 (sqrtl and fmal correctly)
namespace quad_math {
inline quad sqrt(quad x) { return sqrtl(x); }
inline quad fma(quad a, quad b, quad c) { return fmal(a, b, c); }
inline quad nextafter(quad x, quad y) { return nextafterl(x, y); }
inline quad nan() { return nanl(""); }
inline quad fabs(quad x) { return fabsl(x); }
inline quad frexp(quad x, int* exponent) { return frexpl(x, exponent); }
inline quad ldexp(quad x, int exponent) { return ldexpl(x, exponent); }
inline bool signbit(quad x) { return std::signbit(x); }
inline bool finite(quad x) { return std::isfinite(x); }
inline quad from_text(const char* text, char** end) { return std::strtold(text, end); }
}  // namespace quad_math
#else
#define PROMYK_HAS_X87_LONG_DOUBLE 1
using quad = __float128;
namespace quad_math {
inline quad sqrt(quad x) { return sqrtq(x); }
inline quad fma(quad a, quad b, quad c) { return fmaq(a, b, c); }
inline quad nextafter(quad x, quad y) { return nextafterq(x, y); }
inline quad nan() { return nanq(""); }
inline quad fabs(quad x) { return fabsq(x); }
inline quad frexp(quad x, int* exponent) { return frexpq(x, exponent); }
inline quad ldexp(quad x, int exponent) { return ldexpq(x, exponent); }
inline bool signbit(quad x) { return signbitq(x) != 0; }
inline bool finite(quad x) { return finiteq(x) != 0; }
inline quad from_text(const char* text, char** end) { return strtoflt128(text, end); }
}  // namespace quad_math
#endif

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
    static quad max() { return quad_math::nextafter(infinity(), 0); }
    static quad lowest() { return -max(); }
    static quad infinity() { return quad(std::numeric_limits<double>::infinity()); }
    static quad quiet_nan() { return quad_math::nan(); }
    // libquadmath's sqrtq is faithful (wasm's sqrtl is correctly rounded,
    // and passes through unchanged), not correctly rounded (about one
    // result in five is the other neighbour): corrected here, so that quad
    // rounds like every other type. The remainder r = x - s^2 of a faithful
    // s is exact in quad (and fmaq computes it exactly); s is the correctly
    // rounded root when x lies between (s - u/2)^2 and (s + u/2)^2 (u the
    // spacing of quads at s, the same both sides unless s is a power of two),
    // that is when -s u + u^2/4 <= r <= s u + u^2/4; ties cannot happen.
    static quad sqrt(quad x) {
        const quad s = quad_math::sqrt(x);
        if (!(s > 0) || !(s < max())) return s;  // 0, NaN, infinity, negative
        const quad up = quad_math::nextafter(s, infinity());
        const quad down = quad_math::nextafter(s, quad(0));
        const quad r = quad_math::fma(-s, s, x);
        // Compare x with the midpoints exactly: (s + up)/2 squared against x
        // is the sign of x - ((s + up)/2)^2 = r - (up - s)(s + (up - s)/4).
        const quad u_up = up - s, u_down = s - down;  // exact: neighbours
        if (r > 0 && r - u_up * s > u_up * u_up / 4) return up;
        if (r < 0 && r + u_down * s < u_down * u_down / 4) return down;
        return s;
    }
    static quad fma(quad a, quad b, quad c) { return quad_math::fma(a, b, c); }
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
#if PROMYK_HAS_X87_LONG_DOUBLE
std::string real_text(long double x);
#endif
std::string real_text(quad x);

// printf's "%.*g" of a quad (libquadmath's "%.*Qg"), by the project's own
// code from the value's exact decimal expansion: `digits` significant digits
// (1 ... 40), rounded half to even, trailing zeros removed, an exponent of
// at least two digits. wasm's printf prints a long double only to double
// precision. The value must be finite.
std::string quad_g_text(quad x, int digits);

// |x| in any real type, quad included (std::fabs does not take one).
template <class Real>
Real magnitude(Real x) {
    return x < 0 ? -x : x;
}

}  // namespace promyk
