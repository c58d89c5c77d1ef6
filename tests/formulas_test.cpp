// --formula article|stable|fma|geometric: each formula on rays whose answer
// is known (by hand, or computed in quad from the same binary inputs), the
// far small sphere that the article's formula loses, the huge near sphere
// whose near root it cancels away, tangent rays, and traced equals untraced
// for every formula in every real type.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/sphere_formulas.hpp"
#include "math/real.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/recorder.hpp"

using namespace promyk;

namespace {

template <class Real>
Vec3<Real> vec(double x, double y, double z) {
    return {Real(x), Real(y), Real(z)};
}

template <class Real>
Vec3<quad> widen(const Vec3<Real>& v) {
    return {quad(v.x), quad(v.y), quad(v.z)};
}

// What the formula's trace says it found (near, far, behind, miss).
template <class Real>
std::string found_word(Formula formula, const Vec3<Real>& E, const Vec3<Real>& S, Real r) {
    RecordingRecorder record;
    intersect_sphere_with(formula, E, S, r, record);
    std::string word;
    for (const Step& step : record.take_steps())
        if (step.key == Key::found) word = std::get<std::string>(step.value);
    return word;
}

// |got - exact| in units in the last place of exact rounded to Real.
template <class Real>
double ulps(Real got, quad exact) {
    const Real rounded = Real(exact);
    const Real up = std::nextafter(rounded, RealTraits<Real>::infinity());
    return static_cast<double>(fabsq(quad(got) - exact) / (quad(up) - quad(rounded)));
}

// The exact near root of the ray tE against the sphere (S, r), all three
// read exactly from their binary values: the geometric formula in quad, whose
// 113-bit rounding is far below every error measured here (its own error is
// about eps_quad |S| / r relative, 1e-26 at |S| = 1e8).
template <class Real>
quad exact_root(const Vec3<Real>& E, const Vec3<Real>& S, Real r) {
    NullRecorder none;
    const auto root = intersect_sphere_geometric(widen(E), widen(S), quad(r), none);
    REQUIRE(root);
    return root->t;
}

struct FanResult {
    int misses = 0;
    double max_ulps = 0;  // over the rays that hit
};

// The formula on rays E_k = ray(k), k = 0 .. rays - 1, that must all hit the
// sphere (S, r): how many it misses, and its largest error in t in ulps.
template <class Real, class Ray>
FanResult fan(Formula formula, const Vec3<Real>& S, Real r, Ray ray, int rays = 200) {
    NullRecorder none;
    FanResult result;
    for (int k = 0; k < rays; ++k) {
        const Vec3<Real> E = ray(k, rays);
        const quad exact = exact_root(E, S, r);
        const auto root = intersect_sphere_with(formula, E, S, r, none);
        if (!root) {
            ++result.misses;
            continue;
        }
        result.max_ulps = std::max(result.max_ulps, ulps(root->t, exact));
    }
    return result;
}

// A fan of rays E = (a, 0, 1) from the eye towards a unit sphere centred at
// (0, 0, D): a from 0 up to 0.9 / D, so each passes the centre at a distance
// D a / sqrt(1 + a^2) < 0.9 and must hit.
template <class Real>
FanResult far_sphere_fan(Formula formula, double D) {
    return fan(formula, vec<Real>(0, 0, D), Real(1),
               [D](int k, int rays) { return vec<Real>(0.9 * k / rays / D, 0, 1); });
}

// A huge sphere (radius R, an integer) whose surface is at distance 1 in
// front of the eye: S = (0, 0, R + 1), so |S|^2 - r^2 = 2R + 1 is exact. The
// rays E = (a, a/2, 1), a from 0 to 1/2, all hit near t = 1.
template <class Real>
FanResult huge_near_sphere_fan(Formula formula, double R) {
    return fan(formula, vec<Real>(0, 0, R + 1), Real(R), [](int k, int rays) {
        const Real a = Real(0.5 * k / rays);
        return Vec3<Real>{a, a / 2, Real(1)};
    });
}

}  // namespace

