// Scene files: the article's scene file, defaults, every rejection (with the
// JSON pointer or line/column it names), round trips, file errors.

#include <cerrno>
#include <chrono>
#include <ctime>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <thread>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "terminal_control.hpp"

#include "temp_dir.hpp"

#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "util/errors.hpp"

namespace {

using promyk::InputError;
using promyk::parse_scene;
using promyk::Scene;

const std::string article_path = std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes/article.json";

std::uint64_t bits(double value) {
    std::uint64_t out;
    std::memcpy(&out, &value, sizeof out);
    return out;
}

// Exact equality, down to the sign of zero.
void check_same_number(double a, double b) {
    INFO(a << " vs " << b);
    CHECK(bits(a) == bits(b));
}

void check_same_vector(const promyk::Vec3d& a, const promyk::Vec3d& b) {
    check_same_number(a.x, b.x);
    check_same_number(a.y, b.y);
    check_same_number(a.z, b.z);
}

// Every field of the model (not `source`), down to the bits.
void check_same_scene(const Scene& a, const Scene& b) {
    CHECK(a.name == b.name);
    check_same_number(a.z_E, b.z_E);
    check_same_vector(a.background, b.background);
    CHECK(a.shadows == b.shadows);
    REQUIRE(a.spheres.size() == b.spheres.size());
    for (std::size_t k = 0; k < a.spheres.size(); ++k) {
        check_same_vector(a.spheres[k].S, b.spheres[k].S);
        check_same_number(a.spheres[k].r, b.spheres[k].r);
        CHECK(a.spheres[k].material == b.spheres[k].material);
    }
    REQUIRE(a.planes.size() == b.planes.size());
    for (std::size_t k = 0; k < a.planes.size(); ++k) {
        check_same_vector(a.planes[k].Q, b.planes[k].Q);
        check_same_vector(a.planes[k].n, b.planes[k].n);
        CHECK(a.planes[k].material == b.planes[k].material);
    }
    REQUIRE(a.lights.size() == b.lights.size());
    for (std::size_t k = 0; k < a.lights.size(); ++k) {
        check_same_vector(a.lights[k].L, b.lights[k].L);
        check_same_number(a.lights[k].I, b.lights[k].I);
        check_same_vector(a.lights[k].colour, b.lights[k].colour);
    }
    REQUIRE(a.materials.size() == b.materials.size());
    for (std::size_t k = 0; k < a.materials.size(); ++k) {
        check_same_number(a.materials[k].ambient, b.materials[k].ambient);
        check_same_number(a.materials[k].diffuse, b.materials[k].diffuse);
        check_same_number(a.materials[k].specular, b.materials[k].specular);
        CHECK(a.materials[k].exponent == b.materials[k].exponent);
        check_same_vector(a.materials[k].colour, b.materials[k].colour);
    }
}

const std::string article_sphere = R"({"S": [0, 0, 3.2], "r": 1.1})";
const std::string article_light = R"({"L": [1.5, 1, 1], "I": 1})";

// A scene text: `top` is spliced in front of the spheres and lights (end it
// with a comma), `sphere` and `light` replace the article's.
std::string scene_text(const std::string& top = "", const std::string& sphere = article_sphere,
                       const std::string& light = article_light) {
    return "{" + top + R"("spheres": [)" + sphere + R"(], "lights": [)" + light + "]}";
}

void check_rejected(const std::string& text, const std::string& where, std::initializer_list<const char*> words) {
    INFO("input: " << text);
    try {
        parse_scene(text, "test.json");
        FAIL("the scene was accepted");
    } catch (const InputError& error) {
        INFO("message: " << error.what());
        CHECK(error.file == "test.json");
        CHECK(error.where == where);
        for (const char* word : words) CHECK_THAT(error.what(), Catch::Matchers::Contains(word));
    }
}

void check_accepted(const std::string& text) {
    INFO("input: " << text);
    CHECK_NOTHROW(parse_scene(text, "test.json"));
}

}  // namespace

TEST_CASE("the article's scene file loads equal to the built-in article scene", "[scene]") {
    const Scene loaded = promyk::load_scene_file(article_path);
    const Scene article = promyk::article_scene();
    CHECK(loaded.name == "article");
    CHECK(loaded.source == article_path);
    check_same_scene(loaded, article);
    CHECK(loaded.z_E == 2);
    CHECK(loaded.background.x == 0.5);
    REQUIRE(loaded.spheres.size() == 1);
    CHECK(loaded.spheres[0].S.x == 0);
    CHECK(loaded.spheres[0].S.y == 0);
    CHECK(loaded.spheres[0].S.z == 3.2);
    CHECK(loaded.spheres[0].r == 1.1);
    REQUIRE(loaded.lights.size() == 1);
    CHECK(loaded.lights[0].L.x == 1.5);
    CHECK(loaded.lights[0].L.y == 1);
    CHECK(loaded.lights[0].L.z == 1);
    CHECK(loaded.lights[0].I == 1);
    CHECK(promyk::scene_hash(loaded) == promyk::scene_hash(article));
}

TEST_CASE("the article's scene file is exactly what scene_to_json writes", "[scene]") {
    std::ifstream file(article_path, std::ios::binary);
    REQUIRE(file);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    CHECK(text == promyk::scene_to_json(promyk::article_scene()));
}

TEST_CASE("fields left out take their documented defaults", "[scene]") {
    const Scene scene =
        parse_scene(R"({"spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 2, 3]}]})", "test.json");
    CHECK(scene.name == "untitled");
    CHECK(scene.z_E == 2);
    CHECK(scene.background == promyk::Colour{0.5, 0.5, 0.5});
    CHECK_FALSE(scene.shadows);
    CHECK(scene.planes.empty());
    CHECK(scene.materials.empty());
    CHECK(scene.source == "test.json");
    REQUIRE(scene.spheres.size() == 1);
    CHECK(scene.spheres[0].material == promyk::no_material);
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].I == 1);
    CHECK(scene.lights[0].colour == promyk::Colour{1, 1, 1});

    // A plane's material, and a material's fields.
    const Scene other = parse_scene(
        R"({"planes": [{"Q": [0, -1, 0], "n": [0, 2, 0]}], "lights": [{"L": [1, 2, 3]}], "materials": [{}]})",
        "test.json");
    CHECK(other.spheres.empty());
    REQUIRE(other.planes.size() == 1);
    CHECK(other.planes[0].material == promyk::no_material);
    CHECK(other.planes[0].n == promyk::Vec3d{0, 2, 0});  // kept as written: the engine normalises it
    REQUIRE(other.materials.size() == 1);
    CHECK(other.materials[0].ambient == 0);
    CHECK(other.materials[0].diffuse == 1);
    CHECK(other.materials[0].specular == 0);
    CHECK(other.materials[0].exponent == 10);
    CHECK(other.materials[0].colour == promyk::Colour{1, 1, 1});
}

