#include "render/trace_pixel.hpp"

#include <nlohmann/json.hpp>

#include "render/kernel.hpp"
#include "image/quantize.hpp"
#include "render/stages.hpp"
#include "scene/scene_json.hpp"

namespace promyk {

TraceHeader trace_header(const Scene& scene, int w) {
    TraceHeader header;
    header.scene_name = scene.name;
    header.scene_hash = scene_hash(scene);
    header.scene_file = scene.source;
    // The scene writer's text, compacted to one line: it grows with the scene
    // format, so the header never has to know the scene's shape.
    header.scene_content = nlohmann::ordered_json::parse(scene_to_json(scene)).dump();
    header.given.push_back({"z_E", scene.z_E});
    // The scene's values the steps use, by the article's names: unambiguous
    // only for one sphere and one light (a lesson on several names the group).
    if (scene.spheres.size() == 1) {
        header.given.push_back({"S", scene.spheres[0].S});
        header.given.push_back({"r", scene.spheres[0].r});
    }
    if (scene.lights.size() == 1) {
        header.given.push_back({"L", scene.lights[0].L});
        header.given.push_back({"I", scene.lights[0].I});
    }
    // Several objects or lights: each one's values, under its group's name.
    if (scene.object_count() > 1 || scene.lights.size() > 1) {
        for (std::size_t k = 0; k < scene.spheres.size(); ++k)
            header.given_groups.push_back(
                {"sphere", static_cast<int>(k), {{"S", scene.spheres[k].S}, {"r", scene.spheres[k].r}}});
        for (std::size_t k = 0; k < scene.planes.size(); ++k)
            header.given_groups.push_back(
                {"plane", static_cast<int>(k), {{"Q", scene.planes[k].Q}, {"n", scene.planes[k].n}}});
        for (std::size_t k = 0; k < scene.lights.size(); ++k)
            header.given_groups.push_back(
                {"light", static_cast<int>(k), {{"L", scene.lights[k].L}, {"I", scene.lights[k].I}}});
    } else if (!scene.planes.empty()) {
        header.given.push_back({"Q", scene.planes[0].Q});
        header.given.push_back({"n", scene.planes[0].n});
    }
    // A light's colour and the materials, when the scene has them.
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        if (scene.lights[k].colour == white) continue;
        GivenGroup* group = nullptr;
        for (GivenGroup& g : header.given_groups)
            if (g.kind == "light" && g.index == static_cast<int>(k)) group = &g;
        if (group != nullptr)
            group->values.push_back({"c", scene.lights[k].colour});
        else
            header.given.push_back({"c", scene.lights[k].colour});
    }
    for (std::size_t k = 0; k < scene.materials.size(); ++k) {
        const Material& m = scene.materials[k];
        header.given_groups.push_back({"material",
                                       static_cast<int>(k),
                                       {{"k_a", m.ambient},
                                        {"k_d", m.diffuse},
                                        {"k_s", m.specular},
                                        {"exponent", static_cast<double>(m.exponent)},
                                        {"m", m.colour}}});
    }
    if (is_grey(scene.background))
        header.given.push_back({"background", scene.background.x});
    else
        header.given.push_back({"background", scene.background});
    header.w = w;
    header.z_E = scene.z_E;
    const Stages stages = plan_stages(scene);
    header.effects = effect_ids(scene, stages);
    if (!stages.article)
        for (const StageNote& note : stage_notes(scene, stages))
            if (!note.runs) header.skipped.emplace_back(note.id, note.reason);
    return header;
}

PixelTrace trace_pixel(const ArticleWorld<double>& world, const TraceHeader& header, int i, int j) {
    PixelTrace trace;
    trace.header = header;
    trace.header.i = i;
    trace.header.j = j;
    RecordingRecorder recorder;
    const PixelResult<double> result = trace_pixel_ray(world, header.w, i, j, recorder);
    trace.steps = recorder.take_steps();
    trace.branch = result.branch;
    trace.result = result.I_P;
    trace.grey = to_byte(result.I_P);
    trace.first_non_finite = first_non_finite_step(trace.steps);
    return trace;
}

PixelTrace trace_pixel(const Scene& scene, int w, int i, int j, RealType real, Formula formula, int spp) {
    return make_kernel(scene, real, formula, spp)->trace(trace_header(scene, w), i, j);
}

}  // namespace promyk
