// Every comparison that decides something in the engine, on a scene that sits
// exactly on its boundary, in exact binary numbers (issue 19, "Hostile runs
// as tests"): so that turning a < into <= (or back) anywhere fails a test.
// docs/boundaries.md lists each comparison, its test and what its mutation did.
//
// Each case runs twice: through the stage code instantiated here with this
// file's own recorder type (BoundaryRecorder), and through the product
// (trace_pixel), which must agree. The first is what a mutation run changes:
// a copy of src/ with one comparison turned is put first on this file's
// include path, so only this file's instantiations see it (docs/boundaries.md
// says how).
#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "geometry/plane.hpp"
#include "geometry/segment.hpp"
#include "geometry/sphere_formulas.hpp"
#include "math/real.hpp"
#include "render/general_tracer.hpp"
#include "render/pane.hpp"
#include "render/samples.hpp"
#include "render/sampling.hpp"
#include "render/stages.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"
#include "render/world.hpp"
#include "scene/scene.hpp"
#include "shading/phong.hpp"
#include "trace/recorder.hpp"

using namespace promyk;

namespace {

// A recorder type of this file only: every stage template instantiated with
// it is compiled here, from whatever headers this file was compiled with.
struct BoundaryRecorder : RecordingRecorder {};

// The stage switches the cases use (render/general_tracer.hpp).
using Plain = Switches<false, false, false, false>;
using Many = Switches<false, false, false, true>;
using Shadows = Switches<true, false, false, false>;
using ShadowsMany = Switches<true, false, false, true>;
using PhongMany = Switches<false, true, false, true>;

using Article = SphereFormula<Formula::article>;

template <class Fn>
void for_each_real(Fn&& fn) {
    fn(float{});
    fn(double{});
    fn(static_cast<long double>(0));
    fn(quad{});
}

template <class Fn>
void for_each_formula(Fn&& fn) {
    fn(SphereFormula<Formula::article>{});
    fn(SphereFormula<Formula::stable>{});
    fn(SphereFormula<Formula::fma>{});
    fn(SphereFormula<Formula::geometric>{});
}

// One pixel's outcome: branch, the object hit ("" for none), the steps.
struct Outcome {
    Branch branch = Branch::miss;
    std::string hit;
    std::vector<Step> steps;
    std::vector<TraceGroup> groups;
    double result = 0;  // the first channel, rounded to double

    // The first step with `key` in the group chain `path` ("", "light 0", "light 0/sphere 1").
    const Step* find(Key key, const std::string& path = "") const {
        for (const Step& step : steps) {
            if (step.key != key) continue;
            std::string chain;
            for (int g = step.group; g >= 0; g = groups[static_cast<std::size_t>(g)].parent)
                chain = group_title(groups[static_cast<std::size_t>(g)]) + (chain.empty() ? "" : "/" + chain);
            if (chain == path) return &step;
        }
        return nullptr;
    }
    bool has(Key key, const std::string& path = "") const { return find(key, path) != nullptr; }
    double number(Key key, const std::string& path = "") const {
        const Step* step = find(key, path);
        REQUIRE(step != nullptr);
        return std::get<double>(step->value);
    }
    std::string word(Key key, const std::string& path = "") const {
        const Step* step = find(key, path);
        REQUIRE(step != nullptr);
        return std::get<std::string>(step->value);
    }
    // No step is NaN or infinite (a trace that decided something).
    bool all_finite() const {
        for (const Step& step : steps) {
            if (const double* x = std::get_if<double>(&step.value))
                if (!std::isfinite(*x)) return false;
            if (const Vec3d* v = std::get_if<Vec3d>(&step.value))
                if (!std::isfinite(v->x) || !std::isfinite(v->y) || !std::isfinite(v->z)) return false;
        }
        return true;
    }
};

template <class Real>
const char* real_name() {
    return real_type_name(RealTraits<Real>::type).data();
}

// The product's trace of the same pixel agrees with the stage code's.
template <class Real, class F>
void product_agrees(const Scene& scene, int w, int i, int j, const Outcome& o) {
    const PixelTrace trace = trace_pixel(scene, w, i, j, RealTraits<Real>::type, F::id);
    INFO("the product's trace (trace_pixel) of the same pixel");
    CHECK(trace.branch == o.branch);
    CHECK(trace.hit_object == o.hit);
    if (o.branch != Branch::non_finite) CHECK(trace.result == o.result);
}

// Pixel (i, j) of a w x w pane through the general tracer (a grey scene that
// is not the article's world) with switches Sw, in Real, formula F.
template <class Sw, class F, class Real>
Outcome general(const Scene& scene, int w, int i, int j) {
    const Stages stages = plan_stages(scene);
    REQUIRE_FALSE(stages.article);
    REQUIRE_FALSE(stages.colour);
    REQUIRE(stages.shadows == Sw::shadows);
    REQUIRE(stages.phong == Sw::phong);
    REQUIRE(stages.ambient == Sw::ambient);
    REQUIRE(stages.objects == Sw::many);
    const World<Real, false> world = compile_world<Real, false>(scene);
    BoundaryRecorder record;
    WorkCounts work;
    const auto result = trace_general<Sw, F>(world, pane_point(i, j, w, world.z_E), work, record);
    Outcome o;
    o.branch = result.branch;
    if (result.hit_kind != 0) o.hit = object_name(result.hit_kind, result.hit_index);
    o.steps = record.take_steps();
    o.groups = record.take_groups();
    o.result = static_cast<double>(result.I_P);
    product_agrees<Real, F>(scene, w, i, j, o);
    return o;
}

// The same pixel through the article's kernel (the scene must be the
// article's world: one sphere, the eye outside, one white light, defaults).
template <class F, class Real>
Outcome article(const Scene& scene, int w, int i, int j) {
    REQUIRE(plan_stages(scene).article);
    const ArticleWorld<double> a = article_world(scene);
    const ArticleWorld<Real> world{Real(a.z_E), to_real<Real>(a.S), Real(a.r), to_real<Real>(a.L), Real(a.I),
                                   Real(a.background)};
    BoundaryRecorder record;
    const PixelResult<Real> result = trace_ray<F>(world, pane_point(i, j, w, world.z_E), record);
    Outcome o;
    o.branch = result.branch;
    o.steps = record.take_steps();
    o.result = static_cast<double>(result.I_P);
    const PixelTrace trace = trace_pixel(scene, w, i, j, RealTraits<Real>::type, F::id);
    CHECK(trace.branch == o.branch);
    if (o.branch != Branch::non_finite) CHECK(trace.result == o.result);
    return o;
}

Scene scene_at(double z_E) {
    Scene scene;
    scene.name = "boundary";
    scene.z_E = z_E;
    return scene;
}

// The eye's ray E = (0, 0, 1): the one pixel of a 1 x 1 pane at z_E = 1.
constexpr int axis_w = 1;

// The floor y = -1 seen by pixel (1, 0) of a 2 x 2 pane at z_E = 1:
// E = (-1/2, -1/2, 1), n.E = -1/2, n.Q = -1, t = 2, P = (-1, -1, 2); a light
// 4 straight above P: K = (0, 4, 0), |K|^2 = 16, D = 4.
Scene floor_scene() {
    Scene scene = scene_at(1);
    scene.planes = {Plane{{0, -1, 0}, {0, 1, 0}}};
    scene.lights = {Light{{-1, 3, 2}, 1}};
    scene.shadows = true;
    return scene;
}

}  // namespace

