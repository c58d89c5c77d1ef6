// The objects of the scene format, their keys and the hint after "unknown
// key 'k'": a common other name, the object a key belongs in, a typo's
// nearest key, or the keys allowed. Words in the run's language.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace promyk::scene_detail {

struct Alias {
    std::string_view alias;  // lower case
    std::string_view key;
};

struct Level {
    std::string_view id;                 // "scene", "sphere", ...: messages scene_home_ID, scene_of_ID
    std::vector<std::string_view> keys;  // in the documented order
    std::vector<Alias> aliases;          // common other names for the keys
    bool has_material = false;           // an object: it names a material by its index
};

const Level& scene_level();
const Level& sphere_level();
const Level& plane_level();
const Level& light_level();
const Level& material_level();

// The level of an element of the top-level array `array`; nullptr for others.
const Level* element_level(std::string_view array);

bool has_key(const Level& level, std::string_view key);

// The hint after "unknown key 'k'" in an object of `level`.
std::string unknown_key_hint(const std::string& key, const Level& level);

}  // namespace promyk::scene_detail
