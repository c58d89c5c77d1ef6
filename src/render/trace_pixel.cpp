#include "render/trace_pixel.hpp"

#include <nlohmann/json.hpp>

#include "render/quantize.hpp"
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
    for (const Sphere& sphere : scene.spheres) {
        header.given.push_back({"S", sphere.S});
        header.given.push_back({"r", sphere.r});
    }
    for (const Light& light : scene.lights) {
        header.given.push_back({"L", light.L});
        header.given.push_back({"I", light.I});
    }
    header.given.push_back({"background", scene.background.x});
    header.w = w;
    header.z_E = scene.z_E;
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
    return trace_pixel(article_world(scene), trace_header(scene, w), i, j);
}

}  // namespace promyk