// Delta = 0: the article counts a tangent ray a miss (delta <= 0), and so do
// the other formulas (discriminant_misses). E = (0, 0, 1), S = (3, 4, 10),
// r = 5: C = 10, |E|^2 = 1, c_0 = 125 - 25 = 100, delta = 100 - 100 = 0;
// geometric: t_mid = 10, l = (-3, -4, 0), |l|^2 = 25 = r^2; fma: w = 100,
// e = 0. Every number exact in every type.
TEST_CASE("boundary: a ray tangent to a sphere (delta exactly 0) misses, in every type and formula",
          "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{3, 4, 10}, 5}};
    scene.lights = {Light{{0, 10, 0}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        for_each_formula([&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Key delta_key = F::id == Formula::geometric ? Key::delta_g
                                  : F::id == Formula::fma     ? Key::delta_fma
                                                              : Key::delta;
            const Outcome a = article<F, Real>(scene, axis_w, 0, 0);
            CHECK(a.branch == Branch::miss);
            CHECK(a.number(delta_key) == 0);
            // The article's sqrt(Delta) is shown only for delta > 0.
            CHECK_FALSE(a.has(Key::sqrt_Delta));
            Scene with_shadows = scene;  // the general tracer
            with_shadows.shadows = true;
            const Outcome g = general<Shadows, F, Real>(with_shadows, axis_w, 0, 0);
            CHECK(g.branch == Branch::miss);
            CHECK(g.number(delta_key, "sphere 0") == 0);
            CHECK(g.word(Key::found, "sphere 0") == "miss");
        });
    });
}

