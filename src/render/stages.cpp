#include "render/stages.hpp"

#include <algorithm>

namespace promyk {

bool is_coloured(const Scene& scene) {
    if (!is_grey(scene.background)) return true;
    for (const Light& light : scene.lights)
        if (!is_grey(light.colour)) return true;
    auto coloured = [&scene](int material) { return !is_grey(material_of(scene, material).colour); };
    return std::any_of(scene.spheres.begin(), scene.spheres.end(), [&](const Sphere& s) { return coloured(s.material); }) ||
           std::any_of(scene.planes.begin(), scene.planes.end(), [&](const Plane& p) { return coloured(p.material); });
}

namespace {

template <class Test>
bool any_material(const Scene& scene, Test test) {
    for (const Sphere& s : scene.spheres)
        if (test(material_of(scene, s.material))) return true;
    for (const Plane& p : scene.planes)
        if (test(material_of(scene, p.material))) return true;
    return false;
}

}  // namespace

Stages plan_stages(const Scene& scene) {
    Stages stages;
    stages.objects = scene.object_count() > 1;
    stages.planes = !scene.planes.empty();
    stages.ambient = any_material(scene, [](const Material& m) { return m.ambient > 0; });
    stages.phong = any_material(scene, [](const Material& m) { return m.specular > 0; });
    // With one object shadow rays still run when asked: they find no blocker
    // (a sphere cannot shadow its own lit side), and a lesson shows that.
    stages.shadows = scene.shadows;
    stages.colour = is_coloured(scene);
    // The article's kernel computes the program's nearer root and never looks
    // at the other: right only when the eye is outside the sphere, as the
    // article's program assumes (|S|^2 - r^2 > 0 computed as it computes it).
    const bool one_sphere = scene.spheres.size() == 1 && scene.planes.empty();
    const bool eye_outside =
        one_sphere && length_squared(scene.spheres[0].S) - scene.spheres[0].r * scene.spheres[0].r > 0;
    stages.article = one_sphere && eye_outside && scene.lights.size() == 1 && scene.lights[0].colour == white &&
                     is_default(material_of(scene, scene.spheres[0].material)) && !stages.shadows &&
                     !stages.colour;
    return stages;
}

std::vector<StageNote> stage_notes(const Scene& scene, const Stages& stages) {
    auto note = [](const char* id, bool runs) {
        return StageNote{id, runs, std::string(runs ? "stage_why_" : "stage_skip_") + id};
    };
    return {
        note("sphere", !scene.spheres.empty()),
        note("plane", stages.planes),
        note("nearest", stages.objects),
        note("lambert", true),
        note("ambient", stages.ambient),
        note("shadows", stages.shadows),
        note("phong", stages.phong),
        note("colour", stages.colour),
    };
}

std::vector<std::string> effect_ids(const Scene& scene, const Stages& stages) {
    // The article's trace header says "lambert", as it always has: the sphere
    // test is the article's own and goes without saying.
    if (stages.article) return {"lambert"};
    std::vector<std::string> ids;
    for (const StageNote& note : stage_notes(scene, stages))
        if (note.runs) ids.push_back(note.id);
    return ids;
}

}  // namespace promyk