TEST_CASE("every example scene in lessons/scenes loads, as its file says", "[scene]") {
    const std::string folder = std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes/";
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".json" || name == "scene.schema.json") continue;
        INFO(name);
        CHECK_NOTHROW(promyk::load_scene_file(entry.path().string()));
        ++loaded;
    }
    CHECK(loaded >= 8);

    const Scene everything = promyk::load_scene_file(folder + "everything.json");
    CHECK(everything.name == "everything");
    CHECK(everything.shadows);
    CHECK(everything.background == promyk::Colour{0.5, 0.6, 0.75});
    REQUIRE(everything.spheres.size() == 3);
    CHECK(everything.spheres[1].S == promyk::Vec3d{0.9, 0.1, 4.2});
    CHECK(everything.spheres[1].r == 1.0);
    CHECK(everything.spheres[2].material == 2);
    REQUIRE(everything.planes.size() == 1);
    CHECK(everything.planes[0].Q == promyk::Vec3d{0, -1.1, 0});
    CHECK(everything.planes[0].n == promyk::Vec3d{0, 1, 0});
    CHECK(everything.planes[0].material == 3);
    REQUIRE(everything.lights.size() == 2);
    CHECK(everything.lights[1].L == promyk::Vec3d{-3, 1.5, 2});
    CHECK(everything.lights[1].I == 0.4);
    CHECK(everything.lights[1].colour == promyk::Colour{0.6, 0.7, 1});
    REQUIRE(everything.materials.size() == 4);
    CHECK(everything.materials[1].ambient == 0.1);
    CHECK(everything.materials[1].diffuse == 0.7);
    CHECK(everything.materials[1].specular == 0.6);
    CHECK(everything.materials[1].exponent == 80);
    CHECK(everything.materials[1].colour == promyk::Colour{0.25, 0.45, 0.9});
    CHECK(everything.materials[2].specular == 0);  // left out: the default
    CHECK(everything.materials[2].exponent == 10);

    const Scene colour = promyk::load_scene_file(folder + "colour.json");
    CHECK(colour.background == promyk::Colour{0.55, 0.7, 0.9});
    CHECK(colour.lights.at(0).colour == promyk::Colour{1, 0.95, 0.8});
    CHECK_FALSE(colour.shadows);
}

TEST_CASE("limits that are allowed load", "[scene]") {
    check_accepted(scene_text(R"("background": 0,)"));
    check_accepted(scene_text(R"("background": 1,)"));
    check_accepted(scene_text("", article_sphere, R"({"L": [1.5, 1, 1], "I": 0})"));
    check_accepted(scene_text(R"("z_E": 1e-50,)"));  // min_scene_magnitude
    check_accepted(scene_text(R"("name": ")" + std::string(200, 'a') + R"(",)"));
    std::string polish;                                  // 200 characters, 400 bytes
    for (int k = 0; k < 200; ++k) polish += "\xC5\x9B";  // ś
    check_accepted(scene_text(R"("name": ")" + polish + R"(",)"));
    check_accepted("\xEF\xBB\xBF" + scene_text());                   // a byte order mark
    check_accepted(scene_text("", R"({"S": [0, 0, -3], "r": 1})"));  // behind the eye: not drawn, but legal
    check_accepted(scene_text(R"("background": [0, 1, 0.5],)"));
    check_accepted(scene_text(R"("background": [0, 0, 0], "shadows": false,)"));
    check_accepted(scene_text(R"("materials": [{"ambient": 0, "diffuse": 0, "specular": 1e300, "exponent": 1}],)",
                              R"({"S": [0, 0, 3.2], "r": 1.1, "material": 0})"));
    check_accepted(scene_text(R"("materials": [{"exponent": 10000}, {"exponent": 20.0}],)",
                              R"({"S": [0, 0, 3.2], "r": 1.1, "material": 1.0})"));
    check_accepted(scene_text("", article_sphere, R"({"L": [1, 1, 1], "colour": [0, 0, 1]})"));
    check_accepted(scene_text(R"("planes": [{"Q": [0, 0, 0], "n": [1e-150, 0, 0]}],)"));  // n·n = 1e-300
    check_accepted(scene_text(R"("planes": [{"Q": [0, -1, 0], "n": [0, 1e150, 0]}],)"));
}

TEST_CASE("a position or length other than 0 below 1e-50 is refused, with the field and the limit", "[scene]") {
    check_rejected(scene_text(R"("z_E": 1e-300,)"), "/z_E", {"z_E = 1e-300", "at least 1e-50", "too small"});
    check_rejected(scene_text("", R"({"S": [0, 0, 1e-200], "r": 1e-201})"), "/spheres/0/S/2",
                   {"S[2] (z) = 1e-200", "at least 1e-50"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": 9e-51})"), "/spheres/0/r", {"r = 9e-51"});
    check_rejected(scene_text("", article_sphere, R"({"L": [-1e-160, 1, 1]})"), "/lights/0/L/0",
                   {"L[0] (x) = -1e-160"});
    check_rejected(scene_text(R"("planes": [{"Q": [5e-324, -1, 0], "n": [0, 1, 0]}],)"), "/planes/0/Q/0",
                   {"Q[0] (x) = 5e-324"});
    // 0 and -0 are fine, and so is the limit itself.
    check_accepted(scene_text("", R"({"S": [0, -0.0, 1e-50], "r": 1e-50})"));
    check_accepted(scene_text("", article_sphere, R"({"L": [-1e-50, 0, 1]})"));
}

TEST_CASE("a scene that is not a JSON object is rejected", "[scene]") {
    check_rejected("", "", {"empty"});
    check_rejected(" \n\t\r\n", "", {"empty"});
    check_rejected("[1, 2]", "", {"JSON object", "array"});
    check_rejected("3", "", {"JSON object", "number"});
    check_rejected("\"article\"", "", {"JSON object", "string"});
    check_rejected("null", "", {"JSON object", "null"});
}

TEST_CASE("unknown keys are rejected, with a suggestion when one is close", "[scene]") {
    check_rejected(scene_text(R"("$schema": "x",)"), "/$schema", {"unknown key '$schema'"});
    check_rejected(scene_text(R"("comment": "x",)"), "/comment", {"unknown key 'comment'", "'name'", "'lights'"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "radius": 1.1})"), "/spheres/0/radius",
                   {"unknown key 'radius'; did you mean 'r'?"});
    check_rejected(scene_text(R"("z_e": 2,)"), "/z_e", {"unknown key 'z_e'; did you mean 'z_E'?"});
    check_rejected(scene_text(R"("nmae": "x",)"), "/nmae", {"did you mean 'name'?"});
    check_rejected(scene_text(R"("backgrund": 0.5,)"), "/backgrund", {"did you mean 'background'?"});
    check_rejected(R"({"sphere": [], "lights": []})", "/sphere", {"did you mean 'spheres'?"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "intensity": 1})"), "/lights/0/intensity",
                   {"did you mean 'I'?"});
    check_rejected(scene_text("", article_sphere, R"({"l": [1, 1, 1]})"), "/lights/0/l", {"did you mean 'L'?"});
    // A key of another object says where it belongs.
    check_rejected(scene_text(R"("r": 1,)"), "/r", {"unknown key 'r'", "belongs in a sphere"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "S": [0, 0, 1]})"), "/lights/0/S",
                   {"belongs in a sphere"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "name": "x"})"), "/spheres/0/name",
                   {"belongs at the top level"});
    // Far from every key: no suggestion, the allowed keys instead.
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "x": 1})"), "/spheres/0/x",
                   {"unknown key 'x'", "the keys of a sphere are 'S', 'r'"});
    // Pointer tokens are escaped (RFC 6901).
    check_rejected(scene_text(R"("a/b~c": 1,)"), "/a~1b~0c", {"unknown key 'a/b~c'"});
}