// delta = -max, the lowest finite value: still a miss (a delta of -inf or NaN
// decides nothing, but -max is a number). E = (0, 0, 1), S = (s, y, 0) with
// s*s + y*y rounding to max (s = the largest value below sqrt(max), whose
// square is max less one ulp; y*y = 1.125 ulp in double, 0.5625 ulp in
// float), r = 1: C = 0, c_0 = max - 1 = max, delta = -max; geometric
// l = (-s, -y, 0), |l|^2 = max, delta_g = 1 - max = -max; fma: w = max, e = 0.
// Only float and double: a scene's doubles cannot reach long double's max.
TEST_CASE("boundary: a delta of exactly -max (the lowest finite) is a miss, not non-finite", "[boundary]") {
    auto run = [](auto real, double s, double y) {
        using Real = decltype(real);
        Scene scene = scene_at(1);
        scene.spheres = {Sphere{{s, y, 0}, 1}};
        scene.lights = {Light{{0, 10, 0}, 1}};
        REQUIRE(Real(s) * Real(s) + Real(y) * Real(y) == RealTraits<Real>::max());
        for_each_formula([&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Key delta_key = F::id == Formula::geometric ? Key::delta_g
                                  : F::id == Formula::fma     ? Key::delta_fma
                                                              : Key::delta;
            const Outcome a = article<F, Real>(scene, axis_w, 0, 0);
            CHECK(a.branch == Branch::miss);
            CHECK(a.number(delta_key) == static_cast<double>(RealTraits<Real>::lowest()));
            Scene with_shadows = scene;
            with_shadows.shadows = true;
            const Outcome g = general<Shadows, F, Real>(with_shadows, axis_w, 0, 0);
            CHECK(g.branch == Branch::miss);
            CHECK(g.word(Key::found, "sphere 0") == "miss");
        });
    };
    run(double{}, 0x1.fffffffffffffp+511, 0x1.8p+485);
    run(float{}, 0x1.fffffep+63, 0x1.8p+51);
}

// t = 0: the eye on the sphere's surface, looking in. E = (0, 0, 1),
// S = (0, 0, 1), r = 1: c_0 = 0, the roots 0 and 2. A root at the eye is not
// in front of it (t > 0 is a hit): the far root 2 is, seen from inside.
// The light at the centre: P = (0, 0, 2), N = -(P - S) = (0, 0, -1),
// K = (0, 0, -1), D = 1, I_P = 1. (Taking t = 0 would give P = O, D = -1: dark.)
TEST_CASE("boundary: a root exactly at the eye (t = 0) is not a hit, the far root is", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, 1}, 1}};
    scene.lights = {Light{{0, 0, 1}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        for_each_formula([&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Outcome o = general<Plain, F, Real>(scene, axis_w, 0, 0);
            CHECK(o.word(Key::found, "sphere 0") == "far");
            CHECK(o.number(Key::t_hit) == 2);
            CHECK(o.word(Key::flipped) == "inside");
            CHECK(o.branch == Branch::lit);
            CHECK(o.result == 1);
        });
    });
}

// The far root exactly at the eye: E = (0, 0, 1), S = (0, 0, -1), r = 1,
// roots -2 and 0 (-0 for stable and geometric: c_0 / q = 0 / -2): both at
// t <= 0, the sphere is behind the eye.
TEST_CASE("boundary: a far root exactly at the eye (t = 0) is behind: a miss", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, -1}, 1}};
    scene.lights = {Light{{0, 5, 0}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        for_each_formula([&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Outcome o = general<Plain, F, Real>(scene, axis_w, 0, 0);
            CHECK(o.word(Key::found, "sphere 0") == "behind");
            CHECK(o.branch == Branch::miss);
        });
    });
}

// The article's kernel's own test of the near root (render/tracer.hpp): in
// float, r = 1 - 2^-40 rounds to 1, so the eye that is outside in double
// (where the engine decides which kernel runs) is on the surface in float:
// t = (1 - 1) / 1 = 0, behind the eye, a miss. (t = 0 would give P = O,
// N = (0, 0, -1), K = (0, 0, -5), D = 5: lit.) In the wider types the eye
// stays outside and t > 0: this boundary exists only in float.
TEST_CASE("boundary: the article's kernel takes a near root of exactly 0 as behind the eye (float)",
          "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, 1}, 1 - 0x1p-40}};
    scene.lights = {Light{{0, 0, -5}, 1}};
    const Outcome o = article<Article, float>(scene, axis_w, 0, 0);
    CHECK(o.number(Key::t) == 0);
    CHECK(o.word(Key::found) == "behind");
    CHECK(o.branch == Branch::miss);
}

// C = E.S = 0: the stable and geometric formulas take q = C + sign(C) sqrt(delta)
// with sign(0) = +1. E = (0, 0, 1), S = (3, 0, 0), r = 5: C = 0, c_0 = -16,
// delta = 16 (geometric: l = (-3, 0, 0), delta_g = 16), q = +4, t_q = 4,
// t_c = -4; the eye inside sees the far root 4. The light at the eye:
// P = (0, 0, 4), N = (3, 0, -4), K = (0, 0, -4), D = 16, I_P = 16 / (5 * 4).
TEST_CASE("boundary: with C exactly 0 the cancellation-free roots take sign(0) = +1", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{3, 0, 0}, 5}};
    scene.lights = {Light{{0, 0, 0}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        auto check = [&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Outcome o = general<Plain, F, Real>(scene, axis_w, 0, 0);
            CHECK(o.number(Key::C, "sphere 0") == 0);
            CHECK(o.number(Key::q, "sphere 0") == 4);
            CHECK(o.number(Key::t_q, "sphere 0") == 4);
            CHECK(o.number(Key::t_c, "sphere 0") == -4);
            CHECK(o.word(Key::found, "sphere 0") == "far");
            CHECK(o.branch == Branch::lit);
            CHECK(o.result == static_cast<double>(Real(16) / Real(20)));
        };
        check(SphereFormula<Formula::stable>{});
        check(SphereFormula<Formula::geometric>{});
    });
}

