// The full-image trace path (render --traces: TraceLines, trace/trace_lines.hpp)
// writes what the one-pixel path (promyk trace: trace_pixel, append_trace_json)
// writes, byte for byte, and the number writers under both write what fmt
// writes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hard_cases_support.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/digits_lost.hpp"
#include "trace/json_text.hpp"

using namespace promyk;

namespace {

// Keeps the trace lines a render hands over.
class LinesSink final : public RenderSink {
public:
    void image_rows(const std::uint8_t*, int) override {}
    void trace_lines(std::string_view lines) override { text.append(lines); }
    std::string text;
};

struct Setting {
    RealType real;
    Formula formula;
    int spp;
};

// The example scenes, and one whose name and file need escapes.
std::vector<Scene> scenes() {
    std::vector<Scene> all;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find("schema") != std::string::npos) continue;
        all.push_back(load_scene_file(path));
    }
    Scene odd = article_scene();
    odd.name = "a \"quoted\"\tname\\ with a control \x01 character";
    odd.source = "C:\\scenes\\odd.json";
    all.push_back(odd);
    return all;
}

// The selected pixels of a w x w pane traced one by one, as promyk trace
// traces them, in row order.
std::string one_by_one(const Scene& scene, int w, const PixelSelection& traced, const Setting& s) {
    std::string lines;
    for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) {
            if (!traced.contains(i, j)) continue;
            append_trace_json(lines, trace_pixel(scene, w, i, j, s.real, s.formula, s.spp));
            lines += '\n';
        }
    return lines;
}

std::string lines_rendered(const Scene& scene, int w, const PixelSelection& traced, const Setting& s) {
    LinesSink sink;
    render(scene, {w, 2, s.real, s.formula, s.spp}, traced, sink);
    return sink.text;
}

std::string fmt_text(double value) { return fmt::format("{}", value); }

std::string our_text(double value) {
    std::string out;
    json_text::append_number(out, value);
    return out;
}

}  // namespace

TEST_CASE("a render's trace lines are the one-pixel traces, byte for byte", "[trace][trace-lines]") {
    const Setting settings[] = {{RealType::double_, Formula::article, 1},
                                {RealType::double_, Formula::article, 4},
                                {RealType::float_, Formula::stable, 1},
                                {RealType::quad_, Formula::geometric, 4}};
    const int w = 5;
    int lines_compared = 0;
    for (const Scene& scene : scenes())
        for (const Setting& s : settings) {
            INFO("scene " << scene.name << ", " << real_type_name(s.real) << ", " << formula_name(s.formula)
                          << ", spp " << s.spp);
            const std::string expected = one_by_one(scene, w, PixelSelection::all(), s);
            const std::string actual = lines_rendered(scene, w, PixelSelection::all(), s);
            REQUIRE(std::count(actual.begin(), actual.end(), '\n') == w * w);
            CHECK(actual == expected);
            lines_compared += w * w;
        }
    CHECK(lines_compared == static_cast<int>(scenes().size()) * 4 * w * w);
}

