// What the engine runs for a scene, decided once before the pixel loop
// (PRODUCT.md section 4: only the effects a scene calls for are simulated).
// The article's scene runs the article's kernel and nothing else; each
// extension adds its own stage when, and only when, the scene asks for it.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace promyk {

struct Stages {
    // The article's program, unchanged: one sphere in front of the eye (the
    // eye outside it), one white light, the default material, a grey
    // background, no shadows. Every other flag is then false.
    bool article = false;
    bool objects = false;   // several objects: each is tested, the nearest hit wins
    bool planes = false;    // the plane intersection
    bool ambient = false;   // a material with k_a > 0
    bool shadows = false;   // shadow rays towards each light the hit faces
    bool phong = false;     // a material with k_s > 0: the specular highlight
    bool colour = false;    // three channels instead of one grey level
};

Stages plan_stages(const Scene& scene);

// One stage as the trace and `scene check` name it: its id (also the word in
// the trace header's `effects`), whether it runs, and the id of the message
// (lessons/messages.json) that says why it is skipped.
struct StageNote {
    std::string id;      // "sphere", "plane", "nearest", "lambert", "ambient", "shadows", "phong", "colour"
    bool runs = false;
    std::string reason;  // messages.json id: stage_why_<id> for a run stage, stage_skip_<id> for a skipped one
};

// Every stage in the order the engine runs them, whether it runs or not.
std::vector<StageNote> stage_notes(const Scene& scene, const Stages& stages);

// The ids of the stages that run, in order: the trace header's `effects`.
std::vector<std::string> effect_ids(const Scene& scene, const Stages& stages);

}  // namespace promyk