// A plane through the eye: n.Q = 0, so t = 0 / (n.E) = +-0 for every ray
// that is not parallel: behind the eye (t > 0 is a hit), and the trace says
// "behind", not "horizon". Both orientations: t = +0 and t = -0.
TEST_CASE("boundary: a plane through the eye (t exactly 0) is behind the eye", "[boundary]") {
    for (const double nz : {1.0, -1.0}) {
        Scene scene = scene_at(1);
        scene.planes = {Plane{{0, 0, 0}, {0, 0, nz}}};
        scene.lights = {Light{{0, 5, 1}, 1}};
        for_each_real([&](auto real) {
            using Real = decltype(real);
            INFO(real_name<Real>() << ", n = (0, 0, " << nz << ")");
            const Outcome o = general<Plain, Article, Real>(scene, axis_w, 0, 0);
            CHECK(o.number(Key::NE, "plane 0") == nz);
            CHECK(o.number(Key::t_plane, "plane 0") == 0);
            CHECK(o.word(Key::found, "plane 0") == "behind");
            CHECK(o.branch == Branch::miss);
        });
    }
}

// A ray parallel to a plane (n.E = 0) misses it without a division, and a
// shadow segment parallel to a plane (n.K = 0) is not blocked by it. The
// floor y = -1 and the middle row of a 3 x 3 pane at z_E = 2, y_E = 0
// exactly; then the floor scene's segment K = (0, 4, 0) beside the wall x = 5.
TEST_CASE("boundary: a ray or a shadow segment exactly parallel to a plane neither hits nor crosses it",
          "[boundary]") {
    Scene floor = scene_at(2);
    floor.planes = {Plane{{0, -1, 0}, {0, 1, 0}}};
    floor.lights = {Light{{0, 5, 0}, 1}};
    Scene wall = floor_scene();
    wall.planes.push_back(Plane{{5, 0, 0}, {1, 0, 0}});
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        for (int j = 0; j < 3; ++j) {
            const Outcome o = general<Plain, Article, Real>(floor, 3, 1, j);
            CHECK(o.number(Key::NE, "plane 0") == 0);
            CHECK(o.word(Key::found, "plane 0") == "parallel");
            CHECK_FALSE(o.has(Key::t_plane, "plane 0"));
            CHECK(o.all_finite());
            CHECK(o.branch == Branch::miss);
        }
        const Outcome w = general<ShadowsMany, Article, Real>(wall, 2, 1, 0);
        CHECK(w.number(Key::NK, "light 0/plane 1") == 0);
        CHECK_FALSE(w.has(Key::s, "light 0/plane 1"));
        CHECK(w.word(Key::blocker, "light 0") == "none");
        CHECK(w.branch == Branch::lit);
    });
}

// D = N.K = 0: the light in the tangent plane at P. E = (0, 0, 1),
// S = (0, 0, 4), r = 1: t = 3, P = (0, 0, 3), N = (0, 0, -1); L = (5, 0, 3):
// K = (5, 0, 0), D = 0: dark (D <= 0), in the article's kernel and in the
// general tracer (the hit faces the light when D > 0).
TEST_CASE("boundary: a hit with N.K exactly 0 is dark, in both kernels", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, 4}, 1}};
    scene.lights = {Light{{5, 0, 3}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome a = article<Article, Real>(scene, axis_w, 0, 0);
        CHECK(a.number(Key::D) == 0);
        CHECK(a.branch == Branch::dark);
        CHECK(a.result == 0);
        Scene with_shadows = scene;
        with_shadows.shadows = true;
        const Outcome g = general<Shadows, Article, Real>(with_shadows, axis_w, 0, 0);
        CHECK(g.number(Key::D, "light 0") == 0);
        CHECK_FALSE(g.has(Key::blocker, "light 0"));  // no shadow ray towards a light it does not face
        CHECK(g.branch == Branch::dark);
        CHECK(g.result == 0);
    });
}

// A light exactly on the surface, at P: K = 0, |K| = 0, D = 0: dark, and the
// unit direction K / |K| and cos(alpha), undefined, are not shown (no NaN in
// the trace).
TEST_CASE("boundary: a light exactly at the hit point (|K| = 0) is dark, with no NaN in the trace", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, 4}, 1}};
    scene.lights = {Light{{0, 0, 3}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome a = article<Article, Real>(scene, axis_w, 0, 0);
        CHECK(a.number(Key::K_len) == 0);
        CHECK_FALSE(a.has(Key::K_P));
        CHECK_FALSE(a.has(Key::cos_alpha));
        CHECK(a.all_finite());
        CHECK(a.branch == Branch::dark);
        Scene with_shadows = scene;
        with_shadows.shadows = true;
        const Outcome g = general<Shadows, Article, Real>(with_shadows, axis_w, 0, 0);
        CHECK(g.number(Key::K_len, "light 0") == 0);
        CHECK_FALSE(g.has(Key::K_P, "light 0"));
        CHECK_FALSE(g.has(Key::cos_alpha, "light 0"));
        CHECK(g.all_finite());
        CHECK(g.branch == Branch::dark);
    });
}