TEST_CASE("wrong types are rejected with the field's pointer", "[scene]") {
    check_rejected(scene_text(R"("name": 3,)"), "/name", {"name", "string", "number"});
    check_rejected(scene_text(R"("z_E": "2",)"), "/z_E", {"z_E", "number", "string"});
    check_rejected(scene_text(R"("background": true,)"), "/background", {"background", "number", "boolean"});
    check_rejected(R"({"spheres": {}, "lights": []})", "/spheres", {"array", "object"});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": 1}], "lights": null})", "/lights", {"array", "null"});
    check_rejected(scene_text("", "3"), "/spheres/0", {"sphere", "object", "number"});
    check_rejected(scene_text("", article_sphere, "[1.5, 1, 1]"), "/lights/0", {"light", "object", "array"});
    check_rejected(scene_text("", R"({"S": "0 0 3", "r": 1})"), "/spheres/0/S", {"3 numbers", "string"});
    check_rejected(scene_text("", R"({"S": {"x": 0}, "r": 1})"), "/spheres/0/S", {"3 numbers", "object"});
    check_rejected(scene_text("", R"({"S": [0, 0, "3"], "r": 1})"), "/spheres/0/S/2", {"S[2]", "number"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": null})"), "/spheres/0/r", {"r", "number", "null"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, true, 1]})"), "/lights/0/L/1", {"L[1]", "number"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "I": "1"})"), "/lights/0/I",
                   {"I", "number", "string"});
}

TEST_CASE("vectors must be exactly 3 numbers", "[scene]") {
    check_rejected(scene_text("", R"({"S": [0, 3], "r": 1})"), "/spheres/0/S", {"3 numbers", "got 2"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3, 1], "r": 1})"), "/spheres/0/S", {"3 numbers", "got 4"});
    check_rejected(scene_text("", R"({"S": [], "r": 1})"), "/spheres/0/S", {"3 numbers", "got 0"});
    check_rejected(scene_text("", article_sphere, R"({"L": [[1], 1, 1]})"), "/lights/0/L/0", {"L[0]", "number"});
}

TEST_CASE("numbers too large for a double are rejected at their pointer", "[scene]") {
    check_rejected(scene_text(R"("z_E": 1e999,)"), "/z_E", {"1e999", "not finite"});
    check_rejected(scene_text("", R"({"S": [0, 0, -1e400], "r": 1})"), "/spheres/0/S/2", {"-1e400", "not finite"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": 1e309})"), "/spheres/0/r", {"not finite"});
    check_rejected(scene_text("", article_sphere, "{\"L\": [" + std::string(400, '9') + ", 1, 1]}"), "/lights/0/L/0",
                   {"not finite"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "I": 2e308})"), "/lights/0/I", {"not finite"});
}

TEST_CASE("values out of their range are rejected", "[scene]") {
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": 0})"), "/spheres/0/r", {"radius", "> 0", "got 0"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": -1})"), "/spheres/0/r", {"> 0", "got -1"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": -0.0})"), "/spheres/0/r", {"> 0"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "I": -0.5})"), "/lights/0/I",
                   {"intensity", ">= 0", "got -0.5"});
    check_rejected(scene_text(R"("z_E": 0,)"), "/z_E", {"z_E", "> 0", "got 0"});
    check_rejected(scene_text(R"("z_E": -2,)"), "/z_E", {"> 0", "got -2"});
    check_rejected(scene_text(R"("background": -0.1,)"), "/background", {"between 0 and 1", "got -0.1"});
    check_rejected(scene_text(R"("background": 1.5,)"), "/background", {"between 0 and 1", "got 1.5"});
}

TEST_CASE("bad names are rejected", "[scene]") {
    check_rejected(scene_text(R"("name": "",)"), "/name", {"name", "empty"});
    check_rejected(scene_text(R"("name": ")" + std::string(201, 'a') + R"(",)"), "/name",
                   {"too long", "201 characters", "200"});
    check_rejected(scene_text(R"("name": "a\u0007b",)"), "/name", {"control character", "U+0007"});
    check_rejected(scene_text(R"("name": "two\nlines",)"), "/name", {"control character", "U+000A"});
    check_rejected(scene_text(R"("name": "del\u007f",)"), "/name", {"control character", "U+007F"});
    check_rejected(scene_text(R"("name": "c1\u0085",)"), "/name", {"control character", "U+0085"});
}

TEST_CASE("duplicate keys are rejected at the second occurrence", "[scene]") {
    check_rejected(scene_text(R"("z_E": 2, "z_E": 3,)"), "/z_E", {"duplicate key 'z_E'"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3], "r": 1, "r": 2})"), "/spheres/0/r", {"duplicate key 'r'"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "I": 1, "L": [1, 1, 1]})"), "/lights/0/L",
                   {"duplicate key 'L'"});
    check_rejected(R"({"spheres": [], "spheres": []})", "/spheres", {"duplicate"});
}

TEST_CASE("a scene needs at least one object and at least one light", "[scene]") {
    const Scene many = parse_scene(scene_text("", article_sphere + ", " + article_sphere + ", " + article_sphere,
                                              article_light + ", " + article_light),
                                   "test.json");
    CHECK(many.spheres.size() == 3);
    CHECK(many.lights.size() == 2);
    const Scene plane_only =
        parse_scene(R"({"planes": [{"Q": [0, -1, 0], "n": [0, 1, 0]}], "lights": [{"L": [1, 1, 1]}]})", "test.json");
    CHECK(plane_only.spheres.empty());
    CHECK(plane_only.planes.size() == 1);
    check_rejected(R"({"spheres": [], "lights": [{"L": [1, 1, 1]}]})", "/spheres",
                   {"no objects", "sphere", "plane"});
    check_rejected(R"({"spheres": [], "planes": [], "lights": [{"L": [1, 1, 1]}]})", "/spheres", {"no objects"});
    check_rejected(R"({"lights": [{"L": [1, 1, 1]}]})", "/spheres", {"no objects", "\"spheres\"", "\"planes\""});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": 1}], "lights": []})", "/lights",
                   {"at least one light", "got none"});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": 1}]})", "/lights", {"missing", "lights"});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": 1}], "planes": {}, "lights": []})", "/planes",
                   {"planes must be an array of planes", "object"});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": 1}], "materials": 1, "lights": []})", "/materials",
                   {"materials must be an array of materials", "number"});
    check_rejected(scene_text("", R"({"r": 1})"), "/spheres/0/S", {"missing", "'S'"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3]})"), "/spheres/0/r", {"missing", "'r'"});
    check_rejected(scene_text("", article_sphere, R"({"I": 1})"), "/lights/0/L", {"missing", "'L'"});
}

TEST_CASE("the eye inside or on a sphere is accepted, |S|² − r² must be finite", "[scene]") {
    // The engine sees the inside (the far root); scene check warns.
    const Scene inside = parse_scene(scene_text("", R"({"S": [0, 0, 1], "r": 2})"), "test.json");
    CHECK(inside.spheres.at(0).r == 2);
    check_accepted(scene_text("", R"({"S": [0, 0, 3.2], "r": 3.2})"));
    check_accepted(scene_text("", R"({"S": [0, 0, 1e-50], "r": 1e-50})"));  // the eye on the sphere
    check_accepted(scene_text("", R"({"S": [0, 0, 3.2], "r": 3.1999999999999997})"));
    check_rejected(scene_text("", R"({"S": [0, 0, 1e200], "r": 1})"), "/spheres/0", {"not finite", "|S|² − r²"});
    check_rejected(scene_text("", article_sphere + R"(, {"S": [0, 0, 3], "r": 1e155})"), "/spheres/1",
                   {"too far or too large", "not finite"});
}

