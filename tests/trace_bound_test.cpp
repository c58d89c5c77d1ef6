// The bound on a trace's size (issue 19): one pixel's trace estimated from
// the scene's counts, before tracing, against the size of the real trace.
#include <catch2/catch.hpp>

#include <string>

#include <fmt/format.h>

#include "render/trace_pixel.hpp"
#include "render/trace_size.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/trace_text.hpp"
#include "trace/vocabulary.hpp"

using namespace promyk;

namespace {

// Sphere 0 fills the pane's middle; the other spheres are large and behind
// the eye, where the eye's rays and the shadow rays' lines meet them (every
// root computed); the planes lie behind the eye, tilted; every light is
// between the eye and sphere 0; the numbers have 16 or 17 digits. So the
// middle pixel hits sphere 0, faces every light and (with shadows) tests
// every object on the way to each, each test on its longest path: the
// model's worst case.
Scene many_scene(int spheres, int planes, int lights, bool shadows, bool phong = false) {
    std::string text = fmt::format(R"({{"name": "many", "shadows": {}, "spheres": [{{"S": [0.1, 0.2, 6.3], "r": 3.1{}}})",
                                   shadows ? "true" : "false", phong ? R"(, "material": 0)" : "");
    for (int k = 1; k < spheres; ++k)
        text += fmt::format(R"(, {{"S": [{}, {}, -60.3], "r": 30.7}})", (k % 40) * 0.0137, (k / 40) * 0.0191);
    text += R"(], "planes": [)";
    for (int k = 0; k < planes; ++k)
        text += fmt::format(R"({}{{"Q": [0, 0, {}], "n": [0.01, 0.03, 1]}})", k ? ", " : "", -30.3 - k);
    text += R"(], "lights": [)";
    for (int k = 0; k < lights; ++k)
        text += fmt::format(R"({}{{"L": [{}, {}, 1.1], "I": 0.0011}})", k ? ", " : "", (k % 40) / 41.3 - 0.5,
                            (k / 40) / 43.7 - 0.5);
    text += "]";
    if (phong) text += R"(, "materials": [{"ambient": 0.1, "diffuse": 0.5, "specular": 0.5, "exponent": 8, "colour": [0.9, 0.3, 0.2]}])";
    return parse_scene(text + "}", "many.json");
}

std::size_t json_size(const PixelTrace& trace) {
    std::string line;
    append_trace_json(line, trace);
    return line.size() + 1;
}

}  // namespace

TEST_CASE("a pixel's trace size estimated from the scene bounds the real one within the stated factor", "[trace-size]") {
    struct Case {
        int spheres, planes, lights;
        bool shadows, phong;
        RealType real;
        int spp;
    };
    const Case cases[] = {
        {1, 0, 1, true, false, RealType::double_, 1},     {2, 0, 1, false, false, RealType::double_, 1},
        {10, 0, 10, true, false, RealType::double_, 1},   {50, 5, 20, true, false, RealType::double_, 1},
        {200, 0, 5, true, false, RealType::double_, 1},   {5, 0, 200, true, false, RealType::double_, 1},
        {30, 3, 30, true, true, RealType::double_, 1},    {30, 0, 30, true, false, RealType::float_, 1},
        {30, 0, 30, true, false, RealType::quad_, 1},     {20, 2, 20, true, false, RealType::long_double, 4},
        {100, 0, 100, true, false, RealType::double_, 1}, {40, 0, 40, false, false, RealType::double_, 9},
        {5, 3, 20, true, true, RealType::quad_, 1},       {1, 0, 1, false, false, RealType::double_, 1},
    };
    for (const Case& c : cases) {
        const Scene scene = many_scene(c.spheres, c.planes, c.lights, c.shadows, c.phong);
        const PixelTrace trace = trace_pixel(scene, 8, 4, 4, c.real, Formula::article, c.spp);
        REQUIRE(trace.branch == Branch::lit);
        const double real = static_cast<double>(json_size(trace));
        const double estimate = pixel_trace_bytes(scene, c.real, c.spp);
        INFO(fmt::format("{} spheres, {} planes, {} lights, shadows {}, phong {}, {}, spp {}: real {}, estimate {}, "
                         "ratio {:.2f}",
                         c.spheres, c.planes, c.lights, c.shadows, c.phong, real_type_name(c.real), c.spp, real,
                         estimate, estimate / real));
        CHECK(estimate >= real);
        CHECK(estimate <= pixel_trace_bound_factor * real);
        // The text layout within the factor allowed for it.
        TraceTextOptions options;
        const double text = static_cast<double>(format_trace_text(trace, builtin_vocabulary(), options).size());
        CHECK(text <= text_trace_factor * estimate);
    }
}

TEST_CASE("a pixel's trace size estimate grows as objects times lights, without tracing", "[trace-size]") {
    // 1,000 spheres and 1,000 lights with shadows: a million shadow tests,
    // hundreds of MB (the issue measured 583 MB of JSON), estimated at once.
    const Scene scene = many_scene(1000, 0, 1000, true);
    const double estimate = pixel_trace_bytes(scene, RealType::double_, 1);
    CHECK(estimate > 330e6);  // measured: 0.33 kB a shadow test
    CHECK(estimate < 3 * 330e6);
    // Four samples: four times the samples' part.
    CHECK(pixel_trace_bytes(scene, RealType::double_, 4) > 3.9 * estimate);
    // Without shadows, no shadow tests: a few MB at most.
    CHECK(pixel_trace_bytes(many_scene(1000, 0, 1000, false), RealType::double_, 1) < 5e6);
}

TEST_CASE("the article's own pixel is estimated within the factor too", "[trace-size]") {
    const Scene scene = article_scene();
    const PixelTrace trace = trace_pixel(scene, 8, 3, 4);
    const double real = static_cast<double>(json_size(trace));
    const double estimate = pixel_trace_bytes(scene, RealType::double_, 1);
    INFO(fmt::format("real {}, estimate {}", real, estimate));
    CHECK(estimate >= real);
    CHECK(estimate <= pixel_trace_bound_factor * real);
}
