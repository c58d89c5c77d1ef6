// The tracer for every scene that is not the article's world: several
// objects (the nearest hit with t > 0 wins), planes, the eye inside a sphere,
// several lights, shadows, Phong and colour (docs/conventions.md: the engine's
// conventions). The stages a scene does not ask for are template switches,
// chosen once before the pixel loop (render/stages.hpp), so they cost
// nothing per pixel.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "geometry/plane.hpp"
#include "geometry/segment.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_formulas.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "render/world.hpp"
#include "shading/phong.hpp"
#include "trace/keys.hpp"
#include "util/interrupt.hpp"

namespace promyk {

// The work one pixel did, added up by the renderer (render --stats).
struct WorkCounts {
    long long shadow_rays = 0;
    long long sphere_tests = 0;
    long long plane_tests = 0;
};

// The stages that are switched on or off for the whole render.
template <bool Shadows_, bool Phong_, bool Ambient_, bool Many_>
struct Switches {
    static constexpr bool many = Many_;  // several objects: a loop over them, the nearest hit wins
    static constexpr bool shadows = Shadows_;
    static constexpr bool phong = Phong_;
    static constexpr bool ambient = Ambient_;
};

template <class Intensity>
struct GeneralResult {
    Intensity I_P;
    Branch branch;
    int hit_kind = 0;  // 0: none, 1: sphere, 2: plane
    int hit_index = -1;
};

template <class Real, bool Rgb>
typename World<Real, Rgb>::Intensity zero_intensity() {
    if constexpr (Rgb)
        return {Real(0), Real(0), Real(0)};
    else
        return Real(0);
}

template <class Real, bool Rgb>
typename World<Real, Rgb>::Intensity nan_of() {
    const Real nan = RealTraits<Real>::quiet_nan();
    if constexpr (Rgb)
        return {nan, nan, nan};
    else
        return nan;
}

// True when every channel is at most the largest finite value (false for
// +inf and NaN; intensities are never negative).
template <class Real>
bool below_max(Real x) {
    return x <= RealTraits<Real>::max();
}
template <class Real>
bool below_max(const Vec3<Real>& v) {
    return below_max(v.x) && below_max(v.y) && below_max(v.z);
}

inline std::string object_name(int kind, int index) {
    return std::string(kind == 1 ? "sphere " : "plane ") + std::to_string(index);
}

// F: the sphere's formula for the eye's rays (geometry/sphere_formulas.hpp);
// shadow rays keep sphere_blocks whatever the formula.
template <class Sw, class F = SphereFormula<Formula::article>, class Real, bool Rgb, class Recorder>
GeneralResult<typename World<Real, Rgb>::Intensity> trace_general(const World<Real, Rgb>& world, const Vec3<Real>& E,
                                                                   WorkCounts& work, Recorder& record) {
    using Intensity = typename World<Real, Rgb>::Intensity;
    using Result = GeneralResult<Intensity>;
    record(Key::E, E);

    // The nearest hit with t > 0 over every object, ties to the earlier one.
    Real best_t = RealTraits<Real>::infinity();
    int kind = 0, index = -1;
    bool inside = false;    // the sphere's far root: seen from inside
    Real best_NE = 0;       // a plane's n_hat.E: > 0 seen from its back
    bool undecided = false;  // a test whose deciding value was NaN or infinite
    auto test_sphere = [&](std::size_t k) {
        const auto& sphere = world.spheres[k];
        record.begin_group("sphere", static_cast<int>(k));
        ++work.sphere_tests;
        if (const auto root = F::intersect(E, sphere.S, sphere.r, record)) {
            if (!finite_value(root->t)) {
                undecided = true;
            } else if (root->t < best_t) {
                best_t = root->t, kind = 1, index = static_cast<int>(k), inside = root->inside;
            }
        }
        record.end_group();
    };
    auto test_plane = [&](std::size_t k) {
        const auto& plane = world.planes[k];
        record.begin_group("plane", static_cast<int>(k));
        ++work.plane_tests;
        if (const auto root = intersect_plane(E, plane.n_hat, plane.NQ, record)) {
            if (!finite_value(root->t))
                undecided = true;
            else if (root->t < best_t)
                best_t = root->t, kind = 2, index = static_cast<int>(k), best_NE = root->NE;
        }
        record.end_group();
    };
    if constexpr (Sw::many) {
        for (std::size_t k = 0; k < world.spheres.size(); ++k) test_sphere(k);
        for (std::size_t k = 0; k < world.planes.size(); ++k) test_plane(k);
    } else if (!world.spheres.empty()) {
        test_sphere(0);  // one object: no loop, and its hit is the hit
    } else {
        test_plane(0);
    }
    if (undecided) return Result{nan_of<Real, Rgb>(), Branch::non_finite};
    if (kind == 0) return Result{world.background, Branch::miss};
    if constexpr (Recorder::records) record(Key::nearest, object_name(kind, index));
    record(Key::t_hit, best_t);

    // The hit: P, and the normal N facing the eye, of length r (1 for a plane).
    const Vec3<Real> P = best_t * E;
    record(Key::P, P);
    Vec3<Real> N;
    Real r;
    int material;
    if (kind == 1) {
        const auto& sphere = world.spheres[static_cast<std::size_t>(index)];
        N = P - sphere.S;
        r = sphere.r;
        material = sphere.material;
        if (inside) {
            N = -N;
            if constexpr (Recorder::records) record(Key::flipped, "inside");
        }
    } else {
        const auto& plane = world.planes[static_cast<std::size_t>(index)];
        N = plane.n_hat;
        r = Real(1);
        material = plane.material;
        if (best_NE > 0) {
            N = -N;
            if constexpr (Recorder::records) record(Key::flipped, "back");
        }
    }
    if (kind == 1) {
        record(Key::N, N);
        // N = P - S (or its opposite: the same magnitudes).
        if constexpr (Recorder::estimates)
            record.lost(Key::N, P, world.spheres[static_cast<std::size_t>(index)].S, N);
        if constexpr (Recorder::records) record(Key::N_P, N / r);
    } else {
        record(Key::N_plane, N);  // already of length 1
    }
    const auto& surface = world.materials[static_cast<std::size_t>(material)];
    Vec3<Real> V_hat{};
    if constexpr (Sw::phong) {
        V_hat = -P / square_root(length_squared(P));
        record(Key::V_hat, V_hat);
    }

    Intensity I_P = zero_intensity<Real, Rgb>();
    bool faces_any = false, lit_any = false;
    for (std::size_t l = 0; l < world.lights.size(); ++l) {
        const auto& light = world.lights[l];
        record.begin_group("light", static_cast<int>(l));
        const Vec3<Real> K = light.L - P;
        record(Key::K, K);
        record.lost(Key::K, light.L, P, K);
        const Real KK = length_squared(K);
        record(Key::KK, KK);
        if constexpr (Recorder::records) {
            const Real K_len = square_root(KK);
            record(Key::K_len, K_len);
            if (K_len > 0) record(Key::K_P, K / K_len);
        }
        const Real D = dot(N, K);
        record(Key::D, D);
        record.lost_in_dot(Key::D, N, K, D);
        if constexpr (Recorder::records) {
            const Real K_len = square_root(KK);
            if (K_len > 0) record(Key::cos_alpha, dot(N / r, K / K_len));
        }
        if (!(KK * Real(0) + D * Real(0) == Real(0))) {
            record.end_group();
            return Result{nan_of<Real, Rgb>(), Branch::non_finite, kind, index};
        }
        const bool faces = D > 0;
        bool blocked = false;
        if constexpr (Sw::shadows) {
            // Lights times objects tests: a pixel of thousands of each takes
            // seconds, so a signal is heeded between lights, not only rows.
            if ((l & 15) == 15) throw_if_interrupted();
            if (faces) {
                ++work.shadow_rays;
                // The first blocking object, by kind (1 sphere, 2 plane) and
                // index: a number, so rendering builds no name per shadow ray.
                int blocker_kind = 0, blocker_index = -1;
                // Takes one object's verdict; true when it decides nothing.
                auto takes_undecided = [&](Blocks b, int object_kind, std::size_t k) {
                    record.end_group();
                    if (b == Blocks::yes && !blocked) {
                        blocked = true;
                        blocker_kind = object_kind;
                        blocker_index = static_cast<int>(k);
                    }
                    return b == Blocks::undecided;
                };
                for (std::size_t k = 0; k < world.spheres.size(); ++k) {
                    const auto& sphere = world.spheres[k];
                    record.begin_group("sphere", static_cast<int>(k));
                    ++work.sphere_tests;
                    Blocks b;
                    if (kind == 1 && static_cast<int>(k) == index) {
                        // Its own sphere: the line through P meets it again at
                        // s = 2D/|K|^2 seen from inside, and not ahead seen from
                        // outside. Decided exactly, with no epsilon: no acne.
                        if constexpr (Recorder::records)
                            if (inside) record(Key::s_own, Real(2) * D / KK);
                        b = inside && Real(2) * D < KK ? Blocks::yes : Blocks::no;
                    } else {
                        b = sphere_blocks(P, K, KK, sphere.S, sphere.r, record);
                    }
                    if (takes_undecided(b, 1, k)) {
                        record.end_group();
                        return Result{nan_of<Real, Rgb>(), Branch::non_finite, kind, index};
                    }
                }
                for (std::size_t k = 0; k < world.planes.size(); ++k) {
                    const auto& plane = world.planes[k];
                    record.begin_group("plane", static_cast<int>(k));
                    ++work.plane_tests;
                    // Its own plane: a point of the plane never crosses it again.
                    const Blocks b = kind == 2 && static_cast<int>(k) == index
                                         ? Blocks::no
                                         : plane_blocks(P, K, plane.n_hat, plane.NQ, record);
                    if (takes_undecided(b, 2, k)) {
                        record.end_group();
                        return Result{nan_of<Real, Rgb>(), Branch::non_finite, kind, index};
                    }
                }
                if constexpr (Recorder::records)
                    record(Key::blocker, blocked ? object_name(blocker_kind, blocker_index) : std::string("none"));
            }
        }
        const bool reaches = faces && !blocked;
        faces_any = faces_any || faces;
        lit_any = lit_any || reaches;

        // This light's contribution: c (m (k_a I + k_d diffuse) + specular).
        Real diffuse = Real(0);
        if (reaches) {
            diffuse = light.I * D / (r * square_root(KK));  // the article's I D / (r sqrt(K))
            record(Key::diffuse, diffuse);
        }
        Real lambert = surface.k_d * diffuse;
        if constexpr (Sw::ambient) lambert = surface.k_a * light.I + lambert;
        Intensity term;
        if constexpr (Rgb)
            term = lambert * surface.m;
        else
            term = surface.m * lambert;
        if constexpr (Sw::phong) {
            if (reaches && surface.k_s > 0) {
                const Real specular = phong_specular(N, r, K, KK, V_hat, light.I, surface.k_s, surface.n, record);
                if constexpr (Rgb)
                    term = term + Vec3<Real>{specular, specular, specular};
                else
                    term = term + specular;
            }
        }
        const Intensity contribution = light.c * term;
        record(Key::contribution, contribution);
        I_P = I_P + contribution;
        record.end_group();
    }
    const Branch branch = lit_any ? Branch::lit : faces_any ? Branch::shadowed : Branch::dark;
    if (!below_max(I_P)) return Result{I_P, Branch::non_finite, kind, index};
    return Result{I_P, branch, kind, index};
}

}  // namespace promyk