TEST_CASE("planes: Q and n are required, n must be a usable direction", "[scene]") {
    const auto plane = [](const std::string& body) { return scene_text(R"("planes": [)" + body + "],"); };
    check_rejected(plane("3"), "/planes/0", {"a plane must be an object", "\"Q\"", "number"});
    check_rejected(plane(R"({"n": [0, 1, 0]})"), "/planes/0/Q", {"missing required key 'Q'", "point"});
    check_rejected(plane(R"({"Q": [0, 0, 0]})"), "/planes/0/n", {"missing required key 'n'", "normal"});
    check_rejected(plane(R"({"Q": [0, 0], "n": [0, 1, 0]})"), "/planes/0/Q", {"3 numbers", "got 2"});
    check_rejected(plane(R"({"Q": [0, 0, 0], "n": [0, "1", 0]})"), "/planes/0/n/1", {"n[1] (y)", "number"});
    check_rejected(plane(R"({"Q": [0, 0, 0], "n": [0, 0, 0]})"), "/planes/0/n", {"zero vector", "normal"});
    check_rejected(plane(R"({"Q": [0, 0, 0], "n": [-0.0, 0, 0]})"), "/planes/0/n", {"zero vector"});
    // Any finite non-zero n has a direction, however long or short (n·n
    // overflowing or underflowing): the engine scales it first.
    check_accepted(plane(R"({"Q": [0, 0, 0], "n": [1e200, 0, 0]})"));
    check_accepted(plane(R"({"Q": [0, 0, 0], "n": [0, 1e-200, 0]})"));
    check_accepted(plane(R"({"Q": [0, 0, 0], "n": [0, 3e-162, 4e-212]})"));
    // A component more than 1e50 times smaller than the largest is refused:
    // n̂'s products with Q and E would underflow.
    check_rejected(plane(R"({"Q": [0, 0, 0], "n": [0, 3e-162, 4e-320]})"), "/planes/0/n/2",
                   {"n[2] = 4e-320", "1e+50 times smaller", "3e-162"});
    check_accepted(plane(R"({"Q": [0, 0, 0], "n": [-1.7e308, 1.7e308, 1.7e308]})"));
    check_rejected(plane(R"({"Q": [1.5e308, 1.5e308, 0], "n": [1, 1, 0]})"), "/planes/0",
                   {"too far", "n̂·Q", "not finite"});
    // The second plane is named by its index.
    check_rejected(plane(R"({"Q": [0, 0, 0], "n": [0, 1, 0]}, {"Q": [0, 0, 0], "n": [0, 0, 0]})"), "/planes/1/n",
                   {"zero vector"});
}

TEST_CASE("materials: coefficients >= 0, a whole exponent from 1 to 10000, a colour", "[scene]") {
    const auto material = [](const std::string& body) { return scene_text(R"("materials": [)" + body + "],"); };
    check_rejected(material("[]"), "/materials/0", {"a material must be an object", "array"});
    check_rejected(material(R"({"ambient": -0.1})"), "/materials/0/ambient", {"ambient", ">= 0", "got -0.1"});
    check_rejected(material(R"({"diffuse": -1})"), "/materials/0/diffuse", {"diffuse", ">= 0", "got -1"});
    check_rejected(material(R"({"specular": -2e-300})"), "/materials/0/specular", {"specular", ">= 0"});
    check_rejected(material(R"({"diffuse": "1"})"), "/materials/0/diffuse", {"diffuse must be a number", "string"});
    check_rejected(material(R"({"specular": 1e400})"), "/materials/0/specular", {"not finite"});
    for (const char* bad : {"0", "2.5", "10001", "1e300", "-3", "0.5"}) {
        INFO("exponent " << bad);
        check_rejected(material(std::string(R"({"exponent": )") + bad + "}"), "/materials/0/exponent",
                       {"exponent", "whole number from 1 to 10000"});
    }
    check_rejected(material(R"({"exponent": 2.5})"), "/materials/0/exponent", {"got 2.5"});
    check_rejected(material(R"({"exponent": 10001})"), "/materials/0/exponent", {"got 10001"});
    check_rejected(material(R"({"exponent": "20"})"), "/materials/0/exponent", {"must be a number", "string"});
    check_rejected(material(R"({}, {"colour": [1, 0.5]})"), "/materials/1/colour",
                   {"colour", "3 numbers [r, g, b]", "got 2 elements"});
    check_rejected(material(R"({"colour": [1, 0.5, 1.5]})"), "/materials/0/colour/2",
                   {"colour[2] (blue)", "between 0 and 1", "got 1.5"});
    check_rejected(material(R"({"colour": [-0.5, 0, 0]})"), "/materials/0/colour/0", {"colour[0] (red)", "got -0.5"});
    check_rejected(material(R"({"colour": 0.5})"), "/materials/0/colour", {"3 numbers [r, g, b]", "number"});
}

TEST_CASE("an object's material index must be a whole number naming a material", "[scene]") {
    const std::string two = R"("materials": [{"diffuse": 0.5}, {"specular": 1}],)";
    const auto sphere = [](const std::string& index) {
        return R"({"S": [0, 0, 3.2], "r": 1.1, "material": )" + index + "}";
    };
    const Scene scene = parse_scene(scene_text(two, sphere("1") + ", " + article_sphere), "test.json");
    CHECK(scene.spheres.at(0).material == 1);
    CHECK(scene.spheres.at(1).material == promyk::no_material);
    check_rejected(scene_text(two, sphere("2")), "/spheres/0/material",
                   {"material 2 does not exist: the scene has 2 materials (0 and 1)"});
    check_rejected(scene_text(two, article_sphere + ", " + sphere("3")), "/spheres/1/material",
                   {"material 3 does not exist", "2 materials (0 and 1)"});
    check_rejected(scene_text("", sphere("0")), "/spheres/0/material",
                   {"material 0 does not exist: the scene has no materials"});
    check_rejected(scene_text(R"("materials": [{}],)", sphere("1")), "/spheres/0/material",
                   {"the scene has 1 material (0)"});
    check_rejected(scene_text(R"("materials": [{}, {}, {}],)", sphere("7")), "/spheres/0/material",
                   {"the scene has 3 materials (0 to 2)"});
    check_rejected(scene_text(two, sphere("-1")), "/spheres/0/material", {"material must be >= 0", "got -1"});
    check_rejected(scene_text(two, sphere("0.5")), "/spheres/0/material", {"whole number", "got 0.5"});
    check_rejected(scene_text(two, sphere("1e300")), "/spheres/0/material", {"does not exist"});
    check_rejected(scene_text(two, sphere("null")), "/spheres/0/material", {"whole number", "null"});
    check_rejected(scene_text(two, sphere("\"0\"")), "/spheres/0/material", {"whole number", "string"});
    check_rejected(scene_text(two + R"("planes": [{"Q": [0, -1, 0], "n": [0, 1, 0], "material": 2}],)"),
                   "/planes/0/material", {"material 2 does not exist"});
    // The materials are read before the objects that refer to them.
    check_rejected(scene_text(R"("materials": [{"exponent": 0}],)", sphere("5")), "/materials/0/exponent",
                   {"whole number from 1 to 10000"});
}