TEST_CASE("every formula gives the hand-derived root on exactly representable rays", "[formula]") {
    for (const Formula formula : all_formulas) {
        INFO("formula " << formula_name(formula));
        NullRecorder none;
        // Through the centre: t = (|S| - r) / |E|, exact: 3 and 1.5.
        auto root = intersect_sphere_with(formula, vec<double>(0, 0, 1), vec<double>(0, 0, 4), 1.0, none);
        REQUIRE(root);
        CHECK(root->t == 3);
        CHECK_FALSE(root->inside);
        root = intersect_sphere_with(formula, vec<double>(0, 0, 2), vec<double>(0, 0, 4), 1.0, none);
        REQUIRE(root);
        CHECK(root->t == 1.5);
        // Off the centre by 3 with r = 5 (a 3-4-5 triangle): t = 10 - 4 = 6.
        root = intersect_sphere_with(formula, vec<double>(0, 0, 1), vec<double>(3, 0, 10), 5.0, none);
        REQUIRE(root);
        CHECK(root->t == 6);
        // The eye inside: roots 0.5 - 2 and 0.5 + 2; the far one, seen from inside.
        root = intersect_sphere_with(formula, vec<double>(0, 0, 1), vec<double>(0, 0, 0.5), 2.0, none);
        REQUIRE(root);
        CHECK(root->t == 2.5);
        CHECK(root->inside);
        CHECK(found_word(formula, vec<double>(0, 0, 1), vec<double>(0, 0, 0.5), 2.0) == "far");
        // Behind the eye: roots -5 and -3, no hit, and the trace says why.
        CHECK_FALSE(intersect_sphere_with(formula, vec<double>(0, 0, 1), vec<double>(0, 0, -4), 1.0, none));
        CHECK(found_word(formula, vec<double>(0, 0, 1), vec<double>(0, 0, -4), 1.0) == "behind");
        // A clean miss, and a tangent ray with every number exact (delta = 0
        // computed exactly): a tangent ray misses, as in the article.
        CHECK(found_word(formula, vec<double>(0, 0, 1), vec<double>(3, 0, 10), 2.0) == "miss");
        CHECK(found_word(formula, vec<double>(0, 0, 1), vec<double>(3, 4, 10), 5.0) == "miss");
        // The eye on the surface (c = 0): the root t = 0 is not in front of
        // the eye; the other one, 8, is taken.
        root = intersect_sphere_with(formula, vec<double>(0, 0, 1), vec<double>(0, 0, 4), 4.0, none);
        REQUIRE(root);
        CHECK(root->t == 8);
    }
}

TEST_CASE("coefficients that overflow are reported non-finite by every formula, never as a miss", "[formula]") {
    for (const Formula formula : all_formulas) {
        INFO("formula " << formula_name(formula));
        NullRecorder none;
        // |S|^2 and r^2 overflow to infinity: delta is NaN or infinite.
        const auto root = intersect_sphere_with(formula, vec<double>(0.25, 0, 1), vec<double>(0, 0, 1e200), 1e199, none);
        REQUIRE(root);
        CHECK_FALSE(std::isfinite(root->t));
    }
}

