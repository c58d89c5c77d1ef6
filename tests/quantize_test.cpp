// to_byte (src/image/quantize.hpp) against an independent computation of
// the rule of docs/conventions.md, round(clamp(v, 0, 1) * 255), halves rounded up, NaN to 0.
//
// The product clamp(v, 0, 1) * 255 is the double product, as the expression
// evaluates in double; its rounding to an integer is done here with integer
// arithmetic on the product's exact binary value, so no floating-point
// rounding (to even, or of y + 0.5) can hide in the expectation.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "image/quantize.hpp"

namespace {

// round(y) with halves up, for 0 <= y <= 255, by integers: for y >= 1/2 the
// spacing of doubles is at least 2^-53, so y * 2^53 is an integer below 2^61.
int round_half_up(double y) {
    if (y < 0.5) return 0;
    const auto Y = static_cast<std::uint64_t>(std::ldexp(y, 53));  // exact
    REQUIRE(static_cast<double>(Y) == std::ldexp(y, 53));
    return static_cast<int>((Y + (std::uint64_t{1} << 52)) >> 53);
}

int expected_byte(double v) {
    if (std::isnan(v)) return 0;
    const double clamped = v < 0 ? 0 : v > 1 ? 1 : v;
    return round_half_up(clamped * 255);
}

// The double v nearest (k + 1/2) / 255 for which v * 255 is exactly k + 1/2
// in double, searching a few neighbours either way; 0 if there is none.
double exact_half(int k) {
    const double target = k + 0.5;
    const double start = target / 255;
    double up = start, down = start;
    for (int step = 0; step < 16; ++step) {
        if (up * 255 == target) return up;
        if (down * 255 == target) return down;
        up = std::nextafter(up, 2.0);
        down = std::nextafter(down, -1.0);
    }
    return 0;
}

}  // namespace

TEST_CASE("the independent rounding rounds halves up", "[quantize]") {
    CHECK(round_half_up(0.0) == 0);
    CHECK(round_half_up(0.5) == 1);
    CHECK(round_half_up(std::nextafter(0.5, 0.0)) == 0);
    CHECK(round_half_up(2.5) == 3);
    CHECK(round_half_up(3.5) == 4);
    CHECK(round_half_up(254.5) == 255);
    CHECK(round_half_up(255.0) == 255);
}

TEST_CASE("to_byte rounds every half-way grey level up", "[quantize]") {
    int exact_halves = 0;
    for (int k = 0; k <= 254; ++k) {
        INFO("k = " << k);
        const double v = exact_half(k);
        if (v != 0) {
            ++exact_halves;
            REQUIRE(v * 255 == k + 0.5);
            CHECK(expected_byte(v) == k + 1);
            CHECK(static_cast<int>(promyk::to_byte(v)) == k + 1);
        }
        // Just below and just above the half, whether or not a v hits it.
        double below = (k + 0.5) / 255, above = below;
        while (below * 255 >= k + 0.5) below = std::nextafter(below, -1.0);
        while (above * 255 < k + 0.5) above = std::nextafter(above, 2.0);
        CHECK(expected_byte(below) == k);
        CHECK(static_cast<int>(promyk::to_byte(below)) == k);
        CHECK(expected_byte(above) == k + 1);
        CHECK(static_cast<int>(promyk::to_byte(above)) == k + 1);
    }
    // Every half is reached by some v (so both parities of k are tested:
    // rounding half to even differs on the even ones).
    CHECK(exact_halves == 255);
}

TEST_CASE("to_byte at the ends: clamping, NaN, infinities, signed zero", "[quantize]") {
    using promyk::to_byte;
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(static_cast<int>(to_byte(nan)) == 0);
    CHECK(static_cast<int>(to_byte(-nan)) == 0);
    CHECK(static_cast<int>(to_byte(inf)) == 255);
    CHECK(static_cast<int>(to_byte(-inf)) == 0);
    CHECK(static_cast<int>(to_byte(-0.0)) == 0);
    CHECK(static_cast<int>(to_byte(0.0)) == 0);
    CHECK(static_cast<int>(to_byte(std::numeric_limits<double>::denorm_min())) == 0);
    CHECK(static_cast<int>(to_byte(-std::numeric_limits<double>::denorm_min())) == 0);
    CHECK(static_cast<int>(to_byte(-1e300)) == 0);
    CHECK(static_cast<int>(to_byte(1e300)) == 255);
    CHECK(static_cast<int>(to_byte(1.0)) == 255);
    CHECK(static_cast<int>(to_byte(std::nextafter(1.0, 2.0))) == 255);
    CHECK(static_cast<int>(to_byte(3.0)) == 255);  // I = 3 scenes go above 1
    CHECK(static_cast<int>(to_byte(std::nextafter(1.0, 0.0))) == 255);  // 254.99999999999997 rounds up
    CHECK(static_cast<int>(to_byte(0.5 / 255)) == expected_byte(0.5 / 255));
    // The largest v whose product is below 1/2 gives 0.
    double v = 0.5 / 255;
    while (v * 255 >= 0.5) v = std::nextafter(v, 0.0);
    CHECK(static_cast<int>(to_byte(v)) == 0);
    CHECK(static_cast<int>(to_byte(std::nextafter(v, 1.0))) == 1);
}

TEST_CASE("to_byte matches the independent rule on a dense sweep", "[quantize]") {
    int mismatches = 0;
    double first = 0;
    for (int n = 0; n <= 255 * 64; ++n) {
        const double centre = n / (255.0 * 64);
        double v = centre;
        for (int step = 0; step < 3; ++step, v = std::nextafter(v, 2.0)) {
            if (static_cast<int>(promyk::to_byte(v)) != expected_byte(v) && mismatches++ == 0) first = v;
        }
        v = std::nextafter(centre, -1.0);
        if (static_cast<int>(promyk::to_byte(v)) != expected_byte(v) && mismatches++ == 0) first = v;
    }
    INFO("first mismatch at v = " << first);
    CHECK(mismatches == 0);
}
