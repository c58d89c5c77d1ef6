#include "render/trace_pixel.hpp"

#include <nlohmann/json.hpp>

#include "render/kernel.hpp"
#include "render/quantize.hpp"
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

PixelTrace trace_pixel(const Scene& scene, int w, int i, int j) {
    return make_kernel(scene)->trace(trace_header(scene, w), i, j);
}

}  // namespace promyk
