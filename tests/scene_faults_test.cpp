// Every fault of a scene in one run (issue 14): in document order, at most
// max_reported_faults and a count of the rest; the hints of 'color'; the
// loader's words in Polish.
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "scene/scene_json.hpp"
#include "trace/messages.hpp"

namespace {

using promyk::Language;
using promyk::SceneErrors;

// Sets the run's language for one test and puts English back after it.
struct RunLanguage {
    explicit RunLanguage(Language language) { promyk::set_ui_language(language); }
    ~RunLanguage() { promyk::set_ui_language(Language::en); }
};

std::optional<SceneErrors> errors_of(const std::string& text) {
    try {
        promyk::load_scene_text(text, "t.json");
    } catch (const SceneErrors& errors) {
        return errors;
    }
    return std::nullopt;
}

std::vector<std::string> wheres(const SceneErrors& errors) {
    std::vector<std::string> out;
    for (const promyk::SceneFault& fault : errors.faults) out.push_back(fault.where);
    return out;
}

// A scene of `n` spheres, each with a negative radius.
std::string spheres_with_bad_radius(int n) {
    std::string spheres;
    for (int k = 0; k < n; ++k) spheres += (k == 0 ? "" : ", ") + std::string(R"({"S": [0, 0, 3], "r": -1})");
    return R"({"spheres": [)" + spheres + R"(], "lights": [{"L": [1, 1, 1]}]})";
}

std::string hint_for(const std::string& text) {
    const auto errors = errors_of(text);
    REQUIRE(errors);
    REQUIRE(errors->faults.size() == 1);
    return errors->faults.front().what;
}

}  // namespace

TEST_CASE("a scene with three mistakes reports all three, in document order", "[scene][faults]") {
    const RunLanguage english(Language::en);
    const auto errors =
        errors_of(R"({"z_E": -1, "spheres": [{"S": [0, 0, 3], "r": -1}], "lights": [{"L": [1, 1, 1], "I": -2}]})");
    REQUIRE(errors);
    CHECK(wheres(*errors) == std::vector<std::string>{"/z_E", "/spheres/0/r", "/lights/0/I"});
    CHECK(errors->more == 0);
    // The InputError it is: the first fault.
    CHECK(errors->where == "/z_E");
    CHECK_THAT(errors->what(), Catch::Matchers::Contains("z_E (the pane's distance from the eye) must be > 0"));
    // The same faults written in another order are reported in that order.
    const auto reordered =
        errors_of(R"({"lights": [{"I": -2, "L": [1, 1, 1]}], "spheres": [{"r": -1, "S": [0, 0, 3]}], "z_E": -1})");
    REQUIRE(reordered);
    CHECK(wheres(*reordered) == std::vector<std::string>{"/lights/0/I", "/spheres/0/r", "/z_E"});
}

TEST_CASE("at most 20 faults are reported, then how many more", "[scene][faults]") {
    const RunLanguage english(Language::en);
    for (int n = 1; n <= 45; n += (n < 25 ? 1 : 10)) {
        INFO("spheres: " << n);
        const auto errors = errors_of(spheres_with_bad_radius(n));
        REQUIRE(errors);
        const std::size_t shown = std::min<std::size_t>(static_cast<std::size_t>(n), promyk::max_reported_faults);
        REQUIRE(errors->faults.size() == shown);
        CHECK(errors->more == static_cast<std::size_t>(n) - shown);
        for (std::size_t k = 0; k < shown; ++k) CHECK(errors->faults[k].where == "/spheres/" + std::to_string(k) + "/r");
    }
    const auto errors = errors_of(spheres_with_bad_radius(25));
    REQUIRE(errors);
    CHECK(errors->more == 5);
    CHECK(errors->counted);
    // A file of thousands of faults is read up to the max_collected_faults-th.
    const auto many = errors_of(spheres_with_bad_radius(3000));
    REQUIRE(many);
    CHECK(many->faults.size() == promyk::max_reported_faults);
    CHECK(many->more == promyk::max_collected_faults - promyk::max_reported_faults);
    CHECK(!many->counted);
    CHECK(promyk::ui_message("scene_more_faults", {{"count", "5"}}) == "and 5 more");
}

