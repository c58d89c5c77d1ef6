// render/whole_divisor.hpp: a sample's coordinates divided by w and 2^16 n
// with two fmas instead of a division must give the division's bits. Here
// in the baseline build (the C library's fma, exact like the instruction),
// one lane and two, on every pane size up to 4096, the cells' 2^16 n and
// 2^15 n w (the scaled points: render/sample_lanes.hpp), and
// random divisors up to 2^21, against numerators of the samples' kind and,
// the hard part, numerators whose quotient lies next to a midpoint between
// two doubles (where q0 = A y alone is often wrong).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "render/whole_divisor.hpp"
#include "same_bits.hpp"

using namespace promyk;
using lanes::Double2;

namespace {

using promyk::testing::same_bits;

struct Tally {
    long long cases = 0, wrong = 0, q0_wrong = 0;
};

// A / b by the fmas, in one lane and in the second lane of a pair, against
// the division; q0_wrong counts where the first step alone is not A / b.
void check(double A, double b, Tally& tally) {
    const lanes::WholeDivisor<double, true> one(b);
    const lanes::WholeDivisor<Double2, true> two(b);
    const double q = A / b;
    const Double2 pair = two.divide(Double2{1.0, A});
    const bool right = same_bits(one.divide(A), q) && same_bits(pair[1], q);
    ++tally.cases;
    if (!right && ++tally.wrong <= 5) {
        INFO("A = " << A << " (" << std::hexfloat << A << std::defaultfloat << "), b = " << b);
        CHECK(right);
    }
    tally.q0_wrong += !same_bits(A * one.y, q);
}

// Numerators whose quotient by b is next to the midpoint between q and the
// next double: A = b m rounded, and the doubles around it.
void near_midpoints(double q, double b, Tally& tally) {
    const double next = std::nextafter(q, 2 * q + 1);
    const long double m = (static_cast<long double>(q) + next) / 2;
    double A = static_cast<double>(m * b);
    for (int k = 0; k < 3; ++k) A = std::nextafter(A, 0.0);
    for (int k = 0; k < 7; ++k, A = std::nextafter(A, 2 * A + 1)) check(A, b, tally), check(-A, b, tally);
}

}  // namespace

TEST_CASE("Division by a whole number by two fmas gives the division's bits", "[lanes][whole-divisor]") {
    std::mt19937_64 random(20261203);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<double> divisors;
    for (int b = 1; b <= 4096; ++b) divisors.push_back(b);  // pane sizes
    for (int n = 1; n <= 32; ++n) {
        divisors.push_back(65536 * n);                                             // the cells' 2^16 n
        for (double w = 1; w <= 65536; w *= 2) divisors.push_back(32768 * n * w);  // scaled: 2^15 n w
    }
    std::uniform_int_distribution<int> any_divisor(4097, 1 << 21);
    for (int k = 0; k < 2000; ++k) divisors.push_back(any_divisor(random));
    Tally tally;
    for (const double b : divisors) {
        for (int k = 0; k < 40; ++k) {
            // A sample's x numerator, 2 j + 1 + 2 u in [0, 2 b + 1], and y's, negative.
            const double A = (2 * b + 1) * unit(random);
            check(A, b, tally);
            check(-A, b, tally);
            // The jitter's: whole numbers below 2^31.
            check(std::floor(unit(random) * 2147483648.0), b, tally);
            near_midpoints(unit(random) * 2.5, b, tally);
        }
    }
    check(0.0, 7, tally);
    CHECK(tally.wrong == 0);
    // The hard cases were hard: A y alone, rounded once, misses many of them.
    CHECK(tally.q0_wrong > tally.cases / 100);
    CHECK(tally.cases > 2'000'000);
}

TEST_CASE("Without the fused multiply-add, the whole divisor divides", "[lanes][whole-divisor]") {
    const lanes::WholeDivisor<double, false> by_seven(7);
    CHECK(same_bits(by_seven.divide(1.0), 1.0 / 7));
    CHECK(same_bits(by_seven.divide(-22.0), -22.0 / 7));
}
