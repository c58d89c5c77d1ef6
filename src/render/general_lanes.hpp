// The general tracer's pixel (render/general_tracer.hpp's trace_general)
// for several pixels of a row at once, in double with the article's formula
// for the eye's rays: several spheres and planes (the nearest hit with t > 0,
// ties to the earlier object, the far root when the eye is inside), several
// lights, ambient, shadows, Phong, grey or colour. The same steps in the
// same order as trace_general, each lane rounding as the one-pixel tracer
// does; its branches are masks, and its early returns (non-finite) masks
// that stop a lane. Rendering only: the traced path is trace_general; tests
// check that both give every pixel the same bits (tests/general_lanes_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "render/intensity_lanes.hpp"
#include "render/lanes.hpp"
#include "render/world.hpp"
#include "util/interrupt.hpp"

namespace promyk::lanes {

// The stages that change the pixel's steps (render/stages.hpp), as types.
template <bool Shadows_, bool Phong_, bool Ambient_, bool Many_, bool One_ = false, bool Plain_ = false>
struct LaneSwitches {
    static constexpr bool shadows = Shadows_;
    static constexpr bool phong = Phong_;
    static constexpr bool ambient = Ambient_;
    static constexpr bool many = Many_;  // several objects: each tested, the nearest hit wins
    // One sphere and one light (render/general_row_one_sphere.hpp), and of
    // those, plain: k_d, m and c exactly 1 (the article's matte white), so
    // the products by them are left out, and I's sign bit clear and r > 0,
    // so trace_general's 0 + the light's term is left out too
    // (plain_surface_and_light). Not stages, the scene's shape and
    // numbers, chosen once a row.
    static constexpr bool one = One_;
    static constexpr bool plain = Plain_;
};

// What stays the same along a row: the world, flattened, and the products
// with y_E and z_E (whole products only: a dot product's sum keeps its
// order, (x x' + y y') + z z'). Filled by the baseline's translation unit
// only (render/general_row.cpp); the wider sets read it.
template <bool Rgb>
struct GeneralRow {
    using Intensity = typename World<double, Rgb>::Intensity;
    struct Surface {
        double k_a, k_d, k_s;
        int n;  // Phong's exponent
        Intensity m;
    };
    struct Ball {
        Vec3<double> S;
        double r;
        double rr;          // r^2, for the shadow rays' c_s
        double SS_rr;       // |S|^2 - r^2, the program's
        double ySy, zSz;    // y_E y_S, z_E z_S: C's last two terms
        Surface surface;
    };
    struct Flat {
        Vec3<double> n_hat;
        double NQ;
        double yn, zn;      // n_y y_E, n_z z_E: n_hat.E's last two terms
        Surface surface;
    };
    using Lamp = typename World<double, Rgb>::Lamp;
    double y_E = 0, z_E = 0;
    double yy = 0, zz = 0;  // y_E y_E, z_E z_E: |E|^2's last two terms
    Intensity background{};
    // The objects and lights as plain arrays: the kernels read them without
    // calling a function (which, not inlined, one instruction set's copy
    // could serve another's).
    const Ball* spheres = nullptr;
    int sphere_count = 0;
    const Flat* planes = nullptr;
    int plane_count = 0;
    const Lamp* lights = nullptr;
    int light_count = 0;