// I_P exactly the largest finite value is lit, not non-finite (an intensity
// is non-finite only above max). E = (0, 0, 1), S = (0, 0, 4), r = 1,
// P = (0, 0, 3), L = (0, 0, 2): K = (0, 0, -1), |K|^2 = 1, D = 1, so
// I_P = I * 1 / (1 * 1) = I = max. Float and double (a scene's I is a double).
TEST_CASE("boundary: an intensity of exactly max is lit, not non-finite", "[boundary]") {
    auto run = [](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const double max = static_cast<double>(RealTraits<Real>::max());
        Scene scene = scene_at(1);
        scene.spheres = {Sphere{{0, 0, 4}, 1}};
        scene.lights = {Light{{0, 0, 2}, max}};
        const Outcome a = article<Article, Real>(scene, axis_w, 0, 0);
        CHECK(a.branch == Branch::lit);
        CHECK(a.result == max);
        Scene with_shadows = scene;
        with_shadows.shadows = true;
        const Outcome g = general<Shadows, Article, Real>(with_shadows, axis_w, 0, 0);
        CHECK(g.branch == Branch::lit);
        CHECK(g.result == max);
    };
    run(float{});
    run(double{});
}

// Two objects at exactly the same t: the earlier wins (spheres are tested
// before planes). Spheres at S = (0, 0, 4), r = 1, and the plane z = 3: all
// met at t = 3 by E = (0, 0, 1) (article: (4 - 1) / 1; stable and geometric:
// q = 5, c_0 / q = 15 / 5).
TEST_CASE("boundary: objects at exactly the same t: the earlier one is the hit", "[boundary]") {
    const Sphere sphere{{0, 0, 4}, 1};
    const Plane plane{{0, 0, 3}, {0, 0, -1}};
    Scene two_spheres = scene_at(1);
    two_spheres.spheres = {sphere, sphere};
    two_spheres.lights = {Light{{0, 5, 0}, 1}};
    Scene sphere_and_plane = two_spheres;
    sphere_and_plane.spheres = {sphere};
    sphere_and_plane.planes = {plane};
    Scene two_planes = two_spheres;
    two_planes.spheres = {};
    two_planes.planes = {plane, plane};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        for_each_formula([&](auto formula) {
            using F = decltype(formula);
            INFO(real_name<Real>() << ", formula " << formula_name(F::id));
            const Outcome s = general<Many, F, Real>(two_spheres, axis_w, 0, 0);
            CHECK(s.number(Key::t_hit) == 3);
            CHECK(s.hit == "sphere 0");
            const Outcome sp = general<Many, F, Real>(sphere_and_plane, axis_w, 0, 0);
            CHECK(sp.number(Key::t_plane, "plane 0") == 3);
            CHECK(sp.hit == "sphere 0");
        });
        INFO(real_name<Real>());
        const Outcome p = general<Many, Article, Real>(two_planes, axis_w, 0, 0);
        CHECK(p.hit == "plane 0");
    });
}

// Its own sphere seen from inside: the segment from P to the light meets the
// sphere again at s = 2D / |K|^2, a blocker when s < 1. A light exactly on
// the inner surface: s = 1, not blocked. Sphere S = O, r = 2, E = (0, 0, 1):
// P = (0, 0, 2), N = (0, 0, -2) (flipped); L = (0, 2, 0): K = (0, 2, -2),
// |K|^2 = 8, D = 4, 2D = 8 = |K|^2.
TEST_CASE("boundary: inside a sphere, a light exactly on its inner surface is not blocked by it", "[boundary]") {
    Scene scene = scene_at(1);
    scene.spheres = {Sphere{{0, 0, 0}, 2}};
    scene.lights = {Light{{0, 2, 0}, 1}};
    scene.shadows = true;
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome o = general<Shadows, Article, Real>(scene, axis_w, 0, 0);
        CHECK(o.word(Key::flipped) == "inside");
        CHECK(o.number(Key::s_own, "light 0/sphere 0") == 1);
        CHECK(o.word(Key::blocker, "light 0") == "none");
        CHECK(o.branch == Branch::lit);
    });
}

// A shadow ray tangent to another sphere (delta_s = 0) is not blocked: it
// touches the surface without crossing it. Floor P = (-1, -1, 2), K = (0, 4, 0);
// blocker S = (0, 1, 2), r = 1, at distance 1 from the segment's line:
// S - P = (1, 2, 0), b_s = 8, c_s = 4, delta_s = 64 - 16 * 4 = 0.
TEST_CASE("boundary: a shadow ray tangent to a sphere (delta_s exactly 0) is not blocked", "[boundary]") {
    Scene scene = floor_scene();
    scene.spheres = {Sphere{{0, 1, 2}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome o = general<ShadowsMany, Article, Real>(scene, 2, 1, 0);
        CHECK(o.hit == "plane 0");
        CHECK(o.number(Key::delta_s, "light 0/sphere 0") == 0);
        CHECK(o.word(Key::blocker, "light 0") == "none");
        CHECK(o.branch == Branch::lit);
        CHECK(o.result == 1);
    });
}

