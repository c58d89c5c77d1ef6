#include "scene/scene_hints.hpp"

#include <algorithm>
#include <cctype>

#include "trace/messages.hpp"
#include "util/edit_distance.hpp"

namespace promyk::scene_detail {

namespace {

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

const std::vector<const Level*>& levels() {
    static const std::vector<const Level*> all{&scene_level(), &sphere_level(), &plane_level(), &light_level(),
                                               &material_level()};
    return all;
}

std::string home(const Level& level) { return ui_message("scene_home_" + std::string(level.id)); }

// "'k' belongs in a light, inside "lights", or in a material, inside
// "materials"" when `key` is a key of levels other than `level`; else empty.
// An object's hint adds how it refers to a material.
std::string belongs_hint(std::string_view key, const Level& level) {
    std::string homes;
    bool in_material = false;
    for (const Level* other : levels()) {
        if (other == &level || !has_key(*other, key)) continue;
        homes += (homes.empty() ? "" : ui_message("scene_hint_or")) + home(*other);
        in_material = in_material || other == &material_level();
    }
    if (homes.empty()) return "";
    std::string hint = ui_message("scene_hint_belongs", {{"key", std::string(key)}, {"homes", homes}});
    if (in_material && level.has_material) hint += ui_message("scene_hint_by_index_" + std::string(level.id));
    return hint;
}

std::string did_you_mean(std::string_view key) { return ui_message("scene_hint_did_you_mean", {{"key", std::string(key)}}); }

}  // namespace

const Level& scene_level() {
    static const Level level{"scene",
                             {"name", "z_E", "background", "shadows", "spheres", "planes", "lights", "materials"},
                             {{"title", "name"},
                              {"pane", "z_E"},
                              {"bg", "background"},
                              {"colour", "background"},
                              {"color", "background"},
                              {"shadow", "shadows"},
                              {"objects", "spheres"},
                              {"sphere", "spheres"},
                              {"plane", "planes"},
                              {"light", "lights"},
                              {"material", "materials"}}};
    return level;
}

const Level& sphere_level() {
    static const Level level{"sphere",
                             {"S", "r", "material"},
                             {{"radius", "r"},
                              {"center", "S"},
                              {"centre", "S"},
                              {"position", "S"},
                              {"pos", "S"},
                              {"mat", "material"}},
                             true};
    return level;
}

const Level& plane_level() {
    static const Level level{"plane",
                             {"Q", "n", "material"},
                             {{"point", "Q"}, {"position", "Q"}, {"pos", "Q"}, {"normal", "n"}, {"mat", "material"}},
                             true};
    return level;
}

const Level& light_level() {
    static const Level level{"light",
                             {"L", "I", "colour"},
                             {{"position", "L"},
                              {"pos", "L"},
                              {"intensity", "I"},
                              {"power", "I"},
                              {"brightness", "I"},
                              {"color", "colour"}}};
    return level;
}

// In a material 'n' is the exponent (the n), not a plane's normal.
const Level& material_level() {
    static const Level level{"material",
                             {"ambient", "diffuse", "specular", "exponent", "colour"},
                             {{"ka", "ambient"},
                              {"k_a", "ambient"},
                              {"kd", "diffuse"},
                              {"k_d", "diffuse"},
                              {"ks", "specular"},
                              {"k_s", "specular"},
                              {"n", "exponent"},
                              {"shininess", "exponent"},
                              {"phong", "exponent"},
                              {"exp", "exponent"},
                              {"color", "colour"}}};
    return level;
}

const Level* element_level(std::string_view array) {
    return array == "spheres"     ? &sphere_level()
           : array == "planes"    ? &plane_level()
           : array == "lights"    ? &light_level()
           : array == "materials" ? &material_level()
                                  : nullptr;
}

bool has_key(const Level& level, std::string_view key) {
    return std::find(level.keys.begin(), level.keys.end(), key) != level.keys.end();
}

// A common other name for a key of this level (before the levels a key
// belongs to: in a material 'n' is the exponent), the level a known key
// belongs to, a key differing only in case, or a key within edit distance 2
// (that is not a complete rewrite of it); else the allowed keys. 'color'
// where no colour belongs (a sphere, a plane) is spelled out, then where
// 'colour' belongs: an alias would suggest a key the object does not have.
std::string unknown_key_hint(const std::string& key, const Level& level) {
    const std::string lower = lowercase(key);
    for (const Alias& alias : level.aliases) {
        if (alias.alias == lower) return did_you_mean(alias.key);
    }
    if (std::string hint = belongs_hint(key, level); !hint.empty()) return hint;
    if (lower == "color")
        return ui_message("scene_hint_colour_spelling", {{"belongs", belongs_hint("colour", level)}});
    for (std::string_view known : level.keys) {
        if (lowercase(known) == lower) return did_you_mean(known);
    }
    std::string_view best;
    std::size_t best_distance = 3;
    for (std::string_view known : level.keys) {
        const std::size_t distance = edit_distance(key, known);
        if (distance < best_distance && distance < std::max(key.size(), known.size())) {
            best = known;
            best_distance = distance;
        }
    }
    if (!best.empty()) return did_you_mean(best);
    std::string list;
    for (std::string_view known : level.keys) list += (list.empty() ? "'" : ", '") + std::string(known) + "'";
    return ui_message("scene_hint_keys", {{"level", ui_message("scene_of_" + std::string(level.id))}, {"keys", list}});
}

}  // namespace promyk::scene_detail
