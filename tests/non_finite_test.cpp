// The non-finite branch: a NaN or an infinity never decides miss, dark or lit.
// The property, over scenes whose numbers reach the ends of the double range:
// a pixel's branch is non-finite exactly when one of the program's steps or
// its result is not finite, and the renderer counts the same pixels as the tracer.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "image/quantize.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"

using namespace promyk;

namespace {

Scene scene_with(double z_E, Vec3d S, double r, Vec3d L, double I) {
    Scene scene = article_scene();
    scene.name = "overflow";
    scene.z_E = z_E;
    scene.spheres = {Sphere{S, r}};
    scene.lights = {Light{L, I}};
    return scene;
}

// The program's own steps and the result; the lessons' extra quantities
// (4 delta, N / r, ...) may overflow on their own without deciding anything.
bool all_finite(const PixelTrace& trace) {
    std::vector<Step> program;
    for (const Step& step : trace.steps)
        if (is_program_key(step.key)) program.push_back(step);
    return !first_non_finite_step(program) && std::isfinite(trace.result);
}

std::string key_at(const PixelTrace& trace, std::size_t k) { return std::string(key_name(trace.steps[k].key)); }

}  // namespace

TEST_CASE("a pane at z_E = 1e200 overflows |E|² and no pixel gets a numeric branch", "[non-finite]") {
    const Scene scene = scene_with(1e200, {0, 0, 3.2}, 1.1, {1.5, 1, 1}, 1);
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const PixelTrace trace = trace_pixel(scene, 8, i, j);
            INFO("pixel (" << i << ", " << j << ")");
            CHECK(trace.branch == Branch::non_finite);
            REQUIRE(trace.first_non_finite);
            CHECK(key_at(trace, *trace.first_non_finite) == "EE");
            CHECK(std::isnan(trace.result));
            CHECK(trace.grey == 0);
        }
    }
}

TEST_CASE("a delta of -inf is not a miss", "[non-finite]") {
    // |E|² = inf while C stays finite: delta = C² - inf·(|S|² - r²) = -inf,
    // which `delta <= 0` alone would take for a miss.
    const Scene scene = scene_with(1e200, {5, 0, 0}, 1, {1.5, 1, 1}, 1);
    const PixelTrace trace = trace_pixel(scene, 8, 3, 4);
    REQUIRE(trace.steps.size() >= 5);
    CHECK(key_at(trace, 4) == "delta");
    CHECK(std::get<double>(trace.steps[4].value) == -std::numeric_limits<double>::infinity());
    CHECK(trace.branch == Branch::non_finite);
}

TEST_CASE("a centre at 1e154 is accepted and its pixels are non-finite from delta on", "[non-finite]") {
    // |S|² = 1e308 is still finite; C² and |E|²·(|S|² - r²) are not.
    const Scene scene = scene_with(2, {0, 0, 1e154}, 1.1, {1.5, 1, 1}, 1);
    const PixelTrace trace = trace_pixel(scene, 8, 3, 4);
    CHECK(trace.branch == Branch::non_finite);
    REQUIRE(trace.first_non_finite);
    CHECK(key_at(trace, *trace.first_non_finite) == "delta");
}

TEST_CASE("a light far beyond the double range overflows |K|² while D stays finite", "[non-finite]") {
    // K ~ 1e160: |K|² = inf, D = N·K ~ 1e160 is finite, and I·D / (r·√inf)
    // would be a plain 0 ("lit", grey 0) if |K|² went unchecked.
    const Scene scene = scene_with(2, {0, 0, 3.2}, 1.1, {1e160, 1e160, 1e160}, 1);
    const PixelTrace trace = trace_pixel(scene, 8, 3, 4);
    REQUIRE(trace.first_non_finite);
    CHECK(key_at(trace, *trace.first_non_finite) == "KK");
    for (const Step& step : trace.steps)
        if (step.key == Key::D) CHECK(std::isfinite(std::get<double>(step.value)));
    CHECK(trace.branch == Branch::non_finite);
    const ArticleWorld<double> world = article_world(scene);
    std::vector<std::uint8_t> row(8);
    CHECK(render_row(world, 8, 3, row.data()).branches[static_cast<int>(Branch::non_finite)] > 0);
}

TEST_CASE("an intensity that overflows is non-finite, not lit", "[non-finite]") {
    // Every step is finite, but I·D overflows (D = 1.505... at this pixel).
    const Scene scene = scene_with(2, {0, 0, 3.2}, 1.1, {1.5, 1, 1}, std::numeric_limits<double>::max());
    const PixelTrace trace = trace_pixel(scene, 8, 3, 4);
    CHECK_FALSE(trace.first_non_finite);
    CHECK(trace.result == std::numeric_limits<double>::infinity());
    CHECK(trace.branch == Branch::non_finite);
}

