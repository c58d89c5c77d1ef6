// The native build's check of the code the wasm build uses instead of
// libquadmath (math/real.hpp): the project's own "%.*Qg" (quad_g_text)
// against libquadmath's, the portable log10 against log10q, and the x87
// rounding of a quad against the x87 itself.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include <quadmath.h>

#include "math/decimal.hpp"
#include "math/portable_log10.hpp"
#include "math/real.hpp"

using namespace promyk;

namespace {

std::string libquadmath_g(quad x, int digits) {
    char text[128];
    quadmath_snprintf(text, sizeof text, "%.*Qg", digits, x);
    return text;
}

// Random quads of every kind: random 113-bit significands over a wide range
// of exponents, short decimals (ties when rounded), doubles and floats.
quad random_quad(std::mt19937_64& rng, int kind) {
    std::uniform_int_distribution<int> exponent(-60, 60);
    switch (kind % 4) {
        case 0: {
            quad m = 0;
            for (int k = 0; k < 4; ++k) m = quad_math::ldexp(m, 32) + quad(static_cast<std::uint32_t>(rng()));
            return quad_math::ldexp(m, exponent(rng) - 128) * (rng() & 1 ? -1 : 1);
        }
        case 1: {  // k / 2^n: exact short decimals, ties when rounded
            const quad k = quad(static_cast<int>(rng() % 2000) + 1);
            return quad_math::ldexp(k, -static_cast<int>(rng() % 12));
        }
        case 2:
            return quad(std::ldexp(static_cast<double>(rng() >> 11), exponent(rng) - 53));
        default:
            return quad(static_cast<float>(std::ldexp(static_cast<double>(rng() >> 40), exponent(rng) - 24)));
    }
}

}  // namespace

TEST_CASE("quad_g_text writes what libquadmath's %.*Qg writes", "[wasm][real]") {
    std::mt19937_64 rng(20261201);
    int checked = 0;
    for (int n = 0; n < 4000; ++n) {
        const quad x = random_quad(rng, n);
        for (int digits = 1; digits <= 36; digits += (n % 3) + 1) {
            INFO(libquadmath_g(x, 40) << " to " << digits << " digits");
            REQUIRE(quad_g_text(x, digits) == libquadmath_g(x, digits));
            ++checked;
        }
    }
    // Edge cases: zeros, the exponent form's boundaries, carries into a new digit.
    for (const quad x : {quad(0), -quad(0), quad(1), quad(9.5), quad(99.5), quad(0.0001), quad(0.00001),
                         quad(123456), quad(1e30), quad(1e-30), quad(0.125), quad(2.5), quad(-0.5),
                         RealTraits<quad>::max(), quad_math::ldexp(quad(1), -16494)})
        for (int digits = 1; digits <= 40; ++digits) REQUIRE(quad_g_text(x, digits) == libquadmath_g(x, digits));
    CHECK(checked > 20000);
}

TEST_CASE("portable_log10 agrees with log10q to a few units of a double", "[wasm][digits]") {
    std::mt19937_64 rng(7);
    for (int n = 0; n < 20000; ++n) {
        quad x = random_quad(rng, n);
        if (x == 0) continue;
        const double exact = static_cast<double>(log10q(fabsq(x)));
        const double got = log10_magnitude(x);
        INFO(libquadmath_g(x, 36));
        REQUIRE(std::fabs(got - exact) <= 4e-16 * std::max(1.0, std::fabs(exact)));
    }
    // Powers of ten come out as their exponents to about one unit of a double.
    for (int k = -30; k <= 30; ++k)
        REQUIRE(std::fabs(log10_magnitude(quad_math::from_text(("1e" + std::to_string(k)).c_str(), nullptr)) - k) <
                1e-14);
    REQUIRE(log10_magnitude(1000.0) == Approx(3.0).epsilon(1e-15));
    REQUIRE(log10_magnitude(0.5f) == Approx(-0.30102999566398119521).epsilon(1e-15));
}

TEST_CASE("x87_rounded rounds a quad as the x87 reads the same text", "[wasm][real]") {
    std::mt19937_64 rng(11);
    for (int n = 0; n < 5000; ++n) {
        const quad x = random_quad(rng, n);
        const std::string text = libquadmath_g(x, 36);
        const long double x87 = std::strtold(text.c_str(), nullptr);
        INFO(text);
        REQUIRE(x87_rounded(x) == quad(x87));
    }
}
