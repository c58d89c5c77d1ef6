// When the ⚠ mark appears (trace/digits_alarm.hpp): fewer than half of the
// type's digits survive, or the loss can move the grey level across a
// rounding boundary. The boundaries below are worked by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "trace/digits_alarm.hpp"

using promyk::digits_lost_alarm;
using promyk::full_digits_of;

TEST_CASE("digits alarm: the types' full digits", "[digits-alarm]") {
    CHECK(full_digits_of("float") == Approx(24 * std::log10(2.0)));
    CHECK(full_digits_of("double") == Approx(53 * std::log10(2.0)));
    CHECK(full_digits_of("long-double") == Approx(64 * std::log10(2.0)));
    CHECK(full_digits_of("quad") == Approx(113 * std::log10(2.0)));
    CHECK(full_digits_of("octuple") == 0);
}

TEST_CASE("digits alarm: fewer than half the digits survive", "[digits-alarm]") {
    const double dbl = full_digits_of("double");  // 15.95: half 7.98
    CHECK_FALSE(digits_lost_alarm(3.0, dbl, {}));
    CHECK_FALSE(digits_lost_alarm(7.97, dbl, {}));
    CHECK(digits_lost_alarm(7.99, dbl, {}));
    CHECK(digits_lost_alarm(dbl, dbl, {}));  // every digit: the sign itself is unknown
    const double flt = full_digits_of("float");  // 7.22: half 3.61
    CHECK_FALSE(digits_lost_alarm(3.6, flt, {}));
    CHECK(digits_lost_alarm(3.62, flt, {}));
    CHECK_FALSE(digits_lost_alarm(std::nan(""), dbl, {}));  // no estimate, no mark
}

TEST_CASE("digits alarm: a loss that can change the grey level", "[digits-alarm]") {
    const double dbl = full_digits_of("double");
    // 255·I a hair below the boundary 100.5 between levels 100 and 101.
    const double I = (100.5 - 1e-9) / 255;
    // 5 digits lost: relative error 10^(5 − 15.95) ≈ 1.1e-11, so 255·I may
    // move by 100.5 · 1.1e-11 ≈ 1.1e-9 > 1e-9: across the boundary.
    CHECK(digits_lost_alarm(5, dbl, {I}));
    // 3 digits lost: 1.1e-11 of movement, short of the boundary.
    CHECK_FALSE(digits_lost_alarm(3, dbl, {I}));
    // Far from a boundary (255·I = 100.0) even 7 digits cannot move a level.
    CHECK_FALSE(digits_lost_alarm(7, dbl, {100.0 / 255}));
    // A colour: any channel near its boundary counts.
    CHECK(digits_lost_alarm(5, dbl, {0.2, I, 0.7}));
    // Clamped above 1: 255·I = 300 stays at level 255 whatever the error.
    CHECK_FALSE(digits_lost_alarm(7, dbl, {300.0 / 255}));
    // The branch fixes the result (no intensities): only the half rule.
    CHECK_FALSE(digits_lost_alarm(7, dbl, {}));
}
