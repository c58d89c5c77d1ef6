// Rendering the whole pane: every thread draws rows from one counter (one
// row at a time, so the threads stay evenly loaded) into a ring of band
// buffers, which the calling thread passes to a sink in order while the
// others draw on. Memory stays a few bands, not an image.
#pragma once

#include <cstdint>
#include <string_view>

#include "render/kernel.hpp"
#include "render/pixel_selection.hpp"
#include "render/tracer.hpp"
#include "scene/scene.hpp"

namespace promyk {

class RenderSink {
public:
    virtual ~RenderSink() = default;
    // `count` rows of w pixels each (w grey levels, or w r, g, b triples for
    // a coloured scene: image_channels), top first, in order.
    virtual void image_rows(const std::uint8_t* rows, int count) = 0;
    // The whole image's bytes (w rows of w pixels, image_channels each), when
    // the sink keeps it in memory: the rows are then drawn there in place,
    // with no band buffer to copy them from, and image_rows is not called.
    // Null (the default): the rows come through image_rows.
    virtual std::uint8_t* image_memory() { return nullptr; }
    // JSON Lines of traced pixels, whole lines, in row order (i, then j).
    virtual void trace_lines(std::string_view lines) { (void)lines; }
    // Called after each band with the rows finished so far.
    virtual void progress(int rows_done, int rows_total) { (void)rows_done, (void)rows_total; }
};

// What a render did, counted row by row (PRODUCT.md: statistics on request).
struct RenderStats {
    long long rows_computed = 0;  // rows whose pixels were computed (also when interrupted)
    long long primary_rays = 0;   // one per sample: the ray OE through the sample's point (spp 1: the centre)
    long long shadow_rays = 0;    // one per light a hit faces, when the scene asks for shadows
    long long sphere_tests = 0;   // ray-sphere intersection tests (primary and shadow rays)
    long long plane_tests = 0;    // ray-plane intersection tests
    long long skipped = 0;        // pixels proven background without a test (render/silhouette.hpp)
    long long branches[branch_count] = {};  // pixels per Branch (a pixel's is its centre sample's)
    long long disagreeing = 0;  // pixels whose samples took different branches (spp > 1)
    int first_non_finite_i = -1, first_non_finite_j = -1;  // in row order; -1 if none

    long long count(Branch branch) const { return branches[static_cast<int>(branch)]; }
};

// 1 for a grey scene, 3 for a coloured one (an RGB image).
int image_channels(const Scene& scene);

struct RenderSettings {
    int w = 512;
    int threads = 0;  // 0: all cores
    RealType real = RealType::double_;  // the type every number is computed in
    Formula formula = Formula::article;  // the sphere's formula for the eye's rays
    int spp = 1;  // samples per pixel (render/samples.hpp)
    // Count every pixel's branch into RenderStats::branches (render --stats);
    // off, only non-finite pixels are counted there, the rest left 0.
    bool count_branches = true;
};

// The number of threads a setting means (0: all cores).
int resolve_threads(int threads);

// Renders row i of the pane into out[0 .. w): the article's pixel loop body
// (the article's kernel; other scenes' rows are Kernel::row).
RowCounts render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out);

// Renders the scene; traces the selected pixels. Throws InputError for a scene
// the engine cannot trace and Interrupted when a signal asks to stop. `stats`,
// when given, is filled in as the rows are delivered (rows_computed also on
// an interruption).
void render(const Scene& scene, const RenderSettings& settings, const PixelSelection& traced, RenderSink& sink,
            RenderStats* stats = nullptr);

// The same with a kernel made by the caller (a map, render/maps.hpp, made
// for this scene): its rows are what the sink receives; settings.real,
// formula, spp and count_branches are the kernel's (Kernel::counts_branches,
// set by its maker: maps always count), only w and threads are read.
void render(const Kernel& kernel, const Scene& scene, const RenderSettings& settings, const PixelSelection& traced,
            RenderSink& sink, RenderStats* stats = nullptr);

}  // namespace promyk