TEST_CASE("the branch is non-finite exactly when a step or the result is", "[non-finite]") {
    // Scenes whose numbers span the double range, so that every step can be
    // the first to overflow; the pixels of each are traced and rendered.
    std::mt19937_64 random(20261129);
    std::uniform_real_distribution<double> exponent(-160, 160), unit(-1, 1);
    const auto big = [&] { return std::ldexp(unit(random), static_cast<int>(exponent(random) * 3.3)); };
    int non_finite = 0, numeric = 0;
    for (int n = 0; n < 400; ++n) {
        const double z_E = std::fabs(big()) + 1e-300;
        const Vec3d S{big(), big(), std::fabs(big()) + 1};
        const double r = std::fabs(big()) * 1e-3 + 1e-300;
        Scene scene = scene_with(z_E, S, r, {big(), big(), big()}, std::fabs(big()));
        const double outside = length_squared(S) - r * r;
        if (!(outside > 0) || !std::isfinite(outside)) continue;  // the loader refuses these
        const int w = 5;
        const ArticleWorld<double> world = article_world(scene);
        for (int i = 0; i < w; ++i) {
            std::vector<std::uint8_t> row(w);
            const RowCounts counts = render_row(world, w, i, row.data());
            int row_non_finite = 0, first = -1;
            for (int j = 0; j < w; ++j) {
                const PixelTrace trace = trace_pixel(scene, w, i, j);
                INFO("scene " << n << ", pixel (" << i << ", " << j << ")");
                CHECK((trace.branch == Branch::non_finite) == !all_finite(trace));
                CHECK(row[j] == trace.grey);
                if (trace.branch == Branch::non_finite) {
                    ++row_non_finite;
                    if (first < 0) first = j;
                }
            }
            CHECK(counts.branches[static_cast<int>(Branch::non_finite)] == row_non_finite);
            CHECK(counts.first_non_finite_j == first);
            non_finite += row_non_finite;
            numeric += w - row_non_finite;
        }
    }
    // The scenes must exercise both sides of the property.
    CHECK(non_finite > 100);
    CHECK(numeric > 100);
}

namespace {

// Every step that decides something in a general scene: the objects' tests,
// the hit, and each light's K, |K|^2 and D (and the shadow tests' values).
bool decides(Key key) {
    switch (key) {
        case Key::E: case Key::EE: case Key::SS: case Key::C: case Key::delta: case Key::t: case Key::t_far:
        case Key::NE: case Key::t_plane: case Key::t_hit: case Key::P: case Key::N: case Key::N_plane:
        case Key::K: case Key::KK: case Key::D: case Key::b_s: case Key::c_s: case Key::delta_s: case Key::NK:
            return true;
        default:
            return false;
    }
}

bool finite_step(const Step& step) {
    if (const double* v = std::get_if<double>(&step.value)) return std::isfinite(*v);
    if (const Vec3d* v = std::get_if<Vec3d>(&step.value))
        return std::isfinite(v->x) && std::isfinite(v->y) && std::isfinite(v->z);
    return true;
}

bool finite_result(const PixelTrace& trace) {
    if (trace.result_rgb)
        return std::isfinite(trace.result_rgb->x) && std::isfinite(trace.result_rgb->y) &&
               std::isfinite(trace.result_rgb->z);
    return std::isfinite(trace.result);
}

}  // namespace

TEST_CASE("general scenes: non-finite exactly when a deciding value or the result is not finite",
          "[non-finite][effects]") {
    std::mt19937_64 random(20261129);
    std::uniform_real_distribution<double> exponent(-300, 300), unit(-1, 1), positive(0.1, 1);
    auto big = [&] { return (unit(random) < 0 ? -1 : 1) * std::pow(10.0, exponent(random) * positive(random)); };
    auto point = [&] { return Vec3d{big(), big(), big()}; };
    int non_finite = 0, decided = 0;
    for (int n = 0; n < 300; ++n) {
        Scene scene;
        scene.z_E = std::abs(big());
        scene.shadows = n % 2 == 0;
        scene.spheres = {Sphere{point(), std::abs(big())}, Sphere{point(), std::abs(big())}};
        scene.planes = {Plane{point(), {unit(random), unit(random), unit(random) + 2}}};
        scene.lights = {Light{point(), std::abs(big())}, Light{point(), 1}};
        scene.materials = {Material{0.1, 0.8, 0.5, 1 + n % 50, {1, 0.5, 0.25}}};
        scene.spheres[0].material = 0;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                const PixelTrace trace = trace_pixel(scene, 4, i, j);
                bool all_deciding_finite = finite_result(trace);
                for (const Step& step : trace.steps)
                    if (decides(step.key) && !finite_step(step)) all_deciding_finite = false;
                INFO("scene " << n << ", pixel (" << i << ", " << j << "), branch " << branch_name(trace.branch));
                CHECK((trace.branch == Branch::non_finite) == !all_deciding_finite);
                (trace.branch == Branch::non_finite ? non_finite : decided) += 1;
            }
        }
    }
    CHECK(non_finite > 100);
    CHECK(decided > 1000);
}
