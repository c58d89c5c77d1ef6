// A plane's n̂ (geometry/unit_normal.hpp): every finite non-zero normal, its
// components anywhere in the double range (subnormals included), gives a unit
// vector in n's direction in every Real type; an ordinary normal keeps the
// bits of the plain v / √(v·v).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "geometry/unit_normal.hpp"
#include "math/real.hpp"

using namespace promyk;

namespace {

// A random component: zero sometimes, else ±10^k with k uniform in [-320, 300].
double component(std::mt19937_64& random, double low_exponent, double high_exponent) {
    if (std::uniform_int_distribution<int>(0, 5)(random) == 0) return 0.0;
    const double k = std::uniform_real_distribution<double>(low_exponent, high_exponent)(random);
    const double value = std::pow(10.0, k);
    return std::uniform_int_distribution<int>(0, 1)(random) == 0 ? value : -value;
}

Vec3d random_normal(std::mt19937_64& random, double low_exponent, double high_exponent) {
    for (;;) {
        const Vec3d n{component(random, low_exponent, high_exponent), component(random, low_exponent, high_exponent),
                      component(random, low_exponent, high_exponent)};
        if (!(n == Vec3d{0, 0, 0})) return n;
    }
}

// The reference n/|n| in a type of wider range and at least Real's precision
// (long double, or quad for quad): the squares of 1e-320 and 1e300 fit there.
template <class Real>
using Wide = std::conditional_t<std::is_same_v<Real, quad>, quad, long double>;

template <class Real>
void check_unit_and_direction(const Vec3d& n) {
    using W = Wide<Real>;
    const Vec3<Real> n_hat = unit_normal<Real>(n);
    const W length = square_root(W(n.x) * W(n.x) + W(n.y) * W(n.y) + W(n.z) * W(n.z));
    // Real's machine epsilon (numeric_limits knows no __float128: 2^-112).
    const W eps = std::is_same_v<Real, quad> ? W(std::ldexp(1.0, -112)) : W(std::numeric_limits<Real>::epsilon());
    const W rx = W(n.x) / length, ry = W(n.y) / length, rz = W(n.z) / length;
    const W hx = W(n_hat.x), hy = W(n_hat.y), hz = W(n_hat.z);
    const W unit = hx * hx + hy * hy + hz * hz;
    INFO("n = [" << n.x << ", " << n.y << ", " << n.z << "], n_hat = [" << double(hx) << ", " << double(hy) << ", "
                 << double(hz) << "], |n_hat|² - 1 = " << double(unit - 1));
    CHECK(std::fabs(double((unit - 1) / eps)) <= 4);
    // Each component within a few units of Real's last place of 1.
    CHECK(std::fabs(double((hx - rx) / eps)) <= 3);
    CHECK(std::fabs(double((hy - ry) / eps)) <= 3);
    CHECK(std::fabs(double((hz - rz) / eps)) <= 3);
}

template <class Real>
void check_same_bits_as_plain(const Vec3d& n) {
    const Vec3<Real> v{Real(n.x), Real(n.y), Real(n.z)};
    const Vec3<Real> plain = v / square_root(length_squared(v));
    const Vec3<Real> n_hat = unit_normal<Real>(n);
    INFO("n = [" << n.x << ", " << n.y << ", " << n.z << "]");
    CHECK((n_hat.x == plain.x && n_hat.y == plain.y && n_hat.z == plain.z));
}

}  // namespace

TEST_CASE("unit normal: every finite non-zero n, subnormal to huge, gives a unit n_hat along n", "[plane]") {
    std::mt19937_64 random(19);
    for (int k = 0; k < 4000; ++k) {
        const Vec3d n = random_normal(random, -320, 300);
        check_unit_and_direction<float>(n);
        check_unit_and_direction<double>(n);
        check_unit_and_direction<long double>(n);
        check_unit_and_direction<quad>(n);
    }
    // The example and the extremes.
    for (const Vec3d& n : {Vec3d{0, 3e-162, 0}, Vec3d{0, 4.9e-324, 0}, Vec3d{4.9e-324, -4.9e-324, 4.9e-324},
                           Vec3d{1.7e308, -1.7e308, 1.7e308}, Vec3d{1e-300, 1e300, 0}, Vec3d{3e-162, 3e-162, 1e-170}}) {
        check_unit_and_direction<float>(n);
        check_unit_and_direction<double>(n);
        check_unit_and_direction<long double>(n);
        check_unit_and_direction<quad>(n);
    }
    const Vec3<double> tiny = unit_normal<double>({0, 3e-162, 0});
    CHECK(tiny.y == 1.0);
}

TEST_CASE("unit normal: an ordinary normal keeps the bits of v / sqrt(v.v)", "[plane]") {
    std::mt19937_64 random(1919);
    for (int k = 0; k < 4000; ++k) {
        const Vec3d n = random_normal(random, -4, 4);
        check_same_bits_as_plain<float>(n);
        check_same_bits_as_plain<double>(n);
        check_same_bits_as_plain<long double>(n);
        check_same_bits_as_plain<quad>(n);
    }
    for (const Vec3d& n : {Vec3d{0, 1, 0}, Vec3d{0, 0, -1}, Vec3d{1, 1, 0}, Vec3d{0, 3, 4}, Vec3d{-0.3, 2, 0.7}}) {
        check_same_bits_as_plain<float>(n);
        check_same_bits_as_plain<double>(n);
        check_same_bits_as_plain<long double>(n);
        check_same_bits_as_plain<quad>(n);
    }
}
