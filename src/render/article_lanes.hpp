// The article's intensity (render/tracer.hpp's trace_ray) for several pixels
// of a row at once, with the sphere's formula as a policy (the article's,
// stable or geometric: geometry/sphere_*.hpp): the same steps in the same
// order, each lane rounding exactly as the one-pixel tracer does, with the
// branches (miss, behind the eye, non-finite, dark) as masks. Rendering
// only: the traced path, which records, is trace_ray; tests check that both
// give every pixel the same bits (tests/article_lanes_test.cpp).
#pragma once

#include <cstdint>
#include <limits>

#include "geometry/formula.hpp"

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
    Real rr;          // r^2
    Real SS_rr;       // |S|^2 - r^2: the program's, and the other formulas' c_0

    ArticleRow(const ArticleWorld<Real>& w, Real y)
        : world(w), y_E(y), yy(y * y), zz(w.z_E * w.z_E), ySy(y * w.S.y), zSz(w.z_E * w.S.z),
          SS(length_squared(w.S)), rr(w.r * w.r), SS_rr(SS - rr) {}
};

// The templates below are compiled once per instruction set, each in its
// namespace (render/lanes.hpp); ArticleRow is not: only the baseline
// builds one, and the wider sets read it.
inline namespace PROMYK_LANES_ISA {

// The article's formula (geometry/sphere_article.hpp and trace_ray's test
// of a root behind the eye). Each formula is a type of this shape: made
// from E's |E|^2 and C = E.S, it computes the discriminant and its misses;
// then t() gives the root, adding the pixels whose root it rejects.
template <class Lane>
struct ArticleRoot {
    using Real = typename LaneTraits<Lane>::Real;
    using Mask = MaskOf<Lane>;
    Lane EE, C, delta;
    Mask miss;  // delta <= 0; -inf and NaN decide nothing and go on

    template <class Row>
    PROMYK_LANES_INLINE ArticleRoot(const Row& row, Lane x_E, Lane EE_, Lane C_) : EE(EE_), C(C_) {
        (void)x_E;
        delta = C * C - EE * row.SS_rr;
        miss = both(delta <= Real(0), delta >= std::numeric_limits<Real>::lowest());
    }
    // Compute the nearer root; a root behind the eye is a miss too.
    PROMYK_LANES_INLINE Lane t(Mask& missed) const {
        const Lane t = (C - lane_sqrt(delta)) / EE;
        missed = either(missed, both(t <= Real(0), t >= std::numeric_limits<Real>::lowest()));
        return t;
    }
};

// Lanes where the computed t_c = c_0 / q is finite, > 0 and below the
// computed q / |E|^2, which is finite too, proven without dividing. With
// u the unit roundoff and every value normal: t_c <= (c_0 / q)(1 + u) and
// q / |E|^2 rounds to at least (q / |E|^2)(1 - u), so c_0 |E|^2 (1 + u) <
// q^2 (1 - u) is enough; the products are computed within (1 + u), and the
// test c_0 |E|^2 < q^2 (1 - 2^-40) (2^-11 in float) leaves more than the
// 5u those roundings need. t_c >= 2 * the least normal keeps both quotients
// normal (q / |E|^2 exceeds c_0 / q); q < |E|^2 2^1018 (2^122 in float),
// a product that is exact or infinite, keeps q / |E|^2 finite. tests/article_lanes_test.cpp
// and the hard cases compare every pixel with the traced path.
template <class Lane, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE MaskOf<Lane> nearer_root_proven(Lane q, Lane t_c, Real c_0, Lane EE) {
    using limits = std::numeric_limits<Real>;
    constexpr Real below_one = Real(1) - limits::epsilon() * Real(4096);  // 1 - 2^-40 in double, 1 - 2^-11 in float
    constexpr Real least = Real(2) * limits::min();
    constexpr Real huge = Real(1) / (limits::min() * Real(16));  // 2^1018 in double, 2^122 in float
    const Lane c0_EE = c_0 * EE, qq = q * q;
    const MaskOf<Lane> ordered = both(c0_EE >= limits::min(), c0_EE < (qq * below_one));
    const MaskOf<Lane> t_c_fine = both(t_c >= least, t_c <= limits::max());
    const MaskOf<Lane> t_q_finite = both(qq <= limits::max(), both(q > Real(0), q < EE * huge));
    return both(ordered, both(t_c_fine, t_q_finite));
}

// Of two roots t_a and t_b, the engine's choice (geometry/sphere.hpp's
// nearest_root_ahead): the nearer if > 0, else the farther if > 0, else a
// miss (behind the eye); a root that is NaN or infinite is taken.
template <class Lane, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE Lane nearest_ahead(Lane t_a, Lane t_b, MaskOf<Lane>& missed) {
    using Mask = MaskOf<Lane>;
    const Mask finite_a = t_a * Real(0) == Real(0), finite_b = t_b * Real(0) == Real(0);
    const Mask finite = both(finite_a, finite_b);
    const Mask a_first = t_a < t_b;
    const Lane near = select(finite, select(a_first, t_a, t_b), select(finite_a, t_b, t_a));
    const Lane far = select(a_first, t_b, t_a);
    const Mask take_near = either(lane_not(finite), lane_not(near <= Real(0)));
    const Mask take_far = both(lane_not(take_near), far > Real(0));
    missed = either(missed, lane_not(either(take_near, take_far)));  // behind the eye
    return select(take_near, near, far);
}

// The stable and geometric formulas' roots q / |E|^2 and c_0 / q, with
// q = C + sign(C) root_term (geometry/sphere_stable.hpp's
// cancellation_free_roots), and the engine's choice between them.
template <class Lane, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE Lane cancellation_free_root(Lane C, Lane root_term, Real c_0, Lane EE, MaskOf<Lane>& missed) {
    const Lane q = select(C >= Real(0), C + root_term, C - root_term);
    const Lane t_c = c_0 / q;
    // Where every lane's c_0 / q is proven the nearer root and ahead of the
    // eye (or the lane missed already), the choice below would take it:
    // q / |E|^2, a second division, is not needed (nearer_root_proven).
    if constexpr (LaneTraits<Lane>::width > 1)
        if (c_0 > Real(0) && all(either(missed, nearer_root_proven(q, t_c, c_0, EE)))) return t_c;
    return nearest_ahead(q / EE, t_c, missed);
}

// The stable formula (geometry/sphere_stable.hpp): the program's delta, the
// roots without cancellation.
template <class Lane>
struct StableRoot {
    using Real = typename LaneTraits<Lane>::Real;
    using Mask = MaskOf<Lane>;
    Lane EE, C, delta;
    Real c_0;
    Mask miss;

    template <class Row>
    PROMYK_LANES_INLINE StableRoot(const Row& row, Lane x_E, Lane EE_, Lane C_)
        : EE(EE_), C(C_), c_0(row.SS_rr) {
        (void)x_E;
        delta = C * C - EE * c_0;
        miss = both(delta <= Real(0), delta >= std::numeric_limits<Real>::lowest());
    }
    PROMYK_LANES_INLINE Lane t(Mask& missed) const {
        return cancellation_free_root(C, lane_sqrt(delta), c_0, EE, missed);
    }
};

// The geometric formula (geometry/sphere_geometric.hpp): delta_g = r^2 -
// |l|^2 from l = t_mid E - S, the ray's point nearest the centre.
template <class Lane>
struct GeometricRoot {
    using Real = typename LaneTraits<Lane>::Real;
    using Mask = MaskOf<Lane>;
    Lane EE, C, delta_g;
    Real c_0;
    Mask miss;

    template <class Row>
    PROMYK_LANES_INLINE GeometricRoot(const Row& row, Lane x_E, Lane EE_, Lane C_)
        : EE(EE_), C(C_), c_0(row.SS_rr) {
        const Vec3<Real>& S = row.world.S;
        const Lane t_mid = C / EE;
        const Lane l_x = t_mid * x_E - S.x, l_y = t_mid * row.y_E - S.y, l_z = t_mid * row.world.z_E - S.z;
        const Lane ll = (l_x * l_x + l_y * l_y) + l_z * l_z;  // |l|^2
        delta_g = row.rr - ll;
        miss = both(delta_g <= Real(0), delta_g >= std::numeric_limits<Real>::lowest());
    }
    PROMYK_LANES_INLINE Lane t(Mask& missed) const {
        return cancellation_free_root(C, lane_sqrt(EE * delta_g), c_0, EE, missed);
    }
};

// Kahan's discriminant (geometry/sphere_fma.hpp): w = |E|^2 c_0, e =
// fma(-|E|^2, c_0, w), delta = fma(C, C, -w) + e; the article's two roots,
// and the engine's choice between them.
template <class Lane>
struct FmaRoot {
    using Real = typename LaneTraits<Lane>::Real;
    using Mask = MaskOf<Lane>;
    Lane EE, C, delta;
    Mask miss;

    template <class Row>
    PROMYK_LANES_INLINE FmaRoot(const Row& row, Lane x_E, Lane EE_, Lane C_) : EE(EE_), C(C_) {
        (void)x_E;
        const Lane c_0 = splat<Lane>(row.SS_rr);
        const Lane w = EE * c_0;
        const Lane e = lane_fma(-EE, c_0, w);
        delta = lane_fma(C, C, -w) + e;
        miss = both(delta <= Real(0), delta >= std::numeric_limits<Real>::lowest());
    }
    PROMYK_LANES_INLINE Lane t(Mask& missed) const {
        const Lane root = lane_sqrt(delta);
        const Lane t_near = (C - root) / EE, C_far = C + root;
        // Where every lane's t_near is finite and > 0 (or the lane missed
        // already) and C + root < |E|^2 2^1018 (a product exact or
        // infinite: the far root is finite), the far root is at least
        // t_near (C + root >= C - root, divided alike) and nearest_ahead
        // would take t_near: the far root's division is not needed.
        if constexpr (LaneTraits<Lane>::width > 1) {
            constexpr Real huge = Real(1) / (std::numeric_limits<Real>::min() * Real(16));
            const Mask near_ahead =
                both(both(t_near > Real(0), t_near <= std::numeric_limits<Real>::max()), C_far < EE * huge);
            if (all(either(missed, near_ahead))) return t_near;
        }
        return nearest_ahead(t_near, C_far / EE, missed);
    }
};

// Calls visit(RootOf<Root>{}) with the root step of `formula`: the one place
// a formula chosen at run time becomes a template argument.
template <template <class> class R>
struct RootOf {
    template <class Lane>
    using Root = R<Lane>;
};
template <class Visit>
PROMYK_LANES_INLINE decltype(auto) with_root(Formula formula, Visit&& visit) {
    switch (formula) {
        case Formula::stable:
            return visit(RootOf<StableRoot>{});
        case Formula::geometric:
            return visit(RootOf<GeometricRoot>{});
        case Formula::fma:
            return visit(RootOf<FmaRoot>{});
        default:
            return visit(RootOf<ArticleRoot>{});
    }
}

template <class Lane>
struct LanePixel {
    Lane I_P;
    MaskOf<Lane> miss, dark, non_finite;  // lit: none of these
    bool background = false;  // every lane missed the sphere at Δ (I_P the background)
};

// The first half of a pixel's steps: where its ray meets the sphere, t, or
// that it misses (pixel.miss; the background's I_P until shaded). Shading
// (article_shade) needs t and E alone, so a row can find the next vector's
// t while it shades this one (render/article_row_lanes.hpp's draw_row).
template <class Lane>
struct LaneHit {
    Lane x_E, t{};  // t: 0 where pixel.background
    LanePixel<Lane> pixel;
};

// Pixels E = (x_E, y_E, z_E), one a lane, of the row, with the formula Root.
// The row is an ArticleRow (y_E one number) or any type with its members,
// where y_E, yy and ySy may be lanes too (render/sample_lanes.hpp: each lane
// a sample, at its own height).
// EarlyOuts: a vector of misses returns at once, and one with no lane lit
// skips the light's square root and division. Where such vectors are common
// (rows, with whole vectors of background or of the dark side) that pays;
// where they are rare (samples, drawn near the silhouette only, two vectors
// in flight) the two branches, mispredicted at the jittered edges, cost more
// than they save (bench accuracy --spp 16: 23.4-24.1 -> 22.4-23.1 x spp 1).
template <template <class> class Root = ArticleRoot, bool EarlyOuts = true, class Lane, class Row,
          class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE LaneHit<Lane> article_hit(const Row& row, Lane x_E) {
    const ArticleWorld<Real>& world = row.world;
    using Mask = MaskOf<Lane>;
    LaneHit<Lane> hit;
    hit.x_E = x_E;
    LanePixel<Lane>& pixel = hit.pixel;
    // Compute the quadratic's coefficients, named as in the program.
    const Lane EE = (x_E * x_E + row.yy) + row.zz;  // |E|^2
    const Lane C = (x_E * world.S.x + row.ySy) + row.zSz;
    const Root<Lane> root(row, x_E, EE, C);
    pixel.miss = root.miss;
    pixel.I_P = splat<Lane>(world.background);
    pixel.dark = pixel.non_finite = Mask{};  // none yet
    if constexpr (EarlyOuts)
        if (all(pixel.miss)) {  // the background: nothing to shade
            pixel.background = true;
            return hit;
        }
    hit.t = root.t(pixel.miss);
    return hit;
}

// The second half: P, N, K, D and the intensity of the pixels `hit` met.
template <bool EarlyOuts = true, class Lane, class Row, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE LanePixel<Lane> article_shade(const Row& row, const LaneHit<Lane>& hit) {
    const ArticleWorld<Real>& world = row.world;
    using Mask = MaskOf<Lane>;
    LanePixel<Lane> pixel = hit.pixel;
    if constexpr (EarlyOuts)
        if (pixel.background) return pixel;
    const Lane t = hit.t, x_E = hit.x_E;

    // Compute P = tE, N = P - S, K = L - P.
    const Lane P_x = t * x_E, P_y = t * row.y_E, P_z = t * world.z_E;
    const Lane N_x = P_x - world.S.x, N_y = P_y - world.S.y, N_z = P_z - world.S.z;
    const Lane K_x = world.L.x - P_x, K_y = world.L.y - P_y, K_z = world.L.z - P_z;
    const Lane KK = (K_x * K_x + K_y * K_y) + K_z * K_z;  // |K|^2
    const Lane D = (N_x * K_x + N_y * K_y) + N_z * K_z;   // N.K

    // Non-finite |K|^2 or D (x * 0 is 0 only for a finite x); then dark.
    const Mask hit_lanes = lane_not(pixel.miss);
    const Mask undecided = both(hit_lanes, lane_not((KK * Real(0) + D * Real(0)) == Real(0)));
    const Mask decided = both(hit_lanes, lane_not(undecided));
    pixel.dark = both(decided, D <= Real(0));
    const Mask lit = both(decided, lane_not(pixel.dark));
    // No lane lit (each a miss, dark or undecided: a fifth of the article's
    // hits are dark): the light's square root and division would only be
    // thrown away by the selects below.
    Lane I_P = splat<Lane>(Real(0));
    if (!EarlyOuts || any(lit)) I_P = world.I * D / (world.r * lane_sqrt(KK));
    // I D overflowing, or r sqrt(|K|^2) underflowing to 0: non-finite too.
    pixel.non_finite = either(undecided, both(lit, lane_not(I_P <= std::numeric_limits<Real>::max())));

    pixel.I_P = select(pixel.miss, pixel.I_P,
                       select(undecided, splat<Lane>(std::numeric_limits<Real>::quiet_NaN()),
                              select(pixel.dark, splat<Lane>(Real(0)), I_P)));
    return pixel;
}

// Both halves, one after the other.
template <template <class> class Root = ArticleRoot, bool EarlyOuts = true, class Lane, class Row>
PROMYK_LANES_INLINE LanePixel<Lane> article_lanes(const Row& row, Lane x_E) {
    return article_shade<EarlyOuts>(row, article_hit<Root, EarlyOuts>(row, x_E));
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
