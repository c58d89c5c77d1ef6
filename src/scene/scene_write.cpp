// Scenes as scene files: the canonical form (fields in the documented order,
// every number as the shortest text that reads back to the same double).

#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"

namespace promyk {

namespace {

using Json = nlohmann::json;


// The shortest text that reads back to the same double. "-0.0" keeps the sign
// of a negative zero (JSON readers take "-0" for the integer 0). Non-finite
// numbers have no JSON form: null (such a scene does not load back).
std::string number_text(double value) {
    if (!std::isfinite(value)) return "null";
    if (value == 0 && std::signbit(value)) return "-0.0";
    return fmt::format("{}", value);
}

std::string vec3_text(const Vec3d& v) {
    return fmt::format("[{}, {}, {}]", number_text(v.x), number_text(v.y), number_text(v.z));
}

// True when a and b are the same double, down to the sign of zero: a colour
// is written as one grey number only when that number reads back as all
// three channels.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A grey colour as one number, any other as [r, g, b].
std::string colour_text(const Colour& c) {
    return same_bits(c.x, c.y) && same_bits(c.y, c.z) ? number_text(c.x) : vec3_text(c);
}

// `"key": [` then each item on its own line, then `]` (`[]` when empty).
std::string array_text(std::string_view key, const std::vector<std::string>& items) {
    std::string text = fmt::format("  \"{}\": [", key);
    for (std::size_t k = 0; k < items.size(); ++k) text += fmt::format("{}\n    {}", k == 0 ? "" : ",", items[k]);
    return text + (items.empty() ? "]" : "\n  ]");
}

std::string material_index_text(int material) {
    return material == no_material ? "" : fmt::format(", \"material\": {}", material);
}

}  // namespace

std::string scene_to_json(const Scene& scene, SceneDefaults defaults) {
    const bool all = defaults == SceneDefaults::written;
    const std::string name = Json(scene.name).dump(-1, ' ', false, Json::error_handler_t::replace);
    std::vector<std::string> fields = {
        fmt::format("  \"name\": {}", name),
        fmt::format("  \"z_E\": {}", number_text(scene.z_E)),
        fmt::format("  \"background\": {}", colour_text(scene.background)),
    };
    if (scene.shadows || all) fields.push_back(fmt::format("  \"shadows\": {}", scene.shadows ? "true" : "false"));
    std::vector<std::string> items;
    for (const Sphere& s : scene.spheres)
        items.push_back(fmt::format("{{\"S\": {}, \"r\": {}{}}}", vec3_text(s.S), number_text(s.r),
                                    material_index_text(s.material)));
    fields.push_back(array_text("spheres", items));
    items.clear();
    for (const Plane& p : scene.planes)
        items.push_back(
            fmt::format("{{\"Q\": {}, \"n\": {}{}}}", vec3_text(p.Q), vec3_text(p.n), material_index_text(p.material)));
    if (!items.empty() || all) fields.push_back(array_text("planes", items));
    items.clear();
    for (const Light& l : scene.lights)
        items.push_back(fmt::format("{{\"L\": {}, \"I\": {}{}}}", vec3_text(l.L), number_text(l.I),
                                    l.colour == white && !all ? "" : ", \"colour\": " + vec3_text(l.colour)));
    fields.push_back(array_text("lights", items));
    items.clear();
    for (const Material& m : scene.materials)
        items.push_back(fmt::format(
            "{{\"ambient\": {}, \"diffuse\": {}, \"specular\": {}, \"exponent\": {}, \"colour\": {}}}",
            number_text(m.ambient), number_text(m.diffuse), number_text(m.specular), m.exponent,
            vec3_text(m.colour)));
    if (!items.empty() || all) fields.push_back(array_text("materials", items));

    std::string text = "{\n";
    for (std::size_t k = 0; k < fields.size(); ++k) text += fields[k] + (k + 1 < fields.size() ? ",\n" : "\n");
    return text + "}\n";
}

}  // namespace promyk
