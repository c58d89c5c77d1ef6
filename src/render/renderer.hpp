// Rendering the whole pane: rows are computed in bands by all threads (rows
// handed out one at a time, so the threads stay evenly loaded), then passed
// in order to a sink, band after band. Memory stays a band, not an image.
#pragma once

#include <cstdint>
#include <string_view>

#include "render/pixel_selection.hpp"
#include "render/tracer.hpp"
#include "scene/scene.hpp"

namespace promyk {

class RenderSink {
public:
    virtual ~RenderSink() = default;
    // `count` rows of w grey levels each, top first, in order.
    virtual void image_rows(const std::uint8_t* rows, int count) = 0;
    // JSON Lines of traced pixels, whole lines, in row order (i, then j).
    virtual void trace_lines(std::string_view lines) { (void)lines; }
    // Called after each band with the rows finished so far.
    virtual void progress(int rows_done, int rows_total) { (void)rows_done, (void)rows_total; }
};

struct RenderSettings {
    int w = 512;
    int threads = 0;  // 0: all cores
};

// The number of threads a setting means (0: all cores).
int resolve_threads(int threads);

// Renders row i of the pane into out[0 .. w): the article's pixel loop body.
void render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out);

// Renders the scene; traces the selected pixels. Throws InputError for a scene
// the engine cannot trace and Interrupted when SIGINT or SIGTERM arrives.
void render(const Scene& scene, const RenderSettings& settings, const PixelSelection& traced, RenderSink& sink);

}  // namespace promyk
