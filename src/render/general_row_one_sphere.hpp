// The general tracer's pixel (render/general_lanes.hpp's general_lanes) for
// a scene of one sphere and one light, the article's and its like: the same
// steps in the same order, each lane rounding as trace_general does, with
// what such a scene never needs left out (the nearest of several objects,
// the hit object's numbers chosen lane by lane, the loop over lights, the
// sphere's own shadow test against itself), and two steps whose outcome
// the others already decide (whether the root is finite; 0 + the light's
// term in a plain scene). Its numbers are in every lane once a row
// (OneSphereRow), as the article's kernel keeps ArticleRow's.
// Tests check every pixel's bits against the traced path
// (tests/general_lanes_test.cpp).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "render/general_lanes.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// The row's numbers, each in every lane: built once a row, read from
// registers (the row itself could be overwritten by the bytes stored, as
// far as the compiler knows, and would be read again for every vector).
template <class Lane, bool Rgb>
struct OneSphereRow {
    using Intensity = LaneIntensity<Lane, Rgb>;
    Lane y_E, z_E, yy, zz;
    Lane S_x, S_y, S_z, r, SS_rr, ySy, zSz;  // the sphere, and C's last two terms
    Lane k_d, k_a_I;                         // k_a I: a whole product, as trace_general's
    Lane k_s;                                // Phong's
    int n;
    Intensity m;
    Lane L_x, L_y, L_z, I;  // the light
    Intensity c;
    Intensity background;

    explicit OneSphereRow(const GeneralRow<Rgb>& row)
        : y_E(splat<Lane>(row.y_E)), z_E(splat<Lane>(row.z_E)), yy(splat<Lane>(row.yy)),
          zz(splat<Lane>(row.zz)), S_x(splat<Lane>(row.spheres[0].S.x)),
          S_y(splat<Lane>(row.spheres[0].S.y)), S_z(splat<Lane>(row.spheres[0].S.z)),
          r(splat<Lane>(row.spheres[0].r)), SS_rr(splat<Lane>(row.spheres[0].SS_rr)),
          ySy(splat<Lane>(row.spheres[0].ySy)), zSz(splat<Lane>(row.spheres[0].zSz)),
          k_d(splat<Lane>(row.spheres[0].surface.k_d)),
          k_a_I(splat<Lane>(row.spheres[0].surface.k_a * row.lights[0].I)),
          k_s(splat<Lane>(row.spheres[0].surface.k_s)), n(row.spheres[0].surface.n),
          m(splat_of<Lane>(row.spheres[0].surface.m)), L_x(splat<Lane>(row.lights[0].L.x)),
          L_y(splat<Lane>(row.lights[0].L.y)), L_z(splat<Lane>(row.lights[0].L.z)),
          I(splat<Lane>(row.lights[0].I)), c(splat_of<Lane>(row.lights[0].c)),
          background(splat_of<Lane>(row.background)) {}
    // The row's numbers with each lane's own height y (a sample's point):
    // y_E and its products, computed as GeneralRow computes the row's.
    PROMYK_LANES_INLINE OneSphereRow(const OneSphereRow& row, Lane y) : OneSphereRow(row) {
        y_E = y, yy = y * y, ySy = y * S_y;
    }
};

// True where the row is drawn by one_sphere_lanes.
template <bool Rgb>
PROMYK_LANES_INLINE bool one_sphere_and_light(const GeneralRow<Rgb>& row) {
    return row.sphere_count == 1 && row.plane_count == 0 && row.light_count == 1;
}

// True where the one sphere's k_d and m and the one light's c are exactly
// 1: x 1 is x, bit for bit, for every double (a NaN keeps its payload; no
// arithmetic makes a signalling one), so one_sphere_lanes leaves out those
// products (LaneSwitches::plain). And where the light's I has its sign bit
// clear and r > 0 (a valid scene's, but -0 passes I >= 0): the diffuse
// term I D / (r sqrt(|K|^2)), taken where D > 0, is then never -0, nor
// is any sum of it, so trace_general's 0 + x is x and is left out too.
template <class Intensity>
PROMYK_LANES_INLINE bool is_one(const Intensity& x) {
    if constexpr (std::is_same_v<Intensity, double>)
        return x == 1.0;
    else
        return x.x == 1.0 && x.y == 1.0 && x.z == 1.0;
}
template <bool Rgb>
PROMYK_LANES_INLINE bool plain_surface_and_light(const GeneralRow<Rgb>& row) {
    const auto& surface = row.spheres[0].surface;
    return surface.k_d == 1.0 && is_one(surface.m) && is_one(row.lights[0].c) && !std::signbit(row.lights[0].I) &&
           row.spheres[0].r > 0.0;
}

