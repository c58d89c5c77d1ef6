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

// Traces `samples` of the chosen pixels (trace_pixel + append_trace_json)
// and averages their size. InputError for a scene the engine cannot trace.
TraceSizeEstimate estimate_trace_size(const Scene& scene, int w, const TracedPixels& traced, int samples = 256,
                                      RealType real = RealType::double_, Formula formula = Formula::article,
                                      int spp = 1);

}  // namespace promyk
