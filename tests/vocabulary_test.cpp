#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>

#include "render/trace_pixel.hpp"
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
        CHECK(std::set<std::string>{"scalar", "point", "vector", "word", "intensity"}.count(entry->kind) == 1);
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
    const Scene scene = article_scene();
    std::set<std::string> seen;
    for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
            for (const Step& step : trace_pixel(scene, 16, i, j).steps) {
                const std::string key(key_name(step.key));
                const VocabularyEntry* entry = vocabulary.find(key);
                INFO("key " << key);
                REQUIRE(entry != nullptr);
                CHECK(kind_matches(entry->kind, step.value));
                seen.insert(key);
            }
        }
    }
    CHECK(seen.size() == key_names.size());  // the 16 x 16 pane has misses, dark and lit pixels
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