// The first half of one_sphere_lanes: where each ray meets the sphere (t),
// from outside or inside, or that it misses; shading needs this and E
// alone, so a row finds the next vector's hit while it shades this one
// (render/general_row_lanes.hpp), as the article's rows do.
template <class Lane, bool Rgb>
struct OneSphereHit {
    Lane x_E, t{};  // t: 0 where background
    MaskOf<Lane> inside{}, alive{};
    GeneralLanePixel<Lane, Rgb> pixel;
    bool background = false;  // every lane missed the sphere at delta
};

// Pixels E = (x_E, y_E, z_E), one a lane: their hits.
template <bool Rgb, class Lane>
PROMYK_LANES_INLINE OneSphereHit<Lane, Rgb> one_sphere_hit(const OneSphereRow<Lane, Rgb>& row, Lane x_E) {
    using Mask = MaskOf<Lane>;
    OneSphereHit<Lane, Rgb> h;
    h.x_E = x_E;
    GeneralLanePixel<Lane, Rgb>& pixel = h.pixel;
    pixel.I_P = row.background;
    pixel.non_finite = pixel.lit = pixel.shadowed = Mask{};

    // The sphere (geometry/sphere_article.hpp): |E|^2, C = E.S, delta.
    const Lane EE = (x_E * x_E + row.yy) + row.zz;
    const Lane C = (x_E * row.S_x + row.ySy) + row.zSz;
    const Lane delta = C * C - EE * row.SS_rr;
    pixel.miss = both(delta <= 0.0, delta >= std::numeric_limits<double>::lowest());
    if (all(pixel.miss)) {  // the background: nothing to shade
        h.background = true;
        return h;
    }
    const Mask hit = lane_not(pixel.miss);
    // The nearer root; a NaN or infinite one passes on (non-finite).
    Lane t = (C - lane_sqrt(delta)) / EE;
    const Mask behind = both(hit, both(t <= 0.0, t >= std::numeric_limits<double>::lowest()));
    Mask found = both(hit, lane_not(behind)), inside{};
    if (any(behind)) {  // the far root: the eye inside the sphere
        const Lane t_far = (C + lane_sqrt(delta)) / EE;
        inside = both(behind, t_far > 0.0);
        t = select(inside, t_far, t);
        found = either(found, inside);
    }
    // A root that is not finite decides nothing: the pixel is non-finite.
    // Not tested here: such a t makes a coordinate of P, then of K, NaN or
    // infinite, so |K|^2 is, and shading stops the lane as undecided, with
    // the same NaN and branch. This and plain's 0 + x left out below: a
    // baseline sample 10 % faster (docs/bench.md).
    pixel.miss = lane_not(found);
    h.alive = found;  // shaded on (no early return: the lanes that are
    // not are as rare as in the article's kernel, and the selects below
    // leave their intensities as they are)
    h.t = t, h.inside = inside;
    return h;
}