// Tangent rays whose exact delta is 0: the ray E = (3/4, 0, 1) and the
// centre S = sE + p with p = k (1, 0, -3/4), perpendicular to E, and
// r = |p| = 5k/4 (1 + 9/16 = 25/16), so the centre lies at exactly r from the
// ray. s has 40 significant bits and k 20, so S is exact; C, |S|^2 and the
// rest round. What each formula reports (a false hit or the right miss):
// - article and stable compute the same delta, so they report the same: a
//   false hit on a good share of the rays (about one in six here);
// - fma computes C^2 - |E|^2 c exactly, but from the rounded C and c, whose
//   errors have either sign: a false hit on about half of them;
// - geometric computes delta_g = r^2 - |l|^2 from l, which is within a few
//   u |S| of p: on this family it rounds to <= 0 every time (it could
//   report a false hit, but only from an error of a few u |S| r, not u |S|^2).
TEST_CASE("tangent rays: the article's formula reports false hits by rounding, the geometric none", "[formula]") {
    NullRecorder none;
    const auto bits = [](double x, int b) {
        int e = 0;
        const double m = std::frexp(x, &e);
        return std::ldexp(std::round(std::ldexp(m, b)), e - b);
    };
    int article_hits = 0, stable_hits = 0, fma_hits = 0, geometric_hits = 0, rays = 0;
    for (const double k0 : {0.3, 0.5, 1.7}) {
        for (int n = 0; n < 400; ++n) {
            const double s = bits(1 + 0.37 * n, 40), k = bits(k0, 20);
            const Vec3<double> E = vec<double>(0.75, 0, 1);
            const Vec3<double> S = vec<double>(0.75 * s + k, 0, s - 0.75 * k);
            const double r = 1.25 * k;
            REQUIRE(static_cast<long double>(S.x) == 0.75L * s + k);  // S exact: the exact delta is 0
            REQUIRE(static_cast<long double>(S.z) == s - 0.75L * k);
            ++rays;
            article_hits += intersect_sphere_with(Formula::article, E, S, r, none).has_value();
            stable_hits += intersect_sphere_with(Formula::stable, E, S, r, none).has_value();
            fma_hits += intersect_sphere_with(Formula::fma, E, S, r, none).has_value();
            geometric_hits += intersect_sphere_with(Formula::geometric, E, S, r, none).has_value();
        }
    }
    INFO("false hits of " << rays << " tangent rays: article " << article_hits << ", stable " << stable_hits
                          << ", fma " << fma_hits << ", geometric " << geometric_hits);
    CHECK(article_hits > rays / 10);     // a good share of false hits
    CHECK(article_hits < rays / 2);      // and right misses: decided by rounding
    CHECK(stable_hits == article_hits);  // the same delta
    CHECK(fma_hits > rays / 4);          // exact from rounded inputs: more false hits, not fewer
    CHECK(geometric_hits == 0);
}

