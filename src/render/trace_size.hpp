// How big a render's traces will be, before writing them: the number of
// traced pixels times the measured size of a few of their traces. A full
// trace at w = 512 is ~150 MB; a command warns before such a file.
#pragma once

#include "geometry/formula.hpp"
#include "math/real.hpp"

#include <cstdint>
#include <utility>
#include <vector>

#include "render/pixel_selection.hpp"
#include "scene/scene.hpp"

namespace promyk {

// The pixels a render traces, as the user chose them (PixelSelection keeps
// them for fast lookup; counting and sampling need them as typed).
struct TracedPixels {
    bool all = false;
    std::vector<std::pair<int, int>> pixels;  // (i, j), duplicates allowed
    std::vector<PixelRegion> regions;         // may overlap
};

// The number of distinct pixels of the w x w pane chosen. O(w · regions).
std::int64_t count_traced_pixels(const TracedPixels& traced, int w);

// Up to `samples` distinct chosen pixels, spread through the selection's
// rows and columns, in row order (i, then j); the same every run.
std::vector<std::pair<int, int>> sample_traced_pixels(const TracedPixels& traced, int w, int samples);

struct TraceSizeEstimate {
    std::int64_t pixels = 0;     // traces to write
    double bytes_per_trace = 0;  // measured on a sample, newline included
    double bytes() const { return static_cast<double>(pixels) * bytes_per_trace; }
};

// The limit on one pixel's trace (trace, lesson, export, the traces diff
// reads) and on a render's --traces file, unless --max-trace-size: a trace
// is held whole in memory (about 1.5 times its JSON) and written out once
// more, so one of 1,000 spheres x 1,000 lights with shadows (about 0.35 GB
// of JSON, 0.6 GB of text) is refused; a whole w = 512 render's traces
// (about 150 MB) is not.
inline constexpr double default_max_trace_size = 250e6;

// Bounds of the model below against a pixel's real trace (tested in
// [trace-size]): at most this many times the real JSON trace of a pixel that
// hits and faces every light, and never below it.
inline constexpr double pixel_trace_bound_factor = 3;

// One pixel's JSON trace (trace --format json, with its newline), estimated
// from the scene's counts alone, before anything is traced: spp samples of
// (every object tested from the eye, and for each light its steps and, with
// shadows, every object tested on the way to it), each part at its
// measured size in `real`. A pixel that misses or faces fewer lights has a
// smaller trace; the estimate is that of one that hits and faces them all.
double pixel_trace_bytes(const Scene& scene, RealType real, int spp);

// The text trace (trace's default layout) is longer than the JSON one by at
// most this factor (measured: about 1.7 with many shadow tests).
inline constexpr double text_trace_factor = 2;

// Traces `samples` of the chosen pixels (trace_pixel + append_trace_json)
// and averages their size; fewer when their model estimates add up to more
// than 64 MB, and none when one pixel's does (bytes_per_trace is then the
// model's). Polls the interrupt flag. InputError for a scene the engine
// cannot trace.
TraceSizeEstimate estimate_trace_size(const Scene& scene, int w, const TracedPixels& traced, int samples = 256,
                                      RealType real = RealType::double_, Formula formula = Formula::article,
                                      int spp = 1);

}  // namespace promyk