TEST_CASE("the hard cases' and overflowing scenes' trace lines are the one-pixel traces",
          "[trace][trace-lines]") {
    const Setting settings[] = {{RealType::double_, Formula::article, 1}, {RealType::float_, Formula::fma, 1}};
    bool some_non_finite = false;
    for (const auto& c : hard_cases_support::hard_cases_reference().at("cases")) {
        const std::string id = c.at("id").get<std::string>();
        const Scene scene = parse_scene(c.at("scene").dump(), id);
        const int w = c.at("pixel").at("w").get<int>();
        const int i = c.at("pixel").at("i").get<int>(), j = c.at("pixel").at("j").get<int>();
        // The case's pixel and its neighbours on the pane.
        PixelSelection traced;
        traced.add_region({std::max(0, i - 1), std::max(0, j - 1), std::min(w - 1, i + 1), std::min(w - 1, j + 1)});
        for (const Setting& s : settings) {
            INFO("hard case " << id << ", " << real_type_name(s.real) << ", " << formula_name(s.formula));
            const std::string expected = one_by_one(scene, w, traced, s);
            CHECK(lines_rendered(scene, w, traced, s) == expected);
            some_non_finite = some_non_finite || expected.find("first_non_finite") != std::string::npos;
        }
    }
    // Overflows: I D infinite after the dark test, |K|^2 infinite before it.
    Scene bright = article_scene();
    bright.lights[0].I = 1e308;
    Scene far_light = article_scene();
    far_light.lights[0].L = {1e200, 1e200, 1e200};
    for (const Scene& scene : {bright, far_light})
        for (const Setting& s : settings) {
            const std::string expected = one_by_one(scene, 5, PixelSelection::all(), s);
            CHECK(lines_rendered(scene, 5, PixelSelection::all(), s) == expected);
            some_non_finite = some_non_finite || expected.find("first_non_finite") != std::string::npos;
        }
    CHECK(some_non_finite);  // the text beside a non-finite value was compared too
}

TEST_CASE("numbers are written as fmt's {} writes them, on every kind of double", "[trace][json]") {
    const double special[] = {0.0,
                              -0.0,
                              1.0,
                              0.1,
                              1e-4,
                              1e-5,
                              0.00012345678901234567,
                              1e15,
                              1e16,
                              9999999999999998.0,
                              123456789012345680.0,
                              1e21,
                              1e100,
                              1e-100,
                              5e-324,
                              2.2250738585072014e-308,
                              std::numeric_limits<double>::max(),
                              std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::denorm_min()};
    for (const double v : special) {
        CHECK(our_text(v) == fmt_text(v));
        CHECK(our_text(-v) == fmt_text(-v));
    }
    for (int e = -324; e <= 308; ++e) {  // every decimal exponent, both layouts and the switch between them
        const double v = std::pow(10.0, e);
        CHECK(our_text(v) == fmt_text(v));
        CHECK(our_text(v * 1.2345) == fmt_text(v * 1.2345));
    }
    std::mt19937_64 random(20261202);
    std::uniform_real_distribution<double> unit(-4, 4);
    int checked = 0;
    for (int k = 0; k < 200000; ++k) {
        // Any bit pattern, and numbers the size a trace holds.
        std::uint64_t bits = random();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) v = unit(random);
        const double near = unit(random) * std::pow(10.0, static_cast<int>(random() % 40) - 20);
        if (our_text(v) != fmt_text(v) || our_text(near) != fmt_text(near)) {
            FAIL_CHECK("differs: " << fmt::format("{} {}", v, near));
            break;
        }
        ++checked;
    }
    CHECK(checked == 200000);
    CHECK(our_text(std::numeric_limits<double>::infinity()) == "null");
    CHECK(our_text(std::nan("")) == "null");
}

TEST_CASE("digits lost are written as fmt's {:.1f} writes them", "[trace][json]") {
    const auto ours = [](double v) {
        std::string out;
        json_text::append_tenths(out, v);
        return out;
    };
    for (int k = -3000; k <= 3000; ++k) {
        const double v = k / 10.0;
        REQUIRE(ours(v) == fmt::format("{:.1f}", v));
    }
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> digits(-1, 40);
    for (int k = 0; k < 20000; ++k) {
        const double raw = digits(random);
        REQUIRE(ours(rounded_digits(raw)) == fmt::format("{:.1f}", rounded_digits(raw)));
        REQUIRE(ours(raw) == fmt::format("{:.1f}", raw));  // not tenths: fmt's own rounding
    }
    for (const double v : {-0.0, 0.05, 0.25, 1e15, 1e300, -1e300, 0.1 * 3}) CHECK(ours(v) == fmt::format("{:.1f}", v));
    CHECK(ours(std::numeric_limits<double>::infinity()) == "inf");
}