// A light exactly on a blocker's near surface: the segment ends where it
// would cross (s_1 = 1), so it is not blocked. Blocker S = (-1, 4, 2), r = 1:
// S - P = (0, 5, 0), b_s = 20, c_s = 24, delta_s = 16, s_1 = (20 - 4) / 16 = 1,
// s_2 = 24 / 16. And the same blocker moved down by 1: the light on its far
// side (s_2 = 1), the segment crossing its near side at s_1 = 1/2: blocked.
TEST_CASE("boundary: a light exactly on a blocker's near surface is not blocked, on its far surface it is",
          "[boundary]") {
    Scene scene = floor_scene();
    scene.spheres = {Sphere{{-1, 4, 2}, 1}};
    Scene far_side = floor_scene();
    far_side.spheres = {Sphere{{-1, 2, 2}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome o = general<ShadowsMany, Article, Real>(scene, 2, 1, 0);
        CHECK(o.number(Key::s_1, "light 0/sphere 0") == 1);
        CHECK(o.number(Key::s_2, "light 0/sphere 0") == 1.5);
        CHECK(o.word(Key::blocker, "light 0") == "none");
        CHECK(o.branch == Branch::lit);
        const Outcome f = general<ShadowsMany, Article, Real>(far_side, 2, 1, 0);
        CHECK(f.number(Key::s_1, "light 0/sphere 0") == 0.5);
        CHECK(f.number(Key::s_2, "light 0/sphere 0") == 1);
        CHECK(f.word(Key::blocker, "light 0") == "sphere 0");
        CHECK(f.branch == Branch::shadowed);
    });
}

// The sphere segment test's two other ends, on the stage itself (a scene's
// eye ray cannot end on a blocker's surface without hitting the blocker):
// P on the blocker's surface, K = (0, 2, 0), |K|^2 = 4.
// - S = (0, 1, 0), r = 1: the segment is a chord, s_1 = 0 and s_2 = 1: it
//   crosses the surface at neither inner point: not blocked.
// - S = (0, -1, 0), r = 1: P on the far side, the segment leaves the sphere:
//   s_1 = -1, s_2 = 0: not blocked.
// - S = (0, 1, 0), r = 1, K = (0, 1, 0) (the light at the centre): s_1 = 0,
//   s_2 = 2: not blocked.
TEST_CASE("boundary: a shadow segment starting exactly on a sphere (s = 0) or ending on it (s = 1) is not blocked",
          "[boundary]") {
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        using V = Vec3<Real>;
        const V P{0, 0, 0};
        auto blocks = [&](V K, V S, Real& s_1, Real& s_2) {
            BoundaryRecorder record;
            const Blocks b = sphere_blocks(P, K, length_squared(K), S, Real(1), record);
            for (const Step& step : record.take_steps()) {
                if (step.key == Key::s_1) s_1 = Real(std::get<double>(step.value));
                if (step.key == Key::s_2) s_2 = Real(std::get<double>(step.value));
            }
            return b;
        };
        Real s_1 = 7, s_2 = 7;
        CHECK(blocks(V{0, 2, 0}, V{0, 1, 0}, s_1, s_2) == Blocks::no);
        CHECK(s_1 == 0);
        CHECK(s_2 == 1);
        CHECK(blocks(V{0, 2, 0}, V{0, -1, 0}, s_1, s_2) == Blocks::no);
        CHECK(s_1 == -1);
        CHECK(s_2 == 0);
        CHECK(blocks(V{0, 1, 0}, V{0, 1, 0}, s_1, s_2) == Blocks::no);
        CHECK(s_1 == 0);
        CHECK(s_2 == 2);
    });
}

// Another plane through P (s = 0: a copy of the floor, which the eye's ray
// meets at the same t, the earlier winning) does not block; nor does a plane
// through the light (s = 1: y = 3, s = (3 - (-1)) / 4).
TEST_CASE("boundary: a plane exactly through P or exactly through the light does not block", "[boundary]") {
    Scene through_P = floor_scene();
    through_P.planes.push_back(through_P.planes[0]);
    Scene through_L = floor_scene();
    through_L.planes.push_back(Plane{{0, 3, 0}, {0, 1, 0}});
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome p = general<ShadowsMany, Article, Real>(through_P, 2, 1, 0);
        CHECK(p.hit == "plane 0");
        CHECK(p.number(Key::s, "light 0/plane 1") == 0);
        CHECK(p.word(Key::blocker, "light 0") == "none");
        CHECK(p.branch == Branch::lit);
        const Outcome l = general<ShadowsMany, Article, Real>(through_L, 2, 1, 0);
        CHECK(l.number(Key::s, "light 0/plane 1") == 1);
        CHECK(l.word(Key::blocker, "light 0") == "none");
        CHECK(l.branch == Branch::lit);
    });
}

