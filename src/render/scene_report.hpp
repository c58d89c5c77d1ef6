// What `promyk scene check` says of a scene: what it contains, the stages
// the engine will run for it (and those it skips, and why), and warnings
// about scenes that are legal but surprising.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace promyk {

struct SceneReport {
    std::vector<std::string> contents;  // "1 sphere: S = (0, 0, 3.2), r = 1.1", ...
    std::vector<std::string> stages;    // what runs for every pixel, in order
    std::vector<std::string> skipped;   // what does not run, and why
    std::vector<std::string> warnings;  // legal but surprising
};

// Examines the scene; the warnings that depend on what the pixels see come
// from tracing a `probe_w` × `probe_w` pane.
SceneReport report_scene(const Scene& scene, int probe_w = 64);

}  // namespace promyk