// The far small sphere (a unit sphere at distance D on the axis).
//
// The article's delta = C^2 - |E|^2 (|S|^2 - r^2) subtracts two numbers of
// about D^2 to get one of about r^2 = 1. Each carries a rounding error of
// about u D^2 (u = 2^-24 in float, 2^-53 in double), so delta is off by a
// few u D^2: in float the error reaches delta itself near D = 2^12 = 4096.
// Beyond it the computed delta rounds to 0 or below for every ray (D^2 and
// D^2 - 1 round to the same float): the sphere is lost. Before that, the
// error in delta moves sqrt(delta) by about u D^2 / sqrt(delta), and so t
// (about D, whose ulp is about u D) by about D / r ulps: the article keeps
// only the digits of t above D / r.
//
// The stable formula takes the same delta, so it loses the far sphere just
// as the article does (its gain is the near root's cancellation, below);
// fma computes C^2 - |E|^2 c exactly from the rounded C, |E|^2 and c, which
// are already off by u D^2: it loses the sphere too, except at distances
// where c happens to be exact (D^2 - 1 representable).
//
// The geometric formula's bound, operation by operation, for the near root
// t_c = c / q with q = C + sqrt(|E|^2 delta_g) (each operation one rounding,
// relative error at most u): c = |S|^2 - r^2 is within 3u (|S|^2 one
// rounding, r^2 exact, the difference one, r^2 small against |S|^2);
// C = E.S is one product (S on the axis), within u. delta_g = r^2 - |l|^2 has
// an absolute error of about 2 |l| 3u D (l's components come from
// t_mid = C / |E|^2, within 3u, times E, minus S: absolute errors 3u D), with
// |l| <= 0.9 r and delta_g >= 0.19 r^2; sqrt(|E|^2 delta_g) is then off by
// at most 2.7u D / sqrt(0.19) = 6.2u D, which against q, about 2D, is 3.1u.
// So q is within u + 3.1u + u, and t_c = c / q within 3u + 5.1u + u, about
// 9u: at most 9 ulps of t (an ulp of t is at least u t). We assert 10.
TEST_CASE("far small spheres in float: the article's formula loses the sphere past 4096, geometric keeps t",
          "[formula]") {
    // D = 1000: every ray hits, but t keeps only the digits above D / r.
    FanResult article = far_sphere_fan<float>(Formula::article, 1000);
    CHECK(article.misses == 0);
    CHECK(article.max_ulps > 1000 / 10);
    CHECK(article.max_ulps < 1000 * 10);
    // Just above 2^12 every ray of the fan misses: the sphere is gone.
    for (const double D : {4097.0, 4100.0, 1e4, 1e5, 1e6, 1e7, 1e8}) {
        INFO("D = " << D);
        CHECK(far_sphere_fan<float>(Formula::article, D).misses == 200);
        CHECK(far_sphere_fan<float>(Formula::stable, D).misses == 200);
    }
    // fma: lost where c was rounded (4100, 1e4), found where it is exact (4097).
    CHECK(far_sphere_fan<float>(Formula::fma, 4100).misses == 200);
    CHECK(far_sphere_fan<float>(Formula::fma, 1e4).misses == 200);
    CHECK(far_sphere_fan<float>(Formula::fma, 4097).misses == 0);
    // geometric: every ray hits, t within the bound, at every distance.
    for (const double D : {1e3, 4097.0, 4100.0, 1e4, 1e5, 1e6, 1e7, 1e8}) {
        INFO("D = " << D);
        const FanResult geometric = far_sphere_fan<float>(Formula::geometric, D);
        CHECK(geometric.misses == 0);
        CHECK(geometric.max_ulps <= 10);
    }
}

TEST_CASE("far small spheres in double: the article's formula loses digits as D grows and the sphere by 1e8",
          "[formula]") {
    for (const double D : {1e4, 1e5, 1e6, 1e7, 3e7}) {
        INFO("D = " << D);
        const FanResult article = far_sphere_fan<double>(Formula::article, D);
        CHECK(article.misses == 0);
        // About D / r ulps: log10(D) of t's 16 digits are lost.
        CHECK(article.max_ulps > D / 10);
        CHECK(article.max_ulps < D * 10);
        const FanResult geometric = far_sphere_fan<double>(Formula::geometric, D);
        CHECK(geometric.misses == 0);
        CHECK(geometric.max_ulps <= 10);
    }
    for (const double D : {1e8, 1e9}) {
        INFO("D = " << D);
        CHECK(far_sphere_fan<double>(Formula::article, D).misses == 200);
        CHECK(far_sphere_fan<double>(Formula::stable, D).misses == 200);
        const FanResult geometric = far_sphere_fan<double>(Formula::geometric, D);
        CHECK(geometric.misses == 0);
        CHECK(geometric.max_ulps <= 10);
    }
}

