// The lanes' shortcut in cancellation_free_root (render/article_lanes.hpp):
// c_0 / q returned without computing q / |E|^2 where it is proven the nearer
// root. Near tangency the two roots' computed values are within an ulp or two
// and their order can flip; there, and at the ends of the exponent range, the
// vector (which may take the shortcut) must return what one lane (which
// never does) returns, bit for bit, its misses too.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "render/article_lanes.hpp"

using namespace promyk;

namespace {

struct RootCase {
    double C, root_term, c_0, EE;
};

template <class Real>
bool same_real_bits(Real a, Real b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("the nearer root's shortcut gives one lane's root and misses, tangent rays and extremes included",
          "[lanes][nearer-root]") {
    std::mt19937_64 random(20261203);
    std::uniform_real_distribution<double> exponent(-6, 6), unit(0, 1);
    std::uniform_int_distribution<int> ulps(-6, 6);
    std::vector<RootCase> cases;
    for (int n = 0; n < 200000; ++n) {
        const double EE = std::pow(10.0, exponent(random)), c_0 = std::pow(10.0, exponent(random));
        // C^2 within a few ulps of |E|^2 c_0: Δ tiny, the roots nearly equal.
        double C = std::sqrt(EE * c_0);
        for (int k = ulps(random); k != 0; k += k > 0 ? -1 : 1) C = std::nextafter(C, k > 0 ? INFINITY : 0.0);
        const double delta = C * C - EE * c_0;
        const double root_term = n % 3 == 0 ? std::sqrt(std::fabs(delta)) : n % 3 == 1 ? 0.0 : C * unit(random) * 1e-15;
        cases.push_back({C, root_term, c_0, EE});
    }
    // The ends: a root that overflows or underflows, a tiny |E|^2, a huge q.
    const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::min();
    for (const RootCase c : {RootCase{1e300, 1e300, 1.0, 1e-10}, RootCase{1e200, 0.0, 1.0, 1e-200}, RootCase{1.0, 0.5, tiny, 1.0},
                         RootCase{1.0, 0.0, tiny * 4, 1.0}, RootCase{1e-300, 0.0, 1e-300, 1e-300}, RootCase{big, 0.0, big, 1.0},
                         RootCase{1.0, 0.0, 1.0, tiny}, RootCase{1.0, 0.0, 1.0, std::numeric_limits<double>::denorm_min()},
                         RootCase{-1.0, 0.5, 1.0, 1.0}, RootCase{0.0, 0.0, 1.0, 1.0}, RootCase{1.0, NAN, 1.0, 1.0},
                         RootCase{1.0, INFINITY, 1.0, 1.0}, RootCase{2.0, 1.0, -1.0, 1.0}})
        cases.push_back(c);

    int flipped = 0, mismatches = 0;
    for (const RootCase& c : cases) {
        // One lane: the full choice between the roots (no shortcut).
        bool missed_one = false;
        const double one = lanes::cancellation_free_root(c.C, c.root_term, c.c_0, c.EE, missed_one);
        // Two lanes of the same case, then with the other lane an easy hit:
        // the shortcut is taken only when every lane is proven.
        for (const double other : {c.C, 3.0}) {
            const lanes::Double2 C{c.C, other}, root{c.root_term, c.C == other ? c.root_term : 1.0};
            const lanes::Double2 EE{c.EE, c.C == other ? c.EE : 1.0};
            lanes::Mask2 missed{};
            const lanes::Double2 two = lanes::cancellation_free_root(C, root, c.c_0, EE, missed);
            mismatches += !same_real_bits(two[0], one) || (missed[0] != 0) != missed_one;
        }
        const double q = c.C >= 0 ? c.C + c.root_term : c.C - c.root_term;
        flipped += c.c_0 > 0 && q > 0 && q / c.EE < c.c_0 / q;  // the roots' order turned by rounding
    }
    CHECK(mismatches == 0);
    CHECK(flipped > 100);  // the cases reach the order the shortcut must not assume
}