TEST_CASE("background, shadows and light colours", "[scene]") {
    const Scene grey = parse_scene(scene_text(R"("background": [0.25, 0.25, 0.25], "shadows": true,)"), "t");
    CHECK(grey.background == promyk::Colour{0.25, 0.25, 0.25});
    CHECK(grey.shadows);
    check_rejected(scene_text(R"("background": [2, 0, 0],)"), "/background/0",
                   {"background[0] (red)", "between 0 and 1", "got 2"});
    check_rejected(scene_text(R"("background": [0, 0],)"), "/background", {"3 numbers [r, g, b]", "got 2 elements"});
    check_rejected(scene_text(R"("background": "grey",)"), "/background",
                   {"background must be a number (a grey level) or an array [r, g, b]", "string"});
    check_rejected(scene_text(R"("background": [0, null, 0],)"), "/background/1", {"background[1] (green)", "null"});
    check_rejected(scene_text(R"("shadows": "yes",)"), "/shadows", {"shadows must be true or false", "string"});
    check_rejected(scene_text(R"("shadows": 1,)"), "/shadows", {"true or false", "number"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "colour": [1, 1]})"), "/lights/0/colour",
                   {"colour", "got 2 elements"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "colour": [0, 1.0000000000000002, 0]})"),
                   "/lights/0/colour/1", {"colour[1] (green)", "between 0 and 1"});
}

TEST_CASE("unknown keys of the new objects get hints", "[scene]") {
    const std::string one_material = R"("materials": [{}],)";
    // Common other names.
    check_rejected(scene_text(R"("planes": [{"point": [0, 0, 0], "n": [0, 1, 0]}],)"), "/planes/0/point",
                   {"did you mean 'Q'?"});
    check_rejected(scene_text(R"("planes": [{"Q": [0, 0, 0], "normal": [0, 1, 0]}],)"), "/planes/0/normal",
                   {"did you mean 'n'?"});
    check_rejected(scene_text(R"("materials": [{"shininess": 20}],)"), "/materials/0/shininess",
                   {"did you mean 'exponent'?"});
    check_rejected(scene_text(R"("materials": [{"Phong": 20}],)"), "/materials/0/Phong", {"did you mean 'exponent'?"});
    // In a material 'n' is the exponent, not a plane's normal.
    check_rejected(scene_text(R"("materials": [{"n": 20}],)"), "/materials/0/n", {"did you mean 'exponent'?"});
    check_rejected(scene_text(R"("materials": [{"ka": 0.1}],)"), "/materials/0/ka", {"did you mean 'ambient'?"});
    check_rejected(scene_text(R"("materials": [{"Ks": 0.1}],)"), "/materials/0/Ks", {"did you mean 'specular'?"});
    check_rejected(scene_text(R"("materials": [{"color": [1, 0, 0]}],)"), "/materials/0/color",
                   {"did you mean 'colour'?"});
    check_rejected(scene_text(R"("shadow": true,)"), "/shadow", {"did you mean 'shadows'?"});
    check_rejected(scene_text(R"("plane": [],)"), "/plane", {"did you mean 'planes'?"});
    check_rejected(scene_text(R"("material": [],)"), "/material", {"did you mean 'materials'?"});
    check_rejected(scene_text(R"("color": [1, 0, 0],)"), "/color", {"did you mean 'background'?"});
    check_rejected(scene_text(R"("light": [],)"), "/light", {"did you mean 'lights'?"});
    check_rejected(scene_text(one_material, R"({"S": [0, 0, 3.2], "r": 1.1, "mat": 0})"), "/spheres/0/mat",
                   {"did you mean 'material'?"});
    // Keys of the new levels say where they belong.
    check_rejected(scene_text(R"("n": [0, 1, 0],)"), "/n", {"'n' belongs in a plane, inside \"planes\""});
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "Q": [0, 0, 0]})"), "/spheres/0/Q",
                   {"belongs in a plane"});
    check_rejected(scene_text(R"("planes": [{"Q": [0, 0, 0], "n": [0, 1, 0], "r": 1}],)"), "/planes/0/r",
                   {"'r' belongs in a sphere"});
    check_rejected(scene_text(R"("exponent": 3,)"), "/exponent", {"'exponent' belongs in a material, inside \"materials\""});
    check_rejected(scene_text(R"("materials": [{"shadows": true}],)"), "/materials/0/shadows",
                   {"belongs at the top level"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "material": 0})"), "/lights/0/material",
                   {"'material' belongs in a sphere, inside \"spheres\", or in a plane, inside \"planes\""});
    // A colour on an object: it belongs in a material, which the object names by index.
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "colour": [1, 0, 0]})"), "/spheres/0/colour",
                   {"'colour' belongs in a light, inside \"lights\", or in a material, inside \"materials\"",
                    "a sphere names its material by index, as \"material\": 0"});
    check_rejected(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "color": [1, 0, 0]})"), "/spheres/0/color",
                   {"promyk spells it 'colour', and 'colour' belongs in a light", "names its material by index"});
    check_rejected(scene_text(R"("planes": [{"Q": [0, 0, 0], "n": [0, 1, 0], "diffuse": 0.5}],)"),
                   "/planes/0/diffuse", {"belongs in a material", "a plane names its material by index"});
    // Far from every key: the keys allowed there.
    check_rejected(scene_text(R"("materials": [{"glow": 1}],)"), "/materials/0/glow",
                   {"the keys of a material are 'ambient', 'diffuse', 'specular', 'exponent', 'colour'"});
    check_rejected(scene_text(R"("planes": [{"Q": [0, 0, 0], "n": [0, 1, 0], "tilt": 1}],)"), "/planes/0/tilt",
                   {"the keys of a plane are 'Q', 'n', 'material'"});
}

TEST_CASE("syntax errors give the line and column", "[scene]") {
    check_rejected("{\n  \"name\": \"x\",\n  \"z_E\": 2,,\n  \"spheres\": []\n}", "line 3, column 12",
                   {"syntax error", "unexpected ','"});
    // Columns count characters, not bytes: "Ś" is two bytes.
    check_rejected("{\"name\": \"\xC5\x9Bledzenie\" x}", "line 1, column 22", {"syntax error"});
    check_rejected("{\n  \"spheres\": [\n", "line 3, column 1", {"syntax error", "end of input"});
    check_rejected("{\n  \"z_E\": tru\n}", "line 2, column 13", {"syntax error", "invalid literal"});
    check_rejected("{\"name\": \"a\x01\"}", "line 1, column 12", {"syntax error", "control character"});
    check_rejected(scene_text() + " {}", "line 1, column " + std::to_string(scene_text().size() + 2),
                   {"syntax error", "end of input"});
}

TEST_CASE("nesting and size are limited", "[scene]") {
    check_rejected(std::string(100, '['),
                   "/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0"
                   "/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0",
                   {"nested deeper than 64"});
    check_rejected(scene_text() + std::string(promyk::max_scene_file_bytes, ' '), "", {"1 MiB"});
    check_accepted(scene_text() + std::string(promyk::max_scene_file_bytes - scene_text().size(), ' '));
}