// The huge sphere close to the eye: sqrt(delta) is nearly C (|E|^2 c = 2R + 1
// is small against C^2 = R^2), so the article's C - sqrt(delta) cancels:
// delta's relative error of about 2u becomes an error of about u C in
// sqrt(delta), and t (about 1) is off by about u R, R / 2 ulps or so.
// The stable formula's near root c / q divides the exact c by a sum of two
// numbers of one sign: C exact (one product of 1 and R + 1), delta within
// about 3u (C^2 one rounding, |E|^2 c small against it, the difference one),
// sqrt(delta) within 2.5u, q within 3.5u, t_c = c / q within 4.5u: at most 5
// ulps; we assert 8. The geometric formula takes its roots the same way.
// fma does nothing for this case: its delta was not the problem.
TEST_CASE("a huge sphere close to the eye: stable and geometric keep the near root, the article cancels it",
          "[formula]") {
    const FanResult article_f = huge_near_sphere_fan<float>(Formula::article, 1000);
    CHECK(article_f.misses == 0);
    CHECK(article_f.max_ulps > 1000 / 10);
    const FanResult article_d = huge_near_sphere_fan<double>(Formula::article, 1e7);
    CHECK(article_d.misses == 0);
    CHECK(article_d.max_ulps > 1e7 / 10);
    CHECK(huge_near_sphere_fan<double>(Formula::fma, 1e7).max_ulps > 1e7 / 10);
    for (const Formula formula : {Formula::stable, Formula::geometric}) {
        INFO("formula " << formula_name(formula));
        const FanResult f = huge_near_sphere_fan<float>(formula, 1000);
        CHECK(f.misses == 0);
        CHECK(f.max_ulps <= 8);
        const FanResult d = huge_near_sphere_fan<double>(formula, 1e7);
        CHECK(d.misses == 0);
        CHECK(d.max_ulps <= 8);
    }
}

TEST_CASE("each formula in each real type: traced equals untraced on every example scene", "[formula]") {
    std::vector<Scene> scenes = {article_scene()};
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes"))
        if (entry.path().extension() == ".json" && entry.path().string().find(".schema.") == std::string::npos)
            scenes.push_back(load_scene_file(entry.path().string()));
    REQUIRE(scenes.size() >= 9);
    constexpr int w = 8;
    for (const Scene& scene : scenes) {
        const TraceHeader header = trace_header(scene, w);
        for (const RealType type : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_}) {
            for (const Formula formula : all_formulas) {
                INFO("scene " << scene.name << ", " << real_type_name(type) << ", " << formula_name(formula));
                const auto kernel = make_kernel(scene, type, formula);
                std::vector<std::uint8_t> row(static_cast<std::size_t>(w * kernel->channels()));
                for (int i = 0; i < w; ++i) {
                    kernel->row(w, i, row.data());
                    for (int j = 0; j < w; ++j) {
                        const PixelTrace trace = kernel->trace(header, i, j);
                        CHECK(trace.header.formula == formula_name(formula));
                        CHECK(trace.header.real == real_type_name(type));
                        Branch branch;
                        const Vec3d untraced = kernel->intensity(w, i, j, &branch);
                        CHECK(trace.branch == branch);
                        CHECK((trace.result_rgb ? *trace.result_rgb : Vec3d{trace.result, trace.result, trace.result}) ==
                              (trace.result_rgb ? untraced : Vec3d{untraced.x, untraced.x, untraced.x}));
                        CHECK(row[static_cast<std::size_t>(j * kernel->channels())] == trace.grey);
                    }
                }
            }
        }
    }
}

TEST_CASE("the article's formula is the default and the other formulas agree with it on the article's scene",
          "[formula]") {
    const Scene scene = article_scene();
    constexpr int w = 32;
    const auto article = make_kernel(scene);
    CHECK(trace_pixel(scene, 8, 3, 4).header.formula == "article");
    for (const Formula formula : all_formulas) {
        const auto kernel = make_kernel(scene, RealType::double_, formula);
        int branches_differ = 0;
        double largest = 0;
        for (int i = 0; i < w; ++i)
            for (int j = 0; j < w; ++j) {
                Branch a, b;
                const double x = article->intensity(w, i, j, &a).x, y = kernel->intensity(w, i, j, &b).x;
                branches_differ += a != b;
                if (a == b) largest = std::max(largest, std::fabs(x - y));
            }
        INFO("formula " << formula_name(formula));
        CHECK(branches_differ == 0);  // no pixel of the article's scene is that close to an edge
        CHECK(largest < 1e-13);       // a few ulps of a t near 1 move I_P by about as much
    }
}