// Phong's R.V = 0: no specular term (it is added when R.V > 0). On the stage:
// N = (0, 1, 0), r = 1, K = (1, 1, 0), V = (0, 0, 1): K_hat = (a, a, 0),
// cos(alpha) = a, R_hat = (2a) N - K_hat = (-a, a, 0) exactly, R.V = 0.
// (From a scene, V_hat and R_hat are not exact enough for R.V to be exactly
// 0; the value would be 0 either way, 0^n = 0: the trace tells.)
TEST_CASE("boundary: Phong with R.V exactly 0 adds no specular term", "[boundary]") {
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        using V = Vec3<Real>;
        BoundaryRecorder record;
        const V K{1, 1, 0};
        const Real specular =
            phong_specular(V{0, 1, 0}, Real(1), K, length_squared(K), V{0, 0, 1}, Real(1), Real(0.5), 10, record);
        CHECK(specular == 0);
        bool rv_zero = false, rv_n = false;
        for (const Step& step : record.take_steps()) {
            if (step.key == Key::RV) rv_zero = std::get<double>(step.value) == 0;
            if (step.key == Key::RV_n || step.key == Key::specular) rv_n = true;
        }
        CHECK(rv_zero);
        CHECK_FALSE(rv_n);
    });
}

// A material with k_s = 0 in a scene whose other material is shiny: Phong's
// stage runs, but not for it (k_s > 0). Spheres S = (0, 0, 4) (k_s = 0, hit
// by E = (0, 0, 1)) and S = (0, 5, 4) (k_s = 1/2).
TEST_CASE("boundary: a material with k_s exactly 0 gets no Phong term beside a shiny one", "[boundary]") {
    Scene scene = scene_at(1);
    Material matte;
    matte.specular = 0;
    Material shiny;
    shiny.specular = 0.5;
    scene.materials = {matte, shiny};
    scene.spheres = {Sphere{{0, 0, 4}, 1, 0}, Sphere{{0, 5, 4}, 1, 1}};
    scene.lights = {Light{{1, 1, 0}, 1}};
    for_each_real([&](auto real) {
        using Real = decltype(real);
        INFO(real_name<Real>());
        const Outcome o = general<PhongMany, Article, Real>(scene, axis_w, 0, 0);
        CHECK(o.hit == "sphere 0");
        CHECK(o.branch == Branch::lit);
        CHECK_FALSE(o.has(Key::R_hat, "light 0"));
        CHECK_FALSE(o.has(Key::RV, "light 0"));
    });
}

// A sample's cell: sample s of an n x n grid lies in cell (s div n, s mod n),
// [c/n, (c+1)/n) - 1/2 along each axis: closed below (a jitter of exactly 0,
// found by search and pinned here, puts it on the cell's lower edge), open
// above (the jitter is at most 65535/65536).
TEST_CASE("boundary: a sample with a jitter of exactly 0 lies on its cell's lower edge, inside the cell",
          "[boundary]") {
    struct Pinned {
        int i, j, s;
        bool u_zero;  // the jitter along u is 0 (else along v)
    };
    for (const Pinned p : {Pinned{0, 1588, 0, true}, Pinned{11, 1241, 1, false}}) {
        INFO("pixel (" << p.i << ", " << p.j << "), sample " << p.s);
        const std::uint32_t h = sample_hash(p.i, p.j, p.s);
        CHECK((p.u_zero ? (h & 0xffffU) : (h >> 16)) == 0);
        const SampleOffset o = sample_offset(p.i, p.j, p.s, 4);
        const double lower_u = (p.s % 2) / 2.0 - 0.5, lower_v = (p.s / 2) / 2.0 - 0.5;
        if (p.u_zero)
            CHECK(o.u == lower_u);
        else
            CHECK(o.v == lower_v);
    }
    // Every sample of a few pixels, every grid: inside its own cell.
    for (int n = 2; n <= 32; n *= 2)
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int s = 0; s < n * n; ++s) {
                    const SampleOffset o = sample_offset(i, j, s, n * n);
                    const double u = (o.u + 0.5) * n, v = (o.v + 0.5) * n;  // exact: n is a power of two
                    CHECK(std::floor(u) == s % n);
                    CHECK(std::floor(v) == s / n);
                }
}

