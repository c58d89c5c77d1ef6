// The tracer: one pixel's computation, the article's `intensity` function,
// assembled from its named steps. It is the only code that computes a pixel:
// rendering calls it with a NullRecorder, tracing with a RecordingRecorder.
#pragma once


#include "geometry/hit.hpp"
#include "geometry/sphere_article.hpp"
#include "geometry/sphere_formulas.hpp"
#include "math/vec3.hpp"
#include "render/pane.hpp"
#include "scene/scene.hpp"
#include "shading/lambert.hpp"
#include "trace/keys.hpp"

namespace promyk {

// The article's world, read once from a Scene: one sphere, one light.
template <class Real>
struct ArticleWorld {
    Real z_E;
    Vec3<Real> S;
    Real r;
    Vec3<Real> L;
    Real I;
    Real background;
};

// The world's numbers in another real type, each converted once: rounded
// from double (a kernel in float, long double or quad reading the scene),
// exactly to double from float (the silhouette proofs take a float scene's
// own numbers).
template <class To, class From>
ArticleWorld<To> world_as(const ArticleWorld<From>& world) {
    const auto in_to = [](const Vec3<From>& v) { return Vec3<To>{To(v.x), To(v.y), To(v.z)}; };
    return {To(world.z_E), in_to(world.S), To(world.r), in_to(world.L), To(world.I), To(world.background)};
}

// Throws InputError unless the scene is one the article's program handles
// (exactly one sphere and one light, eye outside the sphere). Other scenes
// run the general tracer (render/general_tracer.hpp): render/kernel.hpp
// chooses.
ArticleWorld<double> article_world(const Scene& scene);

template <class Real>
struct PixelResult {
    Real I_P;       // the pixel's intensity
    Branch branch;  // miss, dark, lit or non_finite
};

// The article's intensity(x_E, y_E, z_E), with the sphere's formula F
// (geometry/sphere_formulas.hpp; the article's by default).
template <class F = SphereFormula<Formula::article>, class Real, class Recorder>
PixelResult<Real> trace_ray(const ArticleWorld<Real>& world, const Vec3<Real>& E, Recorder& record) {
    record(Key::E, E);
    Real t;
    if constexpr (F::id == Formula::article) {
        const auto near = intersect_sphere_article(E, world.S, world.r, record);
        if (!near) return {world.background, Branch::miss};
        // The engine's convention: only a hit in front of the eye is drawn. The
        // eye is outside the sphere here, so both roots are behind it too.
        if (*near <= 0 && *near >= RealTraits<Real>::lowest()) {  // -inf decides nothing
            if constexpr (Recorder::records) record(Key::found, "behind");
            return {world.background, Branch::miss};
        }
        t = *near;
    } else {
        // The formula chooses its root as it does for every scene (near, else
        // far, else behind). The far root cannot be in front of an eye outside
        // the sphere unless rounding puts the near one at t <= 0; it is then
        // taken as the near one would be (the normal is the program's).
        const auto root = F::intersect(E, world.S, world.r, record);
        if (!root) return {world.background, Branch::miss};
        t = root->t;
        record(Key::t_hit, t);
    }
    // A t that is not finite (from a delta that was not) needs no test of its
    // own: it makes P, and so |K|^2 and D, non-finite, which shading checks.
    const Vec3<Real> P = hit_point(t, E, record);
    const Vec3<Real> N = sphere_normal(P, world.S, world.r, record);
    const Shade<Real> shade = shade_lambert(P, N, world.r, world.L, world.I, record);
    return {shade.I_P, shade.branch};
}

template <class F = SphereFormula<Formula::article>, class Real, class Recorder>
PixelResult<Real> trace_pixel_ray(const ArticleWorld<Real>& world, int w, int i, int j, Recorder& record) {
    return trace_ray<F>(world, pane_point(i, j, w, world.z_E), record);
}

}  // namespace promyk
