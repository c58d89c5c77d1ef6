// The extended engine against an independent high-precision reference
// (tests/reference/effects_reference.json, made by make_effects_reference.py
// with mpmath at 200 bits from docs/conventions.md, "The engine's conventions (the
// extensions)"; see tests/reference/README.md, "The extensions' reference").
//
// For every listed pixel of the example scenes in lessons/scenes/ (read with
// promyk's own load_scene_file) and of the closed-form cases (scenes written
// inline in the reference, read with parse_scene) the engine's trace must have
// - the reference's branch (miss, dark, shadowed, lit): the reference lists
//   only pixels whose every test its enclosures decide;
// - the reference's hit object ("sphere 1", "plane 0", "" for a miss);
// - a result (the grey value, or [r, g, b] in a coloured scene) equal, bit for
//   bit, to the reference's `double`: README's operations in IEEE doubles
//   (Python floats, no FMA);
// - every value inside the reference's rigorous enclosure [lo, hi] of what a
//   program performing README's operations can produce (each operation one
//   rounding), and within `error_bound` of the exact value (the enclosure's
//   largest distance from it). The exact value is read from 30 digits into a
//   long double, so the check allows 2^-60 of it on top.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/stages.hpp"
#include "render/trace_pixel.hpp"
#include "same_bits.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/keys.hpp"
#include "trace/trace.hpp"

namespace {

using json = nlohmann::json;

const std::string effects_reference_path = PROMYK_SOURCE_DIR "/tests/reference/effects_reference.json";
const std::string example_scene_dir = PROMYK_SOURCE_DIR "/lessons/scenes/";

json read_json_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return json::parse(text.str());
}

const json& effects_reference() {
    static const json reference = read_json_file(effects_reference_path);
    return reference;
}

double text_double(const json& text) {
    const std::string s = text.get<std::string>();
    char* end = nullptr;
    const double value = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) throw std::runtime_error("not a number: " + s);
    return value;
}

long double text_long_double(const json& text) {
    const std::string s = text.get<std::string>();
    char* end = nullptr;
    const long double value = std::strtold(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) throw std::runtime_error("not a number: " + s);
    return value;
}

using promyk::testing::same_bits;
using promyk::testing::show_digits;

// The reference's value of one channel (a grey scene's result is a number,
// a coloured scene's [r, g, b]).
const json& channel(const json& value, bool coloured, std::size_t k) { return coloured ? value.at(k) : value; }

// Traces one listed pixel and checks it against its record.
void check_pixel(const promyk::Scene& scene, const json& pixel, bool coloured, const std::string& where) {
    const int w = pixel.at("w").get<int>();
    const int i = pixel.at("i").get<int>();
    const int j = pixel.at("j").get<int>();
    INFO(where << ": pixel (" << i << ", " << j << ") of w = " << w);
    const promyk::PixelTrace trace = promyk::trace_pixel(scene, w, i, j);

    CHECK(std::string(promyk::branch_name(trace.branch)) == pixel.at("branch").get<std::string>());
    CHECK(trace.hit_object == pixel.at("hit_object").get<std::string>());

    std::vector<double> got;
    if (coloured) {
        REQUIRE(trace.result_rgb.has_value());
        got = {trace.result_rgb->x, trace.result_rgb->y, trace.result_rgb->z};
    } else {
        got = {trace.result};
        // A grey scene is computed in one channel; if the trace also gives
        // [r, g, b], it must be that value three times.
        if (trace.result_rgb.has_value()) {
            CHECK(same_bits(trace.result_rgb->x, trace.result));
            CHECK(same_bits(trace.result_rgb->y, trace.result));
            CHECK(same_bits(trace.result_rgb->z, trace.result));
        }
    }
    const json& result = pixel.at("result");
    for (std::size_t k = 0; k < got.size(); ++k) {
        const double value = got[k];
        const double expected = text_double(channel(result.at("double"), coloured, k));
        const double lo = text_double(channel(result.at("lo"), coloured, k));
        const double hi = text_double(channel(result.at("hi"), coloured, k));
        const long double exact = text_long_double(channel(result.at("exact"), coloured, k));
        const long double bound = text_long_double(channel(result.at("error_bound"), coloured, k));
        const long double error = std::fabs(static_cast<long double>(value) - exact);
        INFO("channel " << k << ": engine " << show_digits(value) << ", reference double " << show_digits(expected)
                        << ", exact " << show_digits(exact) << ", enclosure [" << show_digits(lo) << ", "
                        << show_digits(hi) << "], error " << show_digits(error) << " (bound " << show_digits(bound)
                        << ")");
        CHECK(same_bits(value, expected));
        CHECK(lo <= value);
        CHECK(value <= hi);
        CHECK(error <= bound + std::fabs(exact) * 0x1p-60L);
    }
}

}  // namespace

TEST_CASE("Effects reference: every example scene but the article's is covered", "[reference][effects]") {
    std::set<std::string> listed;
    for (const json& block : effects_reference().at("scenes")) listed.insert(block.at("file").get<std::string>());

    // A scene of the article's shape (one sphere, one light, no effect: the
    // article's own, and far_sphere.json, the article's world far away, for
    // the lesson on precision) runs the article's computation, which the
    // article's reference and the hard cases check; every other scene is here.
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(example_scene_dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".json" && name != "scene.schema.json" &&
            !promyk::plan_stages(promyk::load_scene_file(entry.path().string())).article)
            files.insert(name);
    }
    CHECK(listed == files);
}

TEST_CASE("Effects reference: the example scenes' pixels", "[reference][effects]") {
    std::size_t pixels = 0;
    for (const json& block : effects_reference().at("scenes")) {
        const std::string file = block.at("file").get<std::string>();
        const promyk::Scene scene = promyk::load_scene_file(example_scene_dir + file);
        const bool coloured = block.at("coloured").get<bool>();
        CHECK(promyk::is_coloured(scene) == coloured);
        REQUIRE_FALSE(block.at("pixels").empty());
        for (const json& pixel : block.at("pixels")) {
            check_pixel(scene, pixel, coloured, file);
            ++pixels;
        }
    }
    CHECK(pixels >= 60);
}

TEST_CASE("Effects reference: the closed-form cases", "[reference][effects]") {
    const json& cases = effects_reference().at("closed_form");
    REQUIRE(cases.size() >= 5);
    for (const json& entry : cases) {
        const std::string name = entry.at("name").get<std::string>();
        const promyk::Scene scene = promyk::parse_scene(entry.at("scene").dump(), "effects_reference.json: " + name);
        const bool coloured = entry.at("coloured").get<bool>();
        CHECK(promyk::is_coloured(scene) == coloured);
        const json& pixel = entry.at("pixel");
        // The closed form is what the exact value is (the generator checks
        // that); the engine is checked against the record as for any pixel.
        CHECK(pixel.at("branch") == entry.at("closed_form").at("branch"));
        check_pixel(scene, pixel, coloured, name);
    }
}
