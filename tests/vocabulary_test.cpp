#include <catch2/catch.hpp>

#include <filesystem>
#include <iterator>
#include <fstream>
#include <set>
#include <sstream>

#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/vocabulary.hpp"
#include "util/errors.hpp"

using namespace promyk;

TEST_CASE("the built-in vocabulary is lessons/vocabulary.json", "[vocabulary]") {
    std::ifstream file(PROMYK_SOURCE_DIR "/lessons/vocabulary.json");
    REQUIRE(file);
    std::stringstream text;
    text << file.rdbuf();
    const Vocabulary from_file = parse_vocabulary(text.str(), "lessons/vocabulary.json");
    REQUIRE(from_file.keys.size() == builtin_vocabulary().keys.size());
    for (std::size_t k = 0; k < from_file.keys.size(); ++k)
        CHECK(from_file.keys[k].key == builtin_vocabulary().keys[k].key);
}

TEST_CASE("the vocabulary defines every key the tracer knows, and every branch", "[vocabulary]") {
    const Vocabulary& vocabulary = builtin_vocabulary();
    for (const std::string_view key : key_names) {
        INFO("key " << key);
        const VocabularyEntry* entry = vocabulary.find(key);
        REQUIRE(entry != nullptr);
        CHECK_FALSE(entry->symbol.empty());
        CHECK_FALSE(entry->pl.empty());
        CHECK_FALSE(entry->en.empty());
        CHECK(std::set<std::string>{"scalar", "point", "vector", "word", "intensity", "colour"}.count(entry->kind) == 1);
    }
    for (const Branch branch : {Branch::miss, Branch::dark, Branch::lit, Branch::non_finite, Branch::shadowed})
        CHECK(vocabulary.find_branch(branch_name(branch)) != nullptr);
    CHECK(vocabulary.find("I_P") != nullptr);  // the result
}

// A number for "scalar", a point or vector for "point" and "vector", a word
// for "word", and for "intensity" a grey level or an [r, g, b].
bool kind_matches(const std::string& kind, const StepValue& value) {
    if (kind == "scalar") return std::holds_alternative<double>(value);
    if (kind == "point" || kind == "vector") return std::holds_alternative<Vec3d>(value);
    if (kind == "word") return std::holds_alternative<std::string>(value);
    return kind == "intensity" && !std::holds_alternative<std::string>(value);
}

TEST_CASE("the tracer emits only vocabulary keys, with values of the vocabulary's kind", "[vocabulary]") {
    const Vocabulary& vocabulary = builtin_vocabulary();
    // Every example scene, and the cases no example scene has: an eye inside
    // a sphere (t_far, flipped inside), a plane seen from its back, a sphere
    // behind the eye, and a blocker lit from inside its own sphere (s_own);
    // each with every formula (their own keys: c_0, q, delta_g, ...).
    std::vector<std::pair<Scene, int>> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes"))
        if (entry.path().extension() == ".json" && entry.path().string().find(".schema.") == std::string::npos)
            scenes.emplace_back(load_scene_file(entry.path().string()), 16);
    REQUIRE(scenes.size() >= 8);
    Scene inside;
    inside.spheres = {Sphere{{0, 0, 0}, 2}};
    inside.lights = {Light{{0.5, 0.5, 0.5}, 1}, Light{{0, 0, 9}, 1}};
    inside.shadows = true;
    scenes.emplace_back(inside, 8);
    Scene back;
    back.planes = {Plane{{0, 0, 3}, {0, 0, 1}}};
    back.lights = {Light{{0, 0, 1}, 1}};
    scenes.emplace_back(back, 4);
    // Phong's squarings up to RV^8192 need n >= 8192.
    Scene shiny = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/phong.json");
    shiny.materials[0].exponent = 10000;
    scenes.emplace_back(shiny, 8);
    Scene behind = article_scene();
    behind.spheres[0].S.z = -3.2;
    scenes.emplace_back(behind, 8);
    std::set<std::string> seen;
    for (const auto& [scene, w] : scenes) {
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                // Every formula with one sample; the article's also with 4 (sample_u, I_s, ...).
                constexpr int formulas = static_cast<int>(std::size(all_formulas));
                for (int run = 0; run <= formulas; ++run) {
                    const bool sampled = run == formulas;
                    const Formula formula = sampled ? Formula::article : all_formulas[run];
                    for (const Step& step : trace_pixel(scene, w, i, j, RealType::double_, formula, sampled ? 4 : 1).steps) {
                        const std::string key(key_name(step.key));
                        const VocabularyEntry* entry = vocabulary.find(key);
                        INFO("scene " << scene.name << ", formula " << formula_name(formula) << ", key " << key);
                        REQUIRE(entry != nullptr);
                        CHECK(kind_matches(entry->kind, step.value));
                        seen.insert(key);
                    }
                }
            }
        }
    }
    for (const std::string_view key : key_names) {
        INFO("no scene's trace has " << key);
        CHECK(seen.count(std::string(key)) == 1);
    }
}

TEST_CASE("a malformed vocabulary is reported with its pointer", "[vocabulary]") {
    CHECK_THROWS_AS(parse_vocabulary("{", "v.json"), InputError);
    try {
        parse_vocabulary(R"({"keys": [{"key": "E"}]})", "v.json");
        FAIL("no error");
    } catch (const InputError& error) {
        CHECK(error.file == "v.json");
        CHECK(error.where == "/keys/0/kind");
    }
}
