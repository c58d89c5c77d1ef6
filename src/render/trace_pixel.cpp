#include "render/tracer.hpp"
#include "trace/trace.hpp"

namespace promyk {

TraceHeader trace_header(const Scene& scene, int w) {
    TraceHeader header;
    header.scene_name = scene.name;
    header.scene_hash = scene_hash(scene);
    header.w = w;
    header.z_E = scene.z_E;
    return header;
}

PixelTrace trace_pixel(const Scene& scene, int w, int i, int j) {
    PixelTrace trace;
    trace.header = trace_header(scene, w);
    trace.header.i = i;
    trace.header.j = j;
    RecordingRecorder recorder;
    const PixelResult<double> result = trace_pixel_ray(article_world(scene), w, i, j, recorder);
    trace.steps = recorder.take_steps();
    trace.branch = result.branch;
    trace.result = result.I_P;
    return trace;
}

}  // namespace promyk
