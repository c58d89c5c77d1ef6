// scene_hash and scene_to_json against independent values: the hash of the
// article's scene is FNV-1a 64 of its canonical text, computed here by a
// separate implementation from a hand-written text (and the constant was
// computed with Python); every field of a scene changes the hash; the scene
// writer's text for the article's scene and for a scene file is compared
// with hand-written text, not only read back by promyk's own reader.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_json.hpp"

namespace {

// FNV-1a, 64 bits (offset basis 0xcbf29ce484222325, prime 0x100000001b3).
std::string fnv1a64(const std::string& text) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

// The canonical text scene_hash hashes (src/scene/scene_hash.cpp): one line,
// every number as its shortest round-trip text.
const char* const article_canonical_text =
    "name=article;z_E=2;background=0.5;sphere=S(0,0,3.2),r(1.1);light=L(1.5,1,1),I(1)";

}  // namespace

TEST_CASE("the independent FNV-1a 64 gives the published test vectors", "[scene-hash]") {
    CHECK(fnv1a64("") == "cbf29ce484222325");
    CHECK(fnv1a64("a") == "af63dc4c8601ec8c");
    CHECK(fnv1a64("foobar") == "85944171f73967e8");
}

TEST_CASE("the article scene's hash is FNV-1a 64 of its canonical text", "[scene-hash]") {
    const std::string hash = promyk::scene_hash(promyk::article_scene());
    CHECK(hash == "fnv1a64:" + fnv1a64(article_canonical_text));
    // The same, computed with Python from the same text.
    CHECK(hash == "fnv1a64:41b8d9e464625609");
}

