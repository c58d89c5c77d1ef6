#include "render/trace_pixel.hpp"

namespace promyk {

TraceHeader trace_header(const Scene& scene, int w) {
    TraceHeader header;
    header.scene_name = scene.name;
    header.scene_hash = scene_hash(scene);
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
    return trace;
}

PixelTrace trace_pixel(const Scene& scene, int w, int i, int j) {
    return trace_pixel(article_world(scene), trace_header(scene, w), i, j);
}

}  // namespace promyk