TEST_CASE("scene_to_json reads back to the same scene", "[scene]") {
    check_same_scene(parse_scene(promyk::scene_to_json(promyk::article_scene()), "x"), promyk::article_scene());

    Scene odd = promyk::article_scene();
    odd.name = "Śledzenie \"promieni\" \\ ☀";
    odd.z_E = 0.1 + 0.2;
    odd.background = {5e-324, 5e-324, 5e-324};
    odd.spheres[0].S = {-0.0, 1e-50, 123456789012345678.0};
    odd.spheres[0].r = 1.0 / 3;
    odd.lights[0].L = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), -0.0};
    odd.lights[0].I = 1e300;
    const std::string text = promyk::scene_to_json(odd);
    INFO(text);
    check_same_scene(parse_scene(text, "x"), odd);

    // Every new field away from its default, and values at the edges.
    Scene rich = odd;
    rich.shadows = true;
    rich.background = {0, -0.0, 1};
    rich.materials = {promyk::Material{0.1, 0.0, 1e300, 10000, {0.3, 5e-324, 1}}, promyk::Material{}};
    rich.spheres[0].material = 1;
    rich.spheres.push_back(promyk::Sphere{{1, 2, -7}, 0.5, promyk::no_material});
    rich.planes = {promyk::Plane{{0, -1.1, 0}, {0, 1, 0}, 0}, promyk::Plane{{1e-50, 0, 3}, {-1e-30, 3, 1e20}}};
    rich.lights[0].colour = {1, 0.95, -0.0};
    rich.lights.push_back(promyk::Light{{0, 0, 0}, 0, {1, 1, 1}});
    const std::string rich_text = promyk::scene_to_json(rich);
    INFO(rich_text);
    check_same_scene(parse_scene(rich_text, "x"), rich);
    check_same_scene(parse_scene(promyk::scene_to_json(rich, promyk::SceneDefaults::written), "x"), rich);

    // Random doubles of every magnitude the validation lets through.
    std::mt19937_64 random(20240611);
    // (Down to about 1e-48: a number other than 0 below min_scene_magnitude, 1e-50, is refused.)
    std::uniform_int_distribution<int> exponent(-140, 150);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    const auto any = [&] {
        double m;
        do m = mantissa(random);
        while (std::abs(m) < 1e-6);
        return std::ldexp(m, exponent(random));
    };
    for (int n = 0; n < 500; ++n) {
        Scene scene;
        scene.name = "random " + std::to_string(n);
        scene.z_E = std::abs(any()) + 1e-300;
        { const double grey = std::uniform_real_distribution<double>(0, 1)(random); scene.background = {grey, grey, grey}; }
        const promyk::Vec3d S{any(), any(), any()};
        const double length = std::sqrt(promyk::length_squared(S));
        scene.spheres = {promyk::Sphere{S, length * std::uniform_real_distribution<double>(0.01, 0.9)(random)}};
        scene.lights = {promyk::Light{{any(), any(), any()}, std::abs(any())}};
        // From the 100th on, the new fields too: more objects and lights,
        // planes, materials, colours, shadows.
        if (n >= 100) {
            std::uniform_int_distribution<int> count(0, 3);
            std::uniform_real_distribution<double> unit(0, 1);
            const auto colour = [&] { return promyk::Colour{unit(random), unit(random), unit(random)}; };
            const int materials = count(random);
            for (int k = 0; k < materials; ++k)
                scene.materials.push_back(promyk::Material{std::abs(any()), std::abs(any()), std::abs(any()),
                                                           std::uniform_int_distribution<int>(1, 10000)(random),
                                                           colour()});
            const auto material = [&] {
                return std::uniform_int_distribution<int>(promyk::no_material, materials - 1)(random);
            };
            scene.spheres[0].material = material();
            for (int k = count(random); k > 0; --k) {
                const promyk::Vec3d C{any(), any(), any()};
                scene.spheres.push_back(
                    promyk::Sphere{C, std::sqrt(promyk::length_squared(C)) * std::max(unit(random), 0.01), material()});
            }
            for (int k = count(random); k > 0; --k) {
                promyk::Vec3d normal{mantissa(random), mantissa(random), mantissa(random)};
                if (normal == promyk::Vec3d{0, 0, 0}) normal = {0, 1, 0};
                scene.planes.push_back(promyk::Plane{{any(), any(), any()}, normal, material()});
            }
            for (int k = count(random); k > 0; --k)
                scene.lights.push_back(promyk::Light{{any(), any(), any()}, std::abs(any()), colour()});
            scene.background = n % 2 ? colour() : scene.background;
            scene.shadows = n % 3 == 0;
        }
        const std::string json_text = promyk::scene_to_json(scene);
        INFO(json_text);
        check_same_scene(parse_scene(json_text, "x"), scene);
        check_same_scene(parse_scene(promyk::scene_to_json(scene, promyk::SceneDefaults::written), "x"), scene);
    }
}