// Two samples exactly as near the pixel's centre: the lower index is the
// centre sample, whose branch is the pixel's (render/sampling.hpp and
// centre_sample). Such a tie is rare: a search of every pixel of an
// 8192 x 8192 pane at spp 4, 9, 16, 25, 36 and 64 found this one, samples 27
// and 28 of pixel (7574, 3583) at spp 64 (u^2 + v^2 = 0x1.187038cap-7 both).
TEST_CASE("boundary: two samples exactly as near the centre: the lower index is the centre sample", "[boundary]") {
    constexpr int i = 7574, j = 3583, spp = 64, w = 7576;
    const SampleOffset a = sample_offset(i, j, 27, spp), b = sample_offset(i, j, 28, spp);
    CHECK(a.u * a.u + a.v * a.v == b.u * b.u + b.v * b.v);
    CHECK(centre_sample(i, j, spp) == 27);
    struct Result {
        double I_P;
        Branch branch;
    };
    const SampledPixel<double> pixel = sample_pixel<double>(
        w, i, j, spp, 2.0, [](int s, const Vec3d&) { return Result{double(s), Branch::lit}; }, [](int, const Result&) {});
    CHECK(pixel.centre == 27);
    // The product's trace says so too.
    const Scene scene = article_scene();
    const PixelTrace trace = trace_pixel(scene, w, i, j, RealType::double_, Formula::article, spp);
    REQUIRE(trace.samples);
    CHECK(trace.samples->centre == 27);
}

// Found by the random scenes scaled across the range (docs/boundaries.md):
// a value beyond the type's range decided "behind the eye" where it decides
// nothing. Each scene is in exact binary numbers.
//
// A root of -inf. E = (0, 0, 2^-80), S = (0, 0, -2^40), r = 1: in float
// |E|^2 = 2^-160 underflows to 0, C = -2^-40, delta = C^2 = 2^-80, so the near
// root (C - sqrt(delta)) / |E|^2 = -2^-39 / 0 = -inf (the sphere is behind the
// eye, but no float can say where). In double every number is finite and the
// sphere is behind the eye: a miss.
//
// q = -inf. E = (0, 0, 2), S = (0, 0, -2^62), r = 2^63 (the eye inside): in
// float delta_g = 2^126 and |E|^2 delta_g = 2^128 overflows, q = C - inf, and
// the stable and geometric roots are -inf and +0; the article's and fma's
// delta = 2^128 overflows. In double the far root, 2^61, is seen from inside.
TEST_CASE("boundary: a root of -inf is not behind the eye: it decides nothing (float)", "[boundary]") {
    Scene behind = scene_at(0x1p-80);
    behind.spheres = {Sphere{{0, 0, -0x1p40}, 1}};
    behind.lights = {Light{{0, 5, 0}, 1}};
    Scene inside = scene_at(2);
    inside.spheres = {Sphere{{0, 0, -0x1p62}, 0x1p63}};
    inside.lights = {Light{{0, 0, 0}, 1}};
    for_each_formula([&](auto formula) {
        using F = decltype(formula);
        INFO("formula " << formula_name(F::id));
        const Outcome a = article<F, float>(behind, axis_w, 0, 0);
        CHECK(a.branch == Branch::non_finite);
        CHECK(article<F, double>(behind, axis_w, 0, 0).branch == Branch::miss);
        Scene with_shadows = behind;
        with_shadows.shadows = true;
        CHECK(general<Shadows, F, float>(with_shadows, axis_w, 0, 0).branch == Branch::non_finite);
        CHECK(general<Shadows, F, double>(with_shadows, axis_w, 0, 0).branch == Branch::miss);
        const Outcome i = general<Plain, F, float>(inside, axis_w, 0, 0);
        CHECK(i.branch == Branch::non_finite);
        const Outcome d = general<Plain, F, double>(inside, axis_w, 0, 0);
        CHECK(d.word(Key::found, "sphere 0") == "far");
        CHECK(d.number(Key::t_hit) == 0x1p61);
    });
}

// A plane beyond the type's range: Q = (0, 0, 2^130) is +inf in float, so
// n_hat.Q is -inf and t = -inf / -1 = +inf would be "the horizon"; with
// Q = (1.5 2^127, 0, 1.5 2^127) (finite floats) and n = (1, 0, 1),
// n_hat.Q = 1.5 sqrt(2) 2^127 overflows float: t = inf / 0.7 decides nothing
// either. In double both are far planes, hit at t = 2^130 and about 3 2^127:
// decided, every number finite.
TEST_CASE("boundary: a plane beyond the type's range decides nothing (float)", "[boundary]") {
    Scene far_wall = scene_at(1);
    far_wall.planes = {Plane{{0, 0, 0x1p130}, {0, 0, -1}}};
    far_wall.lights = {Light{{0, 0, 0}, 1}};
    Scene tilted = scene_at(1);
    tilted.planes = {Plane{{0x1.8p127, 0, 0x1.8p127}, {1, 0, 1}}};
    tilted.lights = {Light{{0, 0, 0}, 1}};
    for (const Scene* scene : {&far_wall, &tilted}) {
        const Outcome f = general<Plain, Article, float>(*scene, axis_w, 0, 0);
        CHECK(f.branch == Branch::non_finite);
        CHECK_FALSE(f.has(Key::found, "plane 0"));
        const Outcome d = general<Plain, Article, double>(*scene, axis_w, 0, 0);
        CHECK(d.branch != Branch::non_finite);
        CHECK(d.all_finite());
    }
}