TEST_CASE("every field of a scene changes its hash", "[scene-hash]") {
    using promyk::Scene;
    const Scene article = promyk::article_scene();
    struct Change {
        const char* field;
        void (*apply)(Scene&);
    };
    const std::vector<Change> changes = {
        {"name", [](Scene& s) { s.name = "articlf"; }},
        {"z_E", [](Scene& s) { s.z_E = 3; }},
        {"background", [](Scene& s) { s.background = {0.25, 0.25, 0.25}; }},
        {"S.x", [](Scene& s) { s.spheres[0].S.x = 0.125; }},
        {"S.y", [](Scene& s) { s.spheres[0].S.y = 0.125; }},
        {"S.z", [](Scene& s) { s.spheres[0].S.z = 3.25; }},
        {"r", [](Scene& s) { s.spheres[0].r = 1.2; }},
        {"L.x", [](Scene& s) { s.lights[0].L.x = 1.25; }},
        {"L.y", [](Scene& s) { s.lights[0].L.y = 1.25; }},
        {"L.z", [](Scene& s) { s.lights[0].L.z = 1.25; }},
        {"I", [](Scene& s) { s.lights[0].I = 0.75; }},
        // The fields the format grew; each is at its default in the article.
        {"background colour", [](Scene& s) { s.background = {0.5, 0.5, 0.25}; }},
        {"background grey and -0", [](Scene& s) { s.background = {0, -0.0, 0}; }},
        {"shadows", [](Scene& s) { s.shadows = true; }},
        {"light colour", [](Scene& s) { s.lights[0].colour = {1, 1, 0.5}; }},
        {"a second light", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
        {"a second sphere", [](Scene& s) { s.spheres.push_back(s.spheres[0]); }},
        {"a plane", [](Scene& s) { s.planes = {promyk::Plane{{0, -1, 0}, {0, 1, 0}}}; }},
        {"plane Q", [](Scene& s) { s.planes = {promyk::Plane{{0, -1.5, 0}, {0, 1, 0}}}; }},
        {"plane n", [](Scene& s) { s.planes = {promyk::Plane{{0, -1, 0}, {0, 2, 0}}}; }},
        {"plane material", [](Scene& s) {
             s.materials = {promyk::Material{}};
             s.planes = {promyk::Plane{{0, -1, 0}, {0, 1, 0}, 0}};
         }},
        {"a default material, unused", [](Scene& s) { s.materials = {promyk::Material{}}; }},
        {"sphere material", [](Scene& s) {
             s.materials = {promyk::Material{}};
             s.spheres[0].material = 0;
         }},
        {"ambient", [](Scene& s) { s.materials = {promyk::Material{0.25, 1, 0, 10, promyk::white}}; }},
        {"diffuse", [](Scene& s) { s.materials = {promyk::Material{0, 0.5, 0, 10, promyk::white}}; }},
        {"specular", [](Scene& s) { s.materials = {promyk::Material{0, 1, 0.5, 10, promyk::white}}; }},
        {"exponent", [](Scene& s) { s.materials = {promyk::Material{0, 1, 0, 11, promyk::white}}; }},
        {"material colour", [](Scene& s) { s.materials = {promyk::Material{0, 1, 0, 10, {1, 0.5, 1}}}; }},
    };
    std::set<std::string> hashes = {promyk::scene_hash(article)};
    for (const Change& change : changes) {
        Scene scene = article;
        change.apply(scene);
        const std::string hash = promyk::scene_hash(scene);
        INFO("changing " << change.field);
        CHECK(hash != promyk::scene_hash(article));
        CHECK(hashes.insert(hash).second);  // and differs from every other change
    }
    // One ulp of r is a different image, so a different hash.
    Scene scene = article;
    scene.spheres[0].r = std::nextafter(scene.spheres[0].r, 2.0);
    CHECK(promyk::scene_hash(scene) != promyk::scene_hash(article));
    // The defaults, set explicitly, are the article's scene: the same hash.
    scene = article;
    scene.shadows = false;
    scene.lights[0].colour = promyk::white;
    scene.spheres[0].material = promyk::no_material;
    CHECK(promyk::scene_hash(scene) == promyk::scene_hash(article));
    // A colour channel's last bit changes it.
    scene.lights[0].colour.z = std::nextafter(1.0, 0.0);
    CHECK(promyk::scene_hash(scene) != promyk::scene_hash(article));
    // The source file name is not part of the scene's image.
    scene = article;
    scene.source = "elsewhere.json";
    CHECK(promyk::scene_hash(scene) == promyk::scene_hash(article));
}

TEST_CASE("the scene writer writes the article's scene as the documented text", "[scene-json]") {
    const std::string expected =
        "{\n"
        "  \"name\": \"article\",\n"
        "  \"z_E\": 2,\n"
        "  \"background\": 0.5,\n"
        "  \"spheres\": [\n"
        "    {\"S\": [0, 0, 3.2], \"r\": 1.1}\n"
        "  ],\n"
        "  \"lights\": [\n"
        "    {\"L\": [1.5, 1, 1], \"I\": 1}\n"
        "  ]\n"
        "}\n";
    CHECK(promyk::scene_to_json(promyk::article_scene()) == expected);
}

TEST_CASE("the scene writer writes every new field in the documented order and form", "[scene-json]") {
    promyk::Scene scene = promyk::article_scene();
    scene.name = "rich";
    scene.background = {0.25, 0.5, 1};
    scene.shadows = true;
    scene.materials = {promyk::Material{0.1, 0.8, 0.4, 30, {0.9, 0.25, 0.2}}, promyk::Material{}};
    scene.spheres[0].material = 1;
    scene.spheres.push_back(promyk::Sphere{{1, 0, 5}, 0.5});
    scene.planes = {promyk::Plane{{0, -1.1, 0}, {0, 1, 0}, 0}};
    scene.lights[0].colour = {1, 0.95, 0.8};
    scene.lights.push_back(promyk::Light{{-2, 1, 0}, 0.5});
    const std::string expected =
        "{\n"
        "  \"name\": \"rich\",\n"
        "  \"z_E\": 2,\n"
        "  \"background\": [0.25, 0.5, 1],\n"
        "  \"shadows\": true,\n"
        "  \"spheres\": [\n"
        "    {\"S\": [0, 0, 3.2], \"r\": 1.1, \"material\": 1},\n"
        "    {\"S\": [1, 0, 5], \"r\": 0.5}\n"
        "  ],\n"
        "  \"planes\": [\n"
        "    {\"Q\": [0, -1.1, 0], \"n\": [0, 1, 0], \"material\": 0}\n"
        "  ],\n"
        "  \"lights\": [\n"
        "    {\"L\": [1.5, 1, 1], \"I\": 1, \"colour\": [1, 0.95, 0.8]},\n"
        "    {\"L\": [-2, 1, 0], \"I\": 0.5}\n"
        "  ],\n"
        "  \"materials\": [\n"
        "    {\"ambient\": 0.1, \"diffuse\": 0.8, \"specular\": 0.4, \"exponent\": 30, \"colour\": [0.9, 0.25, 0.2]},\n"
        "    {\"ambient\": 0, \"diffuse\": 1, \"specular\": 0, \"exponent\": 10, \"colour\": [1, 1, 1]}\n"
        "  ]\n"
        "}\n";
    CHECK(promyk::scene_to_json(scene) == expected);
}

TEST_CASE("the scene writer with every default written out", "[scene-json]") {
    const std::string expected =
        "{\n"
        "  \"name\": \"article\",\n"
        "  \"z_E\": 2,\n"
        "  \"background\": 0.5,\n"
        "  \"shadows\": false,\n"
        "  \"spheres\": [\n"
        "    {\"S\": [0, 0, 3.2], \"r\": 1.1}\n"
        "  ],\n"
        "  \"planes\": [],\n"
        "  \"lights\": [\n"
        "    {\"L\": [1.5, 1, 1], \"I\": 1, \"colour\": [1, 1, 1]}\n"
        "  ],\n"
        "  \"materials\": []\n"
        "}\n";
    CHECK(promyk::scene_to_json(promyk::article_scene(), promyk::SceneDefaults::written) == expected);
}

TEST_CASE("the scene writer writes a hand-written scene file back as it was written", "[scene-json]") {
    // The scene files of the reference tests are written in the writer's
    // layout by hand; reading and writing one gives the same bytes.
    for (const char* file : {"off_axis_far.json", "off_axis_near.json", "tangent_axis.json",
                             "tangent_off_axis.json", "dark_exact.json"}) {
        const std::string path = std::string(PROMYK_SOURCE_DIR "/tests/reference/scenes/") + file;
        std::ifstream in(path, std::ios::binary);
        REQUIRE(in);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        INFO(file);
        CHECK(promyk::scene_to_json(promyk::load_scene_file(path)) == text);
    }
    // And the numbers read are the doubles the text names.
    const promyk::Scene far =
        promyk::load_scene_file(PROMYK_SOURCE_DIR "/tests/reference/scenes/off_axis_far.json");
    CHECK(far.z_E == 3.0);
    CHECK(far.spheres.at(0).S.x == 0.45);
    CHECK(far.spheres.at(0).S.y == -0.35);
    CHECK(far.spheres.at(0).S.z == 4.2);
    CHECK(far.spheres.at(0).r == 1.3);
    CHECK(far.lights.at(0).L.x == -2.5);
    CHECK(far.lights.at(0).I == 3.0);
    CHECK(far.background.x == 0.2);
}
