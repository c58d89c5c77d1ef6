// Each step's formula with the pixel's numbers put in (trace/formula_numbers.hpp),
// which the web page typesets under the formula: the numbers are the ones in
// scope (the pane's i, j, w; the tested object's S and r inside its block,
// the hit object's after; the steps done so far), in the language's form.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/formula_numbers.hpp"
#include "trace/number_text.hpp"
#include "trace/trace_text.hpp"

using namespace promyk;

namespace {

// The numbers of the first step with `key` at or after `from` (its index out).
std::string numbers_of(const PixelTrace& trace, const std::vector<std::string>& numbers, const std::string& key,
                       std::size_t from = 0, std::size_t* index = nullptr) {
    for (std::size_t k = from; k < trace.steps.size(); ++k)
        if (key_name(trace.steps[k].key) == key) {
            if (index) *index = k;
            return numbers[k];
        }
    FAIL("no step " << key);
    return "";
}

std::string shown(const PixelTrace& trace, const std::string& key, Language language) {
    for (const Step& step : trace.steps)
        if (key_name(step.key) == key)
            return trace_step_value_text(step, builtin_vocabulary(), key, language, trace.header.real, 4);
    return "";
}

}  // namespace

TEST_CASE("formulas with numbers put in: the article's lit pixel", "[trace][formula_numbers]") {
    const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    const std::vector<std::string> numbers = formulas_with_numbers(trace, builtin_vocabulary(), Language::en, 4);
    REQUIRE(numbers.size() == trace.steps.size());
    // E from the pane: i = 3, j = 4, w = 8, z_E = 2.
    const std::string e = numbers_of(trace, numbers, "E");
    CHECK(e.find("2\\cdot \\text{4}+1}{\\text{8}}") != std::string::npos);
    CHECK(e.find("2\\cdot \\text{3}+1}{\\text{8}}") != std::string::npos);
    CHECK(e.find("\\text{2}\\right)") != std::string::npos);
    // C = x_E x_S + y_E y_S + z_E z_S: the components, each product dotted.
    CHECK(numbers_of(trace, numbers, "C") ==
          " \\text{0.125} \\cdot \\text{0} + \\text{0.125} \\cdot \\text{0} + \\text{2} \\cdot \\text{3.2}");
    // t = (C − √(Δ/4)) / |E|²: C, Δ/4 and |E|² as the steps before found them.
    const std::string t = numbers_of(trace, numbers, "t");
    CHECK(t.find("\\text{" + shown(trace, "C", Language::en) + "}") != std::string::npos);
    CHECK(t.find("\\sqrt{\\text{" + shown(trace, "delta", Language::en) + "}}") != std::string::npos);
    CHECK(t.find("{\\text{" + shown(trace, "EE", Language::en) + "}}") != std::string::npos);
    // N = P − S: the point P (bracketed) and S.
    CHECK(numbers_of(trace, numbers, "N") == " \\text{" + shown(trace, "P", Language::en) + "} - \\text{(0, 0, 3.2)}");
    // Negative numbers are parenthesised: D = x_N x_K + … with z_N < 0.
    CHECK(numbers_of(trace, numbers, "D").find("\\left(\\text{\xE2\x88\x92" "1.084}\\right)") != std::string::npos);
}

TEST_CASE("formulas with numbers put in: Polish numbers", "[trace][formula_numbers]") {
    const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    const std::vector<std::string> numbers = formulas_with_numbers(trace, builtin_vocabulary(), Language::pl, 4);
    CHECK(numbers_of(trace, numbers, "C") ==
          " \\text{0,125} \\cdot \\text{0} + \\text{0,125} \\cdot \\text{0} + \\text{2} \\cdot \\text{3,2}");
    CHECK(numbers_of(trace, numbers, "N").find("\\text{(0; 0; 3,2)}") != std::string::npos);
}

TEST_CASE("formulas with numbers put in: each object's own values, then the hit object's", "[trace][formula_numbers]") {
    const Scene scene = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/everything.json");
    // Find a pixel whose nearest hit is sphere 1 (tested between spheres 0 and 2).
    bool found = false;
    for (int i = 0; i < 16 && !found; ++i)
        for (int j = 0; j < 16 && !found; ++j) {
            const PixelTrace trace = trace_pixel(scene, 16, i, j);
            if (trace.hit_object != "sphere 1") continue;
            found = true;
            const std::vector<std::string> numbers = formulas_with_numbers(trace, builtin_vocabulary(), Language::en, 4);
            // Inside each sphere's block, SS = x_S² + … uses that sphere's S.
            std::size_t at = 0;
            const char* centres[3][3] = {{"\\left(\\text{\xE2\x88\x92" "0.6}\\right)^2", "\\left(\\text{\xE2\x88\x92" "0.3}\\right)^2", "\\text{3.4}^2"},
                                         {"\\text{0.9}^2", "\\text{0.1}^2", "\\text{4.2}^2"},
                                         {"\\text{0.2}^2", "\\left(\\text{\xE2\x88\x92" "0.8}\\right)^2", "\\text{2.6}^2"}};
            for (int sphere = 0; sphere < 3; ++sphere) {
                const std::string ss = numbers_of(trace, numbers, "SS", at, &at);
                ++at;
                INFO("sphere " << sphere << ": " << ss);
                for (const char* centre : centres[sphere]) CHECK(ss.find(centre) != std::string::npos);
            }
            // After the tests, N = P − S is the hit sphere's (1), not the last tested (2).
            const std::string n = numbers_of(trace, numbers, "N");
            INFO(n);
            CHECK(n.find("\\text{(0.9, 0.1, 4.2)}") != std::string::npos);
            // No number for a minimum over a set.
            CHECK(numbers_of(trace, numbers, "t_hit").empty());
        }
    REQUIRE(found);
}

TEST_CASE("formulas with numbers put in: no pane numbers for a sample's moved ray", "[trace][formula_numbers]") {
    const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4, RealType::double_, Formula::article, 4);
    const std::vector<std::string> numbers = formulas_with_numbers(trace, builtin_vocabulary(), Language::en, 4);
    int samples = 0;
    for (std::size_t k = 0; k < trace.steps.size(); ++k)
        if (trace.steps[k].key == Key::E) {
            ++samples;
            CHECK(numbers[k].empty());
        }
    CHECK(samples == 4);
    // the rest of a sample's derivation still has its numbers
    CHECK_FALSE(numbers_of(trace, numbers, "C").empty());
}

TEST_CASE("a shown number as TeX escapes TeX's specials", "[trace][formula_numbers]") {
    CHECK(tex_number("1.5") == "\\text{1.5}");
    CHECK(tex_number("(1, 2, 3)") == "\\text{(1, 2, 3)}");
    CHECK(tex_number("\xE2\x88\x92" "2") == "\\left(\\text{\xE2\x88\x92" "2}\\right)");
    CHECK(tex_number("a_b{c}\\") == "\\left(\\text{a\\_b\\{c\\}\\backslash }\\right)");
}
