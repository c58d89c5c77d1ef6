// What `promyk scene check` says of a scene: what it contains, the stages
// the engine will run for it (and those it skips, and why), and warnings
// about scenes that are legal but surprising.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace promyk {

struct SceneReport {
    std::vector<std::string> contents;  // "sphere 0: S = (0, 0, 3.2), r = 1.1", ...
    std::vector<std::string> stages;    // what runs for every pixel, in order, and why
    std::vector<std::string> skipped;   // what does not run, and why
    std::vector<std::string> warnings;  // legal but surprising
};

// Examines the scene. The stages are plan_stages' (render/stages.hpp), with
// the reasons of lessons/messages.json in the run's language, as are the
// warnings. Most warnings are
// geometry (a light inside a sphere, a sphere behind the eye, the eye inside
// a sphere or in a plane, a plane outside the pane's view); those that
// depend on what the pixels see (an object no pixel sees, a light no visible
// surface faces, non-finite numbers) come from a `probe_w` × `probe_w` pane
// that scene_report.cpp samples with its own small ray-object code.
SceneReport report_scene(const Scene& scene, int probe_w = 64);

// The report's warning that a number of the scene is too small for float's
// unit vectors (under 1e-12, legal in double), or nothing: what `trace --real
// float` says beside a trace whose K̂ or V̂ come out short.
std::optional<std::string> float_range_warning(const Scene& scene);

}  // namespace promyk
