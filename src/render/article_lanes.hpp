// The article's intensity (render/tracer.hpp's trace_ray with the article's
// formula) for several pixels of a row at once: the same steps in the same
// order, each lane rounding exactly as the one-pixel tracer does, with the
// branches (miss, behind the eye, non-finite, dark) as masks. Rendering
// only: the traced path, which records, is trace_ray; tests check that both
// give every pixel the same bits (tests/article_lanes_test.cpp).
#pragma once

#include <cstdint>
#include <limits>

#include "render/lanes.hpp"
#include "render/pane.hpp"
#include "render/tracer.hpp"

namespace promyk::lanes {

// What stays the same along a row: the world, and the products with y_E and
// z_E. Only whole products are kept, never a regrouped sum: C must stay
// (x_E x_S + y_E y_S) + z_E z_S, summed in that order, or its bits change.
template <class Real>
struct ArticleRow {
    ArticleWorld<Real> world;
    Real y_E;
    Real yy, zz;      // y_E y_E, z_E z_E: the last two terms of |E|^2
    Real ySy, zSz;    // y_E y_S, z_E z_S: the last two terms of C
    Real SS;          // |S|^2
    Real SS_rr;       // |S|^2 - r^2

    ArticleRow(const ArticleWorld<Real>& w, Real y)
        : world(w), y_E(y), yy(y * y), zz(w.z_E * w.z_E), ySy(y * w.S.y), zSz(w.z_E * w.S.z),
          SS(length_squared(w.S)), SS_rr(SS - w.r * w.r) {}
};

// The templates below are compiled once per instruction set, each in its
// namespace (render/lanes.hpp); ArticleRow is not: only the baseline
// builds one, and the wider sets read it.
inline namespace PROMYK_LANES_ISA {

template <class Lane>
struct LanePixel {
    Lane I_P;
    MaskOf<Lane> miss, dark, non_finite;  // lit: none of these
};

// Pixels E = (x_E, y_E, z_E), one a lane, of the row.
template <class Lane, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE LanePixel<Lane> article_lanes(const ArticleRow<Real>& row, Lane x_E) {
    const ArticleWorld<Real>& world = row.world;
    using Mask = MaskOf<Lane>;
    constexpr Real lowest = std::numeric_limits<Real>::lowest();
    LanePixel<Lane> pixel;
    // Compute the quadratic's coefficients, named as in the program.
    const Lane EE = (x_E * x_E + row.yy) + row.zz;  // |E|^2
    const Lane C = (x_E * world.S.x + row.ySy) + row.zSz;
    const Lane delta = C * C - EE * row.SS_rr;
    // A miss: delta <= 0; -inf and NaN decide nothing and go on.
    pixel.miss = both(delta <= Real(0), delta >= lowest);
    pixel.I_P = splat<Lane>(world.background);
    pixel.dark = pixel.non_finite = Mask{};  // none yet
    if (all(pixel.miss)) return pixel;  // the background: nothing to shade

    // Compute the nearer root; a root behind the eye is a miss too.
    const Lane t = (C - lane_sqrt(delta)) / EE;
    pixel.miss = either(pixel.miss, both(t <= Real(0), t >= lowest));

    // Compute P = tE, N = P - S, K = L - P.
    const Lane P_x = t * x_E, P_y = t * row.y_E, P_z = t * world.z_E;
    const Lane N_x = P_x - world.S.x, N_y = P_y - world.S.y, N_z = P_z - world.S.z;
    const Lane K_x = world.L.x - P_x, K_y = world.L.y - P_y, K_z = world.L.z - P_z;
    const Lane KK = (K_x * K_x + K_y * K_y) + K_z * K_z;  // |K|^2
    const Lane D = (N_x * K_x + N_y * K_y) + N_z * K_z;   // N.K

    // Non-finite |K|^2 or D (x * 0 is 0 only for a finite x); then dark.
    const Mask hit = lane_not(pixel.miss);
    const Mask undecided = both(hit, lane_not((KK * Real(0) + D * Real(0)) == Real(0)));
    const Mask decided = both(hit, lane_not(undecided));
    pixel.dark = both(decided, D <= Real(0));
    const Lane I_P = world.I * D / (world.r * lane_sqrt(KK));
    // I D overflowing, or r sqrt(|K|^2) underflowing to 0: non-finite too.
    const Mask lit = both(decided, lane_not(pixel.dark));
    pixel.non_finite = either(undecided, both(lit, lane_not(I_P <= std::numeric_limits<Real>::max())));

    pixel.I_P = select(pixel.miss, pixel.I_P,
                       select(undecided, splat<Lane>(std::numeric_limits<Real>::quiet_NaN()),
                              select(pixel.dark, splat<Lane>(Real(0)), I_P)));
    return pixel;
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