TEST_CASE("a missing key is reported where its object ends, unknown keys where they stand", "[scene][faults]") {
    const RunLanguage english(Language::en);
    const auto errors = errors_of(R"({"spheres": [{"x": 1, "r": -1, "y": 2}], "lights": [{"L": [1, 1, 1]}], "q": 1})");
    REQUIRE(errors);
    CHECK(wheres(*errors) ==
          std::vector<std::string>{"/spheres/0/x", "/spheres/0/r", "/spheres/0/y", "/spheres/0/S", "/q"});
    // A missing "lights" comes last: the end of the scene.
    const auto no_lights = errors_of(R"({"spheres": [{"S": [0, 0, 3], "r": -1}], "z_E": 0})");
    REQUIRE(no_lights);
    CHECK(wheres(*no_lights) == std::vector<std::string>{"/spheres/0/r", "/z_E", "/lights"});
}

TEST_CASE("'color' says the right thing in a light, a material and anywhere else", "[scene][faults]") {
    const RunLanguage english(Language::en);
    const std::string sphere = R"({"S": [0, 0, 3], "r": 1})";
    const std::string light = R"({"L": [1, 1, 1]})";
    // Where a colour belongs: the key meant.
    CHECK(hint_for(R"({"spheres": [)" + sphere + R"(], "lights": [{"L": [1, 1, 1], "color": [1, 0, 0]}]})") ==
          "unknown key 'color'; did you mean 'colour'?");
    CHECK(hint_for(R"({"materials": [{"color": [1, 0, 0]}], "spheres": [)" + sphere + R"(], "lights": [)" + light +
                   "]}") == "unknown key 'color'; did you mean 'colour'?");
    // At the top level a colour is the background.
    CHECK(hint_for(R"({"color": 0.2, "spheres": [)" + sphere + R"(], "lights": [)" + light + "]}") ==
          "unknown key 'color'; did you mean 'background'?");
    // In a sphere or a plane no colour belongs: not "did you mean 'colour'".
    for (const std::string& object : {std::string(R"("spheres": [{"S": [0, 0, 3], "r": 1, "color": [1, 0, 0]}])"),
                                      std::string(R"("planes": [{"Q": [0, -1, 0], "n": [0, 1, 0], "color": [1, 0, 0]}])")}) {
        const std::string hint = hint_for("{" + object + R"(, "lights": [)" + light + "]}");
        CHECK_THAT(hint, Catch::Matchers::StartsWith("unknown key 'color'; promyk spells it 'colour', and 'colour' "
                                                     "belongs in a light, inside \"lights\", or in a material, inside "
                                                     "\"materials\"; a "));
        CHECK_THAT(hint, Catch::Matchers::EndsWith("names its material by index, as \"material\": 0"));
        CHECK_THAT(hint, !Catch::Matchers::Contains("did you mean"));
    }
}

TEST_CASE("the loader's faults are in the run's language", "[scene][faults]") {
    const RunLanguage polish(Language::pl);
    const auto errors = errors_of(R"({"spheres": [{"S": [0, 0, 3], "r": -1, "kolor": 1}, 5], "lights": []})");
    REQUIRE(errors);
    REQUIRE(wheres(*errors) == std::vector<std::string>{"/spheres/0/r", "/spheres/0/kolor", "/spheres/1", "/lights"});
    CHECK(errors->faults[0].what == "r (promień kuli) musi być > 0, podano -1");
    CHECK(errors->faults[1].what == "nieznany klucz 'kolor'; klucze kuli to 'S', 'r', 'material'");
    CHECK(errors->faults[2].what == R"(kula musi być obiektem {"S": [x, y, z], "r": r}, podano liczbę)");
    CHECK(errors->faults[3].what == "scena potrzebuje co najmniej jednego światła w \"lights\", nie podano żadnego");
    // Every id of the loader has both languages.
    for (const std::string& id : promyk::message_ids(Language::en))
        if (id.rfind("scene_", 0) == 0) CHECK_NOTHROW(promyk::message(Language::pl, id));
}
