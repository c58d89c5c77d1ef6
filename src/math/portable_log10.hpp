// log10 |x| computed the same way, to the same bits, in every build: from
// x's binary exponent and its significand rounded to double, with double
// +, −, ×, ÷ only (correctly rounded everywhere, and never fused: the build
// has -ffp-contract=off). The C libraries' log10 may differ in the last
// place (glibc against emscripten's musl), and emscripten's log10l of a
// binary128 quad is only about double-precise, while libquadmath's log10q is
// a quad's: digits lost (trace/digits_lost.hpp) and the digits that agree
// (trace --compare) would then differ between the CLI and the web page.
// Accurate to a few units in the last place of a double.
#pragma once

#include <cmath>

#include "math/real.hpp"

namespace promyk {

// log10(m × 2^e) for m in [1/2, 1].
inline double portable_log10(double m, int e) {
    if (m < 0.70710678118654752440) {  // m into [1/√2, √2): |z| below 0.1716
        m *= 2;
        --e;
    }
    // ln m = 2 atanh z = 2 (z + z³/3 + z⁵/5 + ...), z = (m − 1)/(m + 1);
    // z² ≤ 0.0295, so the terms after z²³/23 are below 1e-17 of the sum.
    const double z = (m - 1) / (m + 1);
    const double z2 = z * z;
    double series = 1.0 / 23;
    for (int k = 21; k >= 1; k -= 2) series = series * z2 + 1.0 / k;
    const double ln_m = 2 * z * series;
    constexpr double log10_e = 0.43429448190325182765;
    constexpr double log10_2 = 0.30102999566398119521;
    return ln_m * log10_e + e * log10_2;
}

// log10 |x| for a finite x other than 0, in any real type (frexp is exact
// in every type).
inline double log10_magnitude(double x) {
    int e = 0;
    const double m = std::frexp(std::fabs(x), &e);
    return portable_log10(m, e);
}
inline double log10_magnitude(float x) { return log10_magnitude(static_cast<double>(x)); }
#if PROMYK_HAS_X87_LONG_DOUBLE
inline double log10_magnitude(long double x) {
    int e = 0;
    const long double m = std::frexp(std::fabs(x), &e);
    return portable_log10(static_cast<double>(m), e);
}
#endif
inline double log10_magnitude(quad x) {
    int e = 0;
    const quad m = quad_math::frexp(quad_math::fabs(x), &e);
    return portable_log10(static_cast<double>(m), e);
}

}  // namespace promyk
