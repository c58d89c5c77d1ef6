// A parsed scene file to a Scene: each field checked, every fault collected.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "scene/scene_parse.hpp"

namespace promyk::scene_detail {

// The smallest size of a number other than 0 in a scene's positions and
// lengths (z_E, S, r, Q, L), and the smallest ratio of a plane normal's
// component to its largest: a difference of two such numbers is 0 or at
// least about 1e-66, so the squared lengths the engine divides by (|K|²,
// |V|², r·√|K|²) stay far above double's smallest normal number (2.2e-308)
// and its unit vectors unit. Larger numbers are bounded by the overflow
// checks (a sphere's |S|² − r², a plane's n̂·Q).
inline constexpr double min_scene_magnitude = 1e-50;
// The same bound for float (--real float), whose smallest normal number is
// 1.2e-38: scene check warns below it (the scene is a double's, and fine there).
inline constexpr double min_float_magnitude = 1e-12;

// The scene, its `source` set; SceneErrors (exit 3) with every fault, the
// first max_reported_faults of them in document order, when there are any.
Scene validate_scene(const ParsedJson& parsed, const std::string& source);

}  // namespace promyk::scene_detail