// The second half: the pixels' intensities; `kept`: the lanes whose work counts.
template <class Sw, bool Rgb, class Lane>
PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> one_sphere_shade(const OneSphereRow<Lane, Rgb>& row,
                                                                const OneSphereHit<Lane, Rgb>& h, MaskOf<Lane> kept,
                                                                LaneWork<Lane>& work) {
    using Mask = MaskOf<Lane>;
    using Intensity = LaneIntensity<Lane, Rgb>;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    GeneralLanePixel<Lane, Rgb> pixel = h.pixel;
    if (h.background) return pixel;
    const Lane t = h.t, x_E = h.x_E;
    const Mask inside = h.inside;
    Mask alive = h.alive;

    // P = tE; N = P - S, turned towards the eye seen from inside; K = L - P.
    const Lane P_x = t * x_E, P_y = t * row.y_E, P_z = t * row.z_E;
    Lane N_x = P_x - row.S_x, N_y = P_y - row.S_y, N_z = P_z - row.S_z;
    if (any(inside)) {  // rare: the eye inside the sphere
        N_x = negated_where(inside, N_x), N_y = negated_where(inside, N_y), N_z = negated_where(inside, N_z);
    }
    const Lane K_x = row.L_x - P_x, K_y = row.L_y - P_y, K_z = row.L_z - P_z;
    const Lane KK = (K_x * K_x + K_y * K_y) + K_z * K_z;  // |K|^2
    const Lane D = (N_x * K_x + N_y * K_y) + N_z * K_z;   // N.K
    // Non-finite |K|^2 or D: the pixel stops here.
    const Mask undecided = both(alive, lane_not((KK * 0.0 + D * 0.0) == 0.0));
    alive = both(alive, lane_not(undecided));
    const Mask faces = both(alive, D > 0.0);
    Mask reaches = faces;
    if constexpr (Sw::shadows) {
        // The shadow ray meets only the sphere itself: again at s = 2D/|K|^2
        // seen from inside, never ahead seen from outside.
        work.shadow_rays -= both(faces, kept);
        work.sphere_tests -= both(faces, kept);
        reaches = both(faces, lane_not(both(inside, 2.0 * D < KK)));
    }

    // The light's contribution: c (m (k_a I + k_d diffuse)).
    Lane diffuse = splat<Lane>(0.0);
    if (any(reaches)) diffuse = select(reaches, row.I * D / (row.r * lane_sqrt(KK)), diffuse);
    Lane lambert = diffuse;  // plain: k_d diffuse is diffuse
    if constexpr (!Sw::plain) lambert = row.k_d * diffuse;
    if constexpr (Sw::ambient) lambert = row.k_a_I + lambert;
    Intensity term;  // c (m lambert + specular); plain: lambert (+ specular) in every channel
    if constexpr (Sw::plain && Rgb)
        term = {lambert, lambert, lambert};
    else if constexpr (Sw::plain)
        term = lambert;
    else if constexpr (Rgb)
        term = times(lambert, row.m);
    else
        term = times(row.m, lambert);
    if constexpr (Sw::phong) {
        // Phong's highlight (shading/phong.hpp), where the light reaches.
        if (row.k_s[0] > 0.0 && any(reaches)) {
            const Vec3<Lane> P{P_x, P_y, P_z}, N{N_x, N_y, N_z}, K{K_x, K_y, K_z};
            term = plus_specular(reaches, term,
                                 specular_lanes(N, row.r, K, KK, eye_direction_lanes(P), row.I, row.k_s, row.n));
        }
    }
    if constexpr (!Sw::plain) term = times(row.c, term);
    // 0 + the light's: -0 becomes 0. Plain: diffuse is +0, positive (or
    // infinite) or NaN (I's sign bit clear, r > 0, D > 0:
    // plain_surface_and_light); a sum is -0 only if both its terms are, so
    // no sum of diffuse with the ambient or specular term is, and 0 + x is x.
    Intensity I_P = term;
    if constexpr (!Sw::plain) I_P = plus(every_channel<Lane, Rgb>(0.0), term);

    // An intensity beyond the largest double: non-finite, its value kept.
    const Mask overflow = both(alive, lane_not(below_max_lanes(I_P)));
    pixel.non_finite = either(undecided, overflow);
    const Mask shaded = both(alive, lane_not(overflow));
    pixel.lit = both(shaded, reaches);
    if constexpr (Sw::shadows) pixel.shadowed = both(shaded, both(faces, lane_not(reaches)));
    pixel.I_P = pick(alive, I_P, pick(undecided, every_channel<Lane, Rgb>(nan), pixel.I_P));  // NaN where undecided
    return pixel;
}

// Both halves, one after the other.
template <class Sw, bool Rgb, class Lane>
PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> one_sphere_lanes(const OneSphereRow<Lane, Rgb>& row, Lane x_E,
                                                                MaskOf<Lane> kept, LaneWork<Lane>& work) {
    return one_sphere_shade<Sw>(row, one_sphere_hit(row, x_E), kept, work);
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
