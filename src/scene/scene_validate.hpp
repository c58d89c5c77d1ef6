// A parsed scene file to a Scene: each field checked, every fault collected.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "scene/scene_parse.hpp"

namespace promyk::scene_detail {

// The scene, its `source` set; SceneErrors (exit 3) with every fault, the
// first max_reported_faults of them in document order, when there are any.
Scene validate_scene(const ParsedJson& parsed, const std::string& source);

}  // namespace promyk::scene_detail