TEST_CASE("a missing or unreadable scene file is an input error", "[scene]") {
    const std::string missing = std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes/no-such-scene.json";
    try {
        promyk::load_scene_file(missing);
        FAIL("a missing file loaded");
    } catch (const InputError& error) {
        CHECK(error.file == missing);
        CHECK(error.where.empty());
        CHECK_THAT(error.what(), Catch::Matchers::Contains("No such file"));
    }
    try {
        promyk::load_scene_file(std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes");
        FAIL("a directory loaded");
    } catch (const InputError& error) {
        CHECK(error.where.empty());
        CHECK_THAT(error.what(), Catch::Matchers::Contains("cannot read"));
    }

    const promyk::testing::TempDir dir("promyk-scene");
    const std::filesystem::path big = dir.file("big.json");
    {
        std::ofstream out(big, std::ios::binary);
        out << scene_text() << std::string(promyk::max_scene_file_bytes, ' ');
    }
    try {
        promyk::load_scene_file(big.string());
        FAIL("a file over the limit loaded");
    } catch (const InputError& error) {
        CHECK(error.where.empty());
        CHECK_THAT(error.what(), Catch::Matchers::Contains("1 MiB"));
    }

    // Errors inside a file name the file.
    const std::filesystem::path bad = dir.file("bad.json");
    {
        std::ofstream out(bad, std::ios::binary);
        out << scene_text("", R"({"S": [0, 0, 3], "r": -1})");
    }
    try {
        promyk::load_scene_file(bad.string());
        FAIL("a bad file loaded");
    } catch (const InputError& error) {
        CHECK(error.file == bad.string());
        CHECK(error.where == "/spheres/0/r");
    }
}

// ---------------------------------------------------------------------------
// Hostile input: bytes that hide content, control characters in messages,
// files built to be slow, files that arrive slowly.

namespace {

const std::string bom = "\xEF\xBB\xBF";

std::string scene_file(const std::string& name) { return std::string(PROMYK_SOURCE_DIR) + "/tests/cli/scenes/" + name; }

using promyk::testing::has_terminal_control;

// Rejected, and neither the pointer nor the message holds a control character.
void check_rejected_printable(const std::string& text, const std::string& where,
                              std::initializer_list<const char*> words) {
    check_rejected(text, where, words);
    try {
        parse_scene(text, "test.json");
    } catch (const InputError& error) {
        CHECK(!has_terminal_control(error.where));
        CHECK(!has_terminal_control(error.what()));
    }
}

}  // namespace

TEST_CASE("a NUL byte anywhere is rejected at its line and column", "[scene]") {
    const std::string nul(1, '\0');
    // nlohmann's lexer takes a NUL for the end of the input: what follows it was ignored.
    check_rejected(scene_text() + nul + "garbage", "line 1, column " + std::to_string(scene_text().size() + 1),
                   {"NUL"});
    check_rejected(scene_text() + "\n\n  " + nul, "line 3, column 3", {"NUL"});
    check_rejected(nul + scene_text(), "line 1, column 1", {"NUL"});
    check_rejected(nul, "line 1, column 1", {"NUL"});
    check_rejected(bom + nul + scene_text(), "line 1, column 1", {"NUL"});  // columns after the byte order mark
    check_rejected(scene_text("\"name\": \"Ś" + nul + "\",\n"), "line 1, column 12", {"NUL"});  // in a string
    check_rejected(scene_text("\n\"z_E\": 2" + nul + ",\n"), "line 2, column 9", {"NUL"});

    try {
        promyk::load_scene_file(scene_file("nul_after_scene.json"));
        FAIL("a file with a NUL byte loaded");
    } catch (const InputError& error) {
        CHECK(error.file == scene_file("nul_after_scene.json"));
        CHECK(error.where == "line 12, column 1");
        CHECK_THAT(error.what(), Catch::Matchers::Contains("NUL"));
    }
}

TEST_CASE("one byte order mark is allowed, only at the start", "[scene]") {
    check_accepted(bom + scene_text());
    check_accepted(bom + "\n " + scene_text());
    check_rejected(bom + bom + scene_text(), "line 1, column 1", {"byte order mark", "start"});
    check_rejected(bom + " " + bom + scene_text(), "line 1, column 2", {"byte order mark"});
    check_rejected(" " + bom + scene_text(), "line 1, column 2", {"byte order mark"});
    check_rejected(scene_text() + "\n" + bom, "line 2, column 1", {"byte order mark"});
    check_rejected(scene_text("\"name\": \"a" + bom + "b\","), "line 1, column 12", {"byte order mark"});
    check_rejected(bom + bom, "line 1, column 1", {"byte order mark"});

    try {
        promyk::load_scene_file(scene_file("two_byte_order_marks.json"));
        FAIL("a file with two byte order marks loaded");
    } catch (const InputError& error) {
        CHECK(error.where == "line 1, column 1");
        CHECK_THAT(error.what(), Catch::Matchers::Contains("byte order mark"));
    }
}

TEST_CASE("bytes that are not JSON text are syntax errors, in strings and out", "[scene]") {
    check_rejected(scene_text() + "\xff", "line 1, column " + std::to_string(scene_text().size() + 1),
                   {"syntax error"});
    check_rejected("\xFF\xFE{}", "line 1, column 1", {"syntax error"});  // UTF-16's byte order mark
    check_rejected(scene_text("\"name\": \"a\xff\","), "line 1, column 12", {"syntax error", "UTF-8"});
    check_rejected(scene_text("\"name\": \"a\xC0\x80\","), "line 1, column 12", {"syntax error", "UTF-8"});
    check_rejected(scene_text("\"name\": \"a\xED\xA0\x80\","), "line 1, column 13", {"syntax error", "UTF-8"});
    check_rejected(scene_text("\"name\": \"a\x1b[31m\","), "line 1, column 12", {"syntax error", "control character"});
    check_rejected(scene_text("\x0c\"z_E\": 2,"), "line 1, column 2", {"syntax error"});  // form feed
    check_rejected(scene_text("\x1b[8m\"z_E\": 2,"), "line 1, column 2", {"syntax error"});
}

TEST_CASE("input text in messages and pointers is printable", "[scene]") {
    check_rejected_printable(scene_text(R"("\u001b[31mEVIL": 1,)"), "/\\u001b[31mEVIL",
                             {"unknown key '\\u001b[31mEVIL'"});
    check_rejected_printable(scene_text("\"\x1b[31mEVIL\": 1,"), "line 1, column 3", {"control character"});
    check_rejected_printable(scene_text("", R"({"S": [0, 0, 3.2], "r": 1.1, "\n\u009b2J": 1})"),
                             "/spheres/0/\\n\\u009b2J", {"unknown key '\\n\\u009b2J'"});
    check_rejected_printable(scene_text("", article_sphere, R"({"L": [1, 1, 1], "I\u007f": 1})"), "/lights/0/I\\u007f",
                             {"unknown key 'I\\u007f'"});
    check_rejected_printable(scene_text("\"\xC2\x85\": 1,"), "/\\u0085", {"unknown key '\\u0085'"});
    check_rejected_printable(scene_text("\"\xE2\x80\xAEtxt\": 1,"), "/\\u202etxt", {"unknown key '\\u202etxt'"});
    check_rejected_printable(scene_text(R"("\u0007": 1, "\u0007": 2,)"), "/\\u0007", {"duplicate key '\\u0007'"});
    check_rejected_printable(scene_text(R"("comment": {"\u001b]0;title\u0007": 1e999},)"),
                             "/comment/\\u001b]0;title\\u0007", {"1e999", "not finite"});
    check_rejected_printable(
        scene_text(R"("comment": {"\t": [)" + std::string(70, '[')),
        "/comment/\\t/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0"
        "/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0",
        {"nested deeper than 64"});
}

namespace {

// `count` distinct keys of 1 to 3 printable ASCII characters (none of the
// format's keys, no '"' or '\\'), each with the value 0, after `first`.
std::string many_members(std::size_t count, const std::string& first) {
    std::string alphabet;
    for (char c = '!'; c <= '~'; ++c)
        if (c != '"' && c != '\\') alphabet += c;
    std::string out = "\"" + first + "\":0";
    std::size_t made = 1;
    for (std::size_t length = 1; length <= 3 && made < count; ++length) {
        std::size_t combinations = 1;
        for (std::size_t k = 0; k < length; ++k) combinations *= alphabet.size();
        for (std::size_t n = 0; n < combinations && made < count; ++n) {
            std::string key;
            for (std::size_t k = 0, rest = n; k < length; ++k, rest /= alphabet.size())
                key += alphabet[rest % alphabet.size()];
            if (key == "S" || key == "r" || key == "L" || key == "I" || key == "z_E" || key == first) continue;
            out += ",\"" + key + "\":0";
            ++made;
        }
    }
    return out;
}

void check_rejected_in_time(const std::string& text, const std::string& where,
                            std::initializer_list<const char*> words) {
    REQUIRE(text.size() <= promyk::max_scene_file_bytes);
    // Processor time, not wall-clock time: a busy machine does not count.
    const std::clock_t start = std::clock();
    check_rejected(text, where, words);
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    INFO("bytes: " << text.size() << ", CPU seconds: " << seconds);
    // A bound for slow (sanitizer) builds, not a speed claim: the quadratic
    // cost this guards against took 39.5 s a MiB in a release build.
    CHECK(seconds < 20);
}

}  // namespace

TEST_CASE("a scene file of many keys is rejected in time, whatever its shape", "[scene][slow]") {
    const std::size_t keys = 131567;  // a 1 MiB file of such keys took 39.5 s when objects kept file order
    const std::string members = many_members(keys, "nmae");
    check_rejected_in_time("{" + members + "}", "/nmae", {"unknown key 'nmae'; did you mean 'name'?"});
    // Every fault is reported, in document order: a key duplicated at the start.
    check_rejected_in_time("{\"!\":1," + members + "}", "/!", {"duplicate key '!'"});
    check_rejected_in_time("{\"name\":{" + members + "}}", "/name", {"name must be a string, got an object"});
    check_rejected_in_time("{\"comment\":{" + members + "}}", "/comment", {"unknown key 'comment'"});
    check_rejected_in_time("{\"spheres\":[{" + many_members(keys - 2, "radius") + ",\"S\":[0,0,3],\"r\":1}]}",
                           "/spheres/0/radius", {"unknown key 'radius'; did you mean 'r'?"});
    std::string empty_objects = "{}";
    for (int k = 1; k < 200000; ++k) empty_objects += ",{}";
    check_rejected_in_time("{\"spheres\":[" + empty_objects + "]}", "/spheres/0/S", {"missing required key 'S'"});
    check_rejected_in_time("{\"materials\":[" + empty_objects + "]}", "/spheres", {"no objects"});
    std::string empty_arrays = "[]";
    for (int k = 1; k < 200000; ++k) empty_arrays += ",[]";
    check_rejected_in_time("{\"background\":[" + empty_arrays + "]}", "/background",
                           {"background must be an array of 3 numbers", "got 200000 elements"});
    std::string zeros = "0";
    for (int k = 1; k < 300000; ++k) zeros += ",0";
    check_rejected_in_time("{\"spheres\":[" + zeros + "]}", "/spheres/0", {"a sphere must be an object"});
    std::string spheres = article_sphere;
    for (int k = 1; k < 20000; ++k) spheres += "," + article_sphere;
    check_rejected_in_time("{\"spheres\":[" + spheres + "]}", "/lights", {"missing required key 'lights'"});
    // The first unknown key in file order is reported, wherever the others sit.
    check_rejected_in_time("{\"lights\":[{\"L\":[1,1,1],\"power\":1," + many_members(keys - 3, "~~~~") +
                               "}],\"spheres\":[{\"S\":[0,0,3],\"r\":1}]}",
                           "/lights/0/power", {"unknown key 'power'; did you mean 'I'?"});
}

TEST_CASE("faults are reported in document order, the first as the InputError", "[scene]") {
    check_rejected(scene_text(R"("zzz": 1, "aaa": 1, "nmae": 1,)"), "/zzz", {"unknown key 'zzz'"});
    check_rejected(scene_text("", R"({"x": 1, "S": [0, 0, 3.2], "r": 1.1, "a": 2})"), "/spheres/0/x",
                   {"unknown key 'x'"});
    check_rejected(scene_text("", article_sphere, R"({"q": 1, "L": [1, 1, 1], "b": 2})"), "/lights/0/q",
                   {"unknown key 'q'"});
    // Found after the file is read: a later syntax error is reported first ...
    check_rejected(R"({"zzz": 1, "spheres": [}])", "line 1, column 24", {"syntax error"});
    // ... then every other fault in document order (SceneErrors holds them all).
    check_rejected(R"({"spheres": [{"x": 1, "S": [0, 0, 3], "r": -1}], "lights": [], "zzz": 1})", "/spheres/0/x",
                   {"unknown key 'x'"});
    check_rejected(R"({"z_E": -1, "spheres": [{"x": 1, "S": [0, 0, 3], "r": 1}], "lights": []})", "/z_E", {"> 0"});
    check_rejected(R"({"spheres": [{"S": [0, 0, 3], "r": -1, "x": 1}], "lights": []})", "/spheres/0/r", {"> 0"});
    // Every sphere is read: the second one's unknown key is reported before its missing S
    // (a missing key where its object ends).
    check_rejected(scene_text("", article_sphere + R"(, {"x": 1})"), "/spheres/1/x", {"unknown key 'x'"});
    // In the new objects too.
    check_rejected(scene_text(R"("planes": [{"Q": [0, 0, 0], "nn": 1, "n": [0, 1, 0], "zz": 2}],)"), "/planes/0/nn",
                   {"unknown key 'nn'; did you mean 'n'?"});
    check_rejected(scene_text(R"("materials": [{"kd": 1, "diffuse": -1}],)"), "/materials/0/kd",
                   {"unknown key 'kd'; did you mean 'diffuse'?"});
    check_rejected(scene_text("", article_sphere, R"({"L": [1, 1, 1], "color": [1, 1, 1], "q": 1})"),
                   "/lights/0/color", {"did you mean 'colour'?"});
}

TEST_CASE("a scene file is read to its end through short reads and signals", "[scene]") {
    const auto fifo =
        std::filesystem::temp_directory_path() / ("promyk_scene_json_test_fifo_" + std::to_string(::getpid()));
    std::filesystem::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    // A handler without SA_RESTART, as promyk's own: a blocked read fails with EINTR.
    struct sigaction quiet {
    }, old_usr1{}, old_pipe{};
    quiet.sa_handler = [](int) {};
    sigemptyset(&quiet.sa_mask);
    sigaction(SIGUSR1, &quiet, &old_usr1);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &old_pipe);  // if the reader gave up early, the writer must not die

    std::ifstream article_file(article_path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(article_file)), std::istreambuf_iterator<char>());
    const pthread_t reader = pthread_self();
    std::thread writer([&] {
        const int fd = ::open(fifo.c_str(), O_WRONLY);
        if (fd < 0) return;
        const auto pause = [] { std::this_thread::sleep_for(std::chrono::milliseconds(150)); };
        const auto send = [&](std::size_t from, std::size_t count) {
            if (::write(fd, text.data() + from, count) < 0) return;
        };
        send(0, 20);  // a short read
        pause();
        send(20, 30);
        pause();
        pthread_kill(reader, SIGUSR1);  // the reader is blocked waiting for more
        pause();
        send(50, text.size() - 50);
        ::close(fd);
    });
    Scene loaded;
    std::string failure;
    try {
        loaded = promyk::load_scene_file(fifo.string());
    } catch (const InputError& error) {
        failure = error.what();
    }
    writer.join();
    sigaction(SIGUSR1, &old_usr1, nullptr);
    sigaction(SIGPIPE, &old_pipe, nullptr);
    std::filesystem::remove(fifo);
    INFO("error: " << failure);
    REQUIRE(failure.empty());
    check_same_scene(loaded, promyk::article_scene());
}

TEST_CASE("a scene file that cannot be opened or read carries errno", "[scene]") {
    try {
        promyk::load_scene_file(std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes/no-such-scene.json");
        FAIL("a missing file loaded");
    } catch (const promyk::SceneFileError& error) {
        CHECK(error.error_number == ENOENT);
        CHECK(error.where.empty());
    }
    try {
        promyk::load_scene_file(std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes");
        FAIL("a directory loaded");
    } catch (const promyk::SceneFileError& error) {
        CHECK(error.error_number == EISDIR);
        CHECK_THAT(error.what(), Catch::Matchers::Contains("cannot read the scene file: Is a directory"));
    }
}