    GeneralRow() = default;
    // Row y_E = y of the world: its arrays refilled, their memory kept (a
    // thread draws row after row into one GeneralRow without allocating).
    void set(const World<double, Rgb>& world, double y) {
        y_E = y, z_E = world.z_E, yy = y * y, zz = world.z_E * world.z_E;
        background = world.background;
        auto surface = [&](int material) {
            const auto& s = world.materials[static_cast<std::size_t>(material)];
            return Surface{s.k_a, s.k_d, s.k_s, s.n, s.m};
        };
        balls_.clear(), flats_.clear();
        for (const auto& b : world.spheres)
            balls_.push_back({b.S, b.r, b.r * b.r, length_squared(b.S) - b.r * b.r, y * b.S.y, z_E * b.S.z,
                              surface(b.material)});
        for (const auto& f : world.planes)
            flats_.push_back({f.n_hat, f.NQ, f.n_hat.y * y, f.n_hat.z * z_E, surface(f.material)});
        lamps_.assign(world.lights.begin(), world.lights.end());
        spheres = balls_.data(), sphere_count = static_cast<int>(balls_.size());
        planes = flats_.data(), plane_count = static_cast<int>(flats_.size());
        lights = lamps_.data(), light_count = static_cast<int>(lamps_.size());
    }
    GeneralRow(const GeneralRow&) = delete;
    GeneralRow& operator=(const GeneralRow&) = delete;

private:
    std::vector<Ball> balls_;
    std::vector<Flat> flats_;
    std::vector<Lamp> lamps_;
};

inline namespace PROMYK_LANES_ISA {

template <class Lane, bool Rgb>
struct GeneralLanePixel {
    using Mask = MaskOf<Lane>;
    LaneIntensity<Lane, Rgb> I_P;
    Mask miss, non_finite, lit, shadowed;  // dark: none of these
};

// The work a vector of pixels did beyond its primary tests (which are the
// same for every pixel): lanes counted where `kept`, a mask being -1 where
// true, so subtracting it adds one.
template <class Lane>
struct LaneWork {
    MaskOf<Lane> shadow_rays{}, sphere_tests{}, plane_tests{};
};

// The nearest hit so far, lane by lane: trace_general's best_t, kind and
// index (as one number: sphere k is k, plane k is the sphere count + k), and
// inside / the plane's back (flip: N turned towards the eye).
template <class Lane>
struct NearestLanes {
    using Mask = MaskOf<Lane>;
    Lane t = splat<Lane>(std::numeric_limits<double>::infinity());
    Lane id = splat<Lane>(-1.0);
    Mask flip{};
    Mask undecided{};  // a test whose deciding value was NaN or infinite

    // The only object's root: taken where found and finite.
    PROMYK_LANES_INLINE void take_only(Mask found, Lane t_k, Mask flip_k) {
        const Mask finite = finite_lanes(t_k);
        undecided = both(found, lane_not(finite));
        const Mask taken = both(found, finite);
        t = select(taken, t_k, t);
        id = select(taken, splat<Lane>(0.0), id);
        flip = flip_k;
    }
    PROMYK_LANES_INLINE void take(Mask found, Lane t_k, double id_k, Mask flip_k) {
        undecided = either(undecided, both(found, lane_not(finite_lanes(t_k))));
        const Mask nearer = both(both(found, finite_lanes(t_k)), t_k < t);  // ties: the earlier object stays
        t = select(nearer, t_k, t);
        id = select(nearer, splat<Lane>(id_k), id);
        flip = pick_mask(nearer, flip_k, flip);
    }
};

// geometry/sphere.hpp's intersect_sphere with the article's formula
// (geometry/sphere_article.hpp), then trace_general's test of its root.
// Only: the scene's only object (its root, if finite, is the nearest).
// ySy: y_E y_S, the row's (a double) or each sample's (lanes).
template <bool Rgb, bool Only, class Lane, class Y>
PROMYK_LANES_INLINE void test_sphere(const typename GeneralRow<Rgb>::Ball& ball, Lane x_E, Y ySy, Lane EE, double id,
                                     NearestLanes<Lane>& nearest) {
    using Mask = MaskOf<Lane>;
    const Lane C = (x_E * ball.S.x + ySy) + ball.zSz;  // E.S
    const Lane delta = C * C - EE * ball.SS_rr;
    const Mask miss = both(delta <= 0.0, delta >= std::numeric_limits<double>::lowest());
    if (all(miss)) return;  // (not !any(!miss): GCC makes that integer code lane by lane)
    const Mask hit = lane_not(miss);
    // The nearer root; a NaN or infinite one passes on (non-finite).
    const Lane t = (C - lane_sqrt(delta)) / EE;
    const Mask near = either(lane_not(t <= 0.0), lane_not(finite_lanes(t)));
    Lane root = t;
    Mask found = both(hit, near), inside{};
    const Mask behind = both(hit, lane_not(near));
    if (any(behind)) {
        // The far root: the eye inside the sphere.
        const Lane t_far = (C + lane_sqrt(delta)) / EE;
        inside = both(behind, t_far > 0.0);
        root = select(inside, t_far, t);
        found = either(found, inside);
    }
    if constexpr (Only)
        nearest.take_only(found, root, inside);
    else
        nearest.take(found, root, id, inside);
}

// geometry/plane.hpp's intersect_plane, then trace_general's test of its root.
// yn: n_y y_E, the row's or each sample's.
template <bool Rgb, bool Only, class Lane, class Y>
PROMYK_LANES_INLINE void test_plane(const typename GeneralRow<Rgb>::Flat& flat, Lane x_E, Y yn, double id,
                                    NearestLanes<Lane>& nearest) {
    using Mask = MaskOf<Lane>;
    const Lane NE = (flat.n_hat.x * x_E + yn) + flat.zn;  // n_hat.E
    const Mask crosses = lane_not(NE == 0.0);                  // parallel: a miss
    const Lane t = flat.NQ / NE;
    // n_hat.Q or n_hat.E beyond the range: a NaN root (nothing decided).
    const Mask decides = (flat.NQ * 0.0 + NE * 0.0) == 0.0;
    const Mask ahead = both(decides, both(t > 0.0, finite_lanes(t)));
    const Lane root = select(decides, t, splat<Lane>(std::numeric_limits<double>::quiet_NaN()));
    const Mask found = both(crosses, either(lane_not(decides), ahead));
    if constexpr (Only)
        nearest.take_only(found, root, NE > 0.0);
    else
        nearest.take(found, root, id, NE > 0.0);
}

// geometry/segment.hpp's sphere_blocks: blocked, and undecided.
template <class Lane>
PROMYK_LANES_INLINE void sphere_blocks_lanes(const Vec3<Lane>& P, const Vec3<Lane>& K, Lane KK, const Vec3<double>& S,
                                             double rr, MaskOf<Lane>& yes, MaskOf<Lane>& undecided) {
    const Lane SP_x = S.x - P.x, SP_y = S.y - P.y, SP_z = S.z - P.z;
    const Lane b_s = (K.x * SP_x + K.y * SP_y) + K.z * SP_z;
    const Lane c_s = ((SP_x * SP_x + SP_y * SP_y) + SP_z * SP_z) - rr;
    const Lane delta_s = b_s * b_s - KK * c_s;
    undecided = lane_not(finite_lanes(delta_s));
    const auto crosses = both(lane_not(undecided), lane_not(delta_s <= 0.0));
    yes = crosses;
    if (!any(crosses)) return;
    const Lane q = lane_sqrt(delta_s);
    const Lane s_1 = (b_s - q) / KK;
    const Lane s_2 = (b_s + q) / KK;
    yes = both(crosses, either(both(s_1 > 0.0, s_1 < 1.0), both(s_2 > 0.0, s_2 < 1.0)));
}

// geometry/segment.hpp's plane_blocks: blocked, and undecided.
template <class Lane>
PROMYK_LANES_INLINE void plane_blocks_lanes(const Vec3<Lane>& P, const Vec3<Lane>& K, const Vec3<double>& n_hat,
                                            double NQ, MaskOf<Lane>& yes, MaskOf<Lane>& undecided) {
    const Lane NK = (n_hat.x * K.x + n_hat.y * K.y) + n_hat.z * K.z;
    const Lane s = (NQ - ((n_hat.x * P.x + n_hat.y * P.y) + n_hat.z * P.z)) / NK;
    const auto crosses = lane_not(NK == 0.0);  // parallel: never blocks
    undecided = both(crosses, lane_not(finite_lanes(s)));
    yes = both(both(crosses, lane_not(undecided)), both(s > 0.0, s < 1.0));
}

// Phong's stage (shading/phong.hpp), lanes at a time. V_hat = -P / |P|,
// once a pixel.
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> eye_direction_lanes(const Vec3<Lane>& P) {
    const Lane length = lane_sqrt((P.x * P.x + P.y * P.y) + P.z * P.z);
    return {-P.x / length, -P.y / length, -P.z / length};
}
// x^n by math/power.hpp's squarings, n the same in every lane.
template <class Lane>
PROMYK_LANES_INLINE Lane power_lanes(Lane x, int n) {
    Lane y = splat<Lane>(1.0);
    for (; n > 0; n >>= 1) {
        if (n & 1) y = y * x;
        x = x * x;
    }
    return y;
}
// n in every lane, as integers as wide as the lanes' masks.
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> exponent_lanes(int n) {
    return MaskOf<Lane>{} + n;
}
// The same with each lane's own n (the hit object's, 1 to 10000, or 0): a
// lane whose n is used up multiplies no more, so its y is power's. No
// comparison of the 64-bit n: SSE2 has none, and GCC compared each lane in
// a general register (the baseline's general kernels held 1000 such
// sequences). A lane multiplies where n is odd, its mask -(n & 1); the loop
// goes on while a 32-bit half of n is not 0.
// (A class's typedef: inside the function, GCC 12 deduced a template
// argument of such a vector as int.)
template <class Mask>
struct HalvesOf {
    typedef std::int32_t type __attribute__((vector_size(sizeof(Mask))));
};
template <class Lane>
PROMYK_LANES_INLINE Lane power_lanes(Lane x, MaskOf<Lane> n) {
    using Mask = MaskOf<Lane>;
    using Halves = typename HalvesOf<Mask>::type;
    Lane y = splat<Lane>(1.0);
    for (; !all(reinterpret_cast<Halves>(n) == 0); n >>= 1) {
        y = select(Mask{} - (n & 1), y * x, y);
        x = x * x;
    }
    return y;
}
// phong_specular's k_s (R_hat.V_hat)^n times I, where RV > 0, else 0: N of
// length r, K = L - P, KK = |K|^2; N: int or lanes.
template <class Lane, class Exponent>
PROMYK_LANES_INLINE Lane specular_lanes(const Vec3<Lane>& N, Lane r, const Vec3<Lane>& K, Lane KK,
                                        const Vec3<Lane>& V_hat, Lane I, Lane k_s, Exponent n) {
    const Vec3<Lane> N_P{N.x / r, N.y / r, N.z / r};
    const Lane K_len = lane_sqrt(KK);
    const Vec3<Lane> K_P{K.x / K_len, K.y / K_len, K.z / K_len};
    const Lane cos_alpha = (N_P.x * K_P.x + N_P.y * K_P.y) + N_P.z * K_P.z;
    const Lane twice = 2.0 * cos_alpha;
    const Vec3<Lane> R_hat{twice * N_P.x - K_P.x, twice * N_P.y - K_P.y, twice * N_P.z - K_P.z};
    const Lane RV = (R_hat.x * V_hat.x + R_hat.y * V_hat.y) + R_hat.z * V_hat.z;
    return select(RV > 0.0, I * (k_s * power_lanes(RV, n)), splat<Lane>(0.0));
}
// term + specular where `where` (every channel), else term as it was (+0
// would turn a -0 into 0).
template <class Lane>
PROMYK_LANES_INLINE Lane plus_specular(MaskOf<Lane> where, Lane term, Lane specular) {
    return select(where, term + specular, term);
}
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> plus_specular(MaskOf<Lane> where, const Vec3<Lane>& term, Lane specular) {
    return {select(where, term.x + specular, term.x), select(where, term.y + specular, term.y),
            select(where, term.z + specular, term.z)};
}

// The eye's heights y_E: the row's, every lane's the same, its products
// with y_E computed once a row (GeneralRow); or each lane's own (a sample's
// point, render/general_sample_lanes.hpp), the same products in lanes.
template <bool Rgb>
struct RowHeights {
    const GeneralRow<Rgb>& row;
    PROMYK_LANES_INLINE double y_E() const { return row.y_E; }
    PROMYK_LANES_INLINE double yy() const { return row.yy; }
    PROMYK_LANES_INLINE double ySy(int k) const { return row.spheres[k].ySy; }
    PROMYK_LANES_INLINE double yn(int k) const { return row.planes[k].yn; }
};
template <bool Rgb, class Lane>
struct LaneHeights {
    const GeneralRow<Rgb>& row;
    Lane y, y_y;
    PROMYK_LANES_INLINE LaneHeights(const GeneralRow<Rgb>& r, Lane y_E) : row(r), y(y_E), y_y(y_E * y_E) {}
    PROMYK_LANES_INLINE Lane y_E() const { return y; }
    PROMYK_LANES_INLINE Lane yy() const { return y_y; }
    PROMYK_LANES_INLINE Lane ySy(int k) const { return y * row.spheres[k].S.y; }   // as GeneralRow's y S_y
    PROMYK_LANES_INLINE Lane yn(int k) const { return row.planes[k].n_hat.y * y; }  // and n_y y
};

// Pixels E = (x_E, y_E, z_E), one a lane, y_E the heights'; `kept`: the
// lanes whose work counts.
template <class Sw, bool Rgb, class Lane, class Heights>
PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> general_lanes(const GeneralRow<Rgb>& row, const Heights& y, Lane x_E,
                                                             MaskOf<Lane> kept, LaneWork<Lane>& work) {
    using Mask = MaskOf<Lane>;
    using Intensity = LaneIntensity<Lane, Rgb>;
    GeneralLanePixel<Lane, Rgb> pixel;
    pixel.I_P = splat_of<Lane>(row.background);
    pixel.non_finite = pixel.lit = pixel.shadowed = Mask{};

    // The nearest hit with t > 0 over every object, ties to the earlier one.
    const Lane EE = (x_E * x_E + y.yy()) + row.zz;  // |E|^2
    NearestLanes<Lane> nearest;
    const double sphere_count = row.sphere_count;
    if constexpr (Sw::many) {
        for (int k = 0; k < row.sphere_count; ++k)
            test_sphere<Rgb, false>(row.spheres[k], x_E, y.ySy(k), EE, k, nearest);
        for (int k = 0; k < row.plane_count; ++k)
            test_plane<Rgb, false>(row.planes[k], x_E, y.yn(k), sphere_count + k, nearest);
    } else if (row.sphere_count > 0) {
        test_sphere<Rgb, true>(row.spheres[0], x_E, y.ySy(0), EE, 0.0, nearest);
    } else {
        test_plane<Rgb, true>(row.planes[0], x_E, y.yn(0), 0.0, nearest);
    }
    pixel.non_finite = nearest.undecided;
    pixel.miss = both(lane_not(nearest.undecided), nearest.id < 0.0);
    Mask alive = lane_not(either(pixel.miss, pixel.non_finite));  // shaded on
    if (!any(alive)) {
        pixel.I_P = pick(pixel.non_finite, every_channel<Lane, Rgb>(std::numeric_limits<double>::quiet_NaN()), pixel.I_P);
        return pixel;
    }

    // The hit: P, and the normal N facing the eye, of length r (1 for a plane).
    const Lane t = nearest.t;
    const Vec3<Lane> P{t * x_E, t * y.y_E(), t * row.z_E};
    Mask on_sphere;
    Vec3<Lane> N;
    Lane r;
    Lane k_a, k_d, k_s;
    MaskOf<Lane> n{};  // Phong's exponent, each lane's
    Intensity m;
    if constexpr (Sw::many) {
        // The hit object's own numbers, chosen lane by lane.
        on_sphere = nearest.id < sphere_count;
        Vec3<Lane> S{}, n_hat{};
        r = splat<Lane>(1.0);
        k_a = k_d = k_s = splat<Lane>(0.0);
        m = splat_of<Lane>(row.background);
        for (int k = 0; k < row.sphere_count; ++k) {
            const auto& ball = row.spheres[k];
            const Mask is = nearest.id == double(k);
            S = pick(is, splat_of<Lane>(ball.S), S);
            r = select(is, splat<Lane>(ball.r), r);
            k_a = select(is, splat<Lane>(ball.surface.k_a), k_a);
            k_d = select(is, splat<Lane>(ball.surface.k_d), k_d);
            if constexpr (Sw::phong) {
                k_s = select(is, splat<Lane>(ball.surface.k_s), k_s);
                n = pick_mask(is, exponent_lanes<Lane>(ball.surface.n), n);
            }
            m = pick(is, splat_of<Lane>(ball.surface.m), m);
        }
        for (int k = 0; k < row.plane_count; ++k) {
            const auto& flat = row.planes[k];
            const Mask is = nearest.id == sphere_count + k;
            n_hat = pick(is, splat_of<Lane>(flat.n_hat), n_hat);
            k_a = select(is, splat<Lane>(flat.surface.k_a), k_a);
            k_d = select(is, splat<Lane>(flat.surface.k_d), k_d);
            if constexpr (Sw::phong) {
                k_s = select(is, splat<Lane>(flat.surface.k_s), k_s);
                n = pick_mask(is, exponent_lanes<Lane>(flat.surface.n), n);
            }
            m = pick(is, splat_of<Lane>(flat.surface.m), m);
        }
        N = pick(on_sphere, Vec3<Lane>{P.x - S.x, P.y - S.y, P.z - S.z}, n_hat);
    } else if (row.sphere_count > 0) {
        const auto& ball = row.spheres[0];
        on_sphere = lane_not(Mask{});
        N = {P.x - ball.S.x, P.y - ball.S.y, P.z - ball.S.z};
        r = splat<Lane>(ball.r);
        k_a = splat<Lane>(ball.surface.k_a), k_d = splat<Lane>(ball.surface.k_d);
        k_s = splat<Lane>(ball.surface.k_s), n = exponent_lanes<Lane>(ball.surface.n);
        m = splat_of<Lane>(ball.surface.m);
    } else {
        const auto& flat = row.planes[0];
        on_sphere = Mask{};
        N = splat_of<Lane>(flat.n_hat);
        r = splat<Lane>(1.0);
        k_a = splat<Lane>(flat.surface.k_a), k_d = splat<Lane>(flat.surface.k_d);
        k_s = splat<Lane>(flat.surface.k_s), n = exponent_lanes<Lane>(flat.surface.n);
        m = splat_of<Lane>(flat.surface.m);
    }
    N = pick(nearest.flip, Vec3<Lane>{-N.x, -N.y, -N.z}, N);  // seen from inside, or from the plane's back
    (void)k_a, (void)k_s, (void)n;
    Vec3<Lane> V_hat{};
    if constexpr (Sw::phong) V_hat = eye_direction_lanes(P);

    Intensity I_P = every_channel<Lane, Rgb>(0.0);
    Mask faces_any{}, lit_any{};
    for (int l = 0; l < row.light_count; ++l) {
        const auto& light = row.lights[l];
        const Vec3<Lane> K{light.L.x - P.x, light.L.y - P.y, light.L.z - P.z};
        const Lane KK = (K.x * K.x + K.y * K.y) + K.z * K.z;  // |K|^2
        const Lane D = (N.x * K.x + N.y * K.y) + N.z * K.z;   // N.K
        // Non-finite |K|^2 or D: the pixel stops here.
        const Mask undecided = both(alive, lane_not((KK * 0.0 + D * 0.0) == 0.0));
        pixel.non_finite = either(pixel.non_finite, undecided);
        alive = both(alive, lane_not(undecided));
        const Mask faces = both(alive, D > 0.0);
        Mask blocked{};
        if constexpr (Sw::shadows) {
            // Lights times objects tests: a pixel of thousands of each takes
            // seconds, so a signal is heeded between lights, not only rows.
            if ((l & 15) == 15) throw_if_interrupted();
            // A shadow ray from each pixel that faces the light; every object
            // is tested, in order, until one is undecided (the pixel stops).
            Mask ray = faces;
            work.shadow_rays -= both(ray, kept);
            auto takes = [&](Mask yes, Mask undecided_k) __attribute__((always_inline)) {
                blocked = either(blocked, both(ray, yes));
                const Mask stops = both(ray, undecided_k);
                pixel.non_finite = either(pixel.non_finite, stops);
                alive = both(alive, lane_not(stops));
                ray = both(ray, lane_not(stops));
            };
            for (int k = 0; k < row.sphere_count; ++k) {
                work.sphere_tests -= both(ray, kept);
                if (!any(ray)) continue;
                Mask yes{}, undecided_k{};
                sphere_blocks_lanes(P, K, KK, row.spheres[k].S, row.spheres[k].rr, yes, undecided_k);
                // Its own sphere: blocks only seen from inside, at s = 2D/|K|^2 < 1.
                const Mask own = both(on_sphere, nearest.id == double(k));
                yes = pick_mask(own, both(nearest.flip, 2.0 * D < KK), yes);
                takes(yes, both(lane_not(own), undecided_k));
            }
            for (int k = 0; k < row.plane_count; ++k) {
                work.plane_tests -= both(ray, kept);
                if (!any(ray)) continue;
                Mask yes{}, undecided_k{};
                plane_blocks_lanes(P, K, row.planes[k].n_hat, row.planes[k].NQ, yes, undecided_k);
                // Its own plane: a point of the plane never crosses it again.
                const Mask own = both(lane_not(on_sphere), nearest.id == sphere_count + k);
                takes(both(lane_not(own), yes), both(lane_not(own), undecided_k));
            }
        }
        const Mask reaches = both(faces, lane_not(blocked));
        faces_any = either(faces_any, faces);
        lit_any = either(lit_any, reaches);

        // This light's contribution: c (m (k_a I + k_d diffuse)).
        Lane diffuse = splat<Lane>(0.0);
        if (any(reaches)) diffuse = select(reaches, light.I * D / (r * lane_sqrt(KK)), diffuse);
        Lane lambert = k_d * diffuse;
        if constexpr (Sw::ambient) lambert = k_a * light.I + lambert;
        Intensity term;
        if constexpr (Rgb)
            term = times(lambert, m);
        else
            term = times(m, lambert);
        if constexpr (Sw::phong) {
            const Mask shiny = both(reaches, k_s > 0.0);
            if (any(shiny))
                term = plus_specular(shiny, term, specular_lanes(N, r, K, KK, V_hat, splat<Lane>(light.I), k_s, n));
        }
        const Intensity contribution = times(splat_of<Lane>(light.c), term);
        I_P = plus(I_P, contribution);
    }
    // An intensity beyond the largest double: non-finite, its value kept.
    const Mask overflow = both(alive, lane_not(below_max_lanes(I_P)));
    pixel.non_finite = either(pixel.non_finite, overflow);
    const Mask shaded = both(alive, lane_not(overflow));
    pixel.lit = both(shaded, lit_any);
    pixel.shadowed = both(shaded, both(lane_not(lit_any), faces_any));
    const Mask stopped = both(lane_not(alive), pixel.non_finite);  // NaN
    pixel.I_P = pick(alive, I_P, pick(stopped, every_channel<Lane, Rgb>(std::numeric_limits<double>::quiet_NaN()), pixel.I_P));
    return pixel;
}

// A row's pixels: the heights the row's.
template <class Sw, bool Rgb, class Lane>
PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> general_lanes(const GeneralRow<Rgb>& row, Lane x_E, MaskOf<Lane> kept,
                                                             LaneWork<Lane>& work) {
    return general_lanes<Sw>(row, RowHeights<Rgb>{row}, x_E, kept, work);
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
