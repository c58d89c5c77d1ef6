#include "render/trace_size.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"
#include "trace/trace.hpp"
#include "util/interrupt.hpp"

namespace promyk {
namespace {

// Calls visit(i, j0, j1) for each run of chosen pixels, row by row, runs
// sorted and disjoint within a row.
template <typename Visit>
void for_each_run(const TracedPixels& traced, int w, Visit&& visit) {
    if (traced.all) {
        for (int i = 0; i < w; ++i)
            if (!visit(i, 0, w - 1)) return;
        return;
    }
    std::vector<std::pair<int, int>> pixels = traced.pixels;
    std::sort(pixels.begin(), pixels.end());
    auto next_pixel = pixels.begin();
    std::vector<std::pair<int, int>> runs;
    for (int i = 0; i < w; ++i) {
        runs.clear();
        for (const PixelRegion& r : traced.regions) {
            if (r.i0 <= i && i <= r.i1) runs.emplace_back(std::max(r.j0, 0), std::min(r.j1, w - 1));
        }
        while (next_pixel != pixels.end() && next_pixel->first < i) ++next_pixel;
        for (; next_pixel != pixels.end() && next_pixel->first == i; ++next_pixel)
            runs.emplace_back(next_pixel->second, next_pixel->second);
        if (runs.empty()) continue;
        std::sort(runs.begin(), runs.end());
        int start = runs.front().first;
        int end = runs.front().second;
        for (std::size_t k = 1; k < runs.size(); ++k) {
            if (runs[k].first <= end + 1) {
                end = std::max(end, runs[k].second);
                continue;
            }
            if (!visit(i, start, end)) return;
            start = runs[k].first;
            end = runs[k].second;
        }
        if (!visit(i, start, end)) return;
    }
}

// The model's parts, in bytes of JSON in double: measured on traces of
// scenes of 1 to 41 spheres, planes and lights whose every test takes its
// longest path (every root computed), with numbers of 16 or 17 digits, and
// raised so that the estimate stays above every one of them (1.15 to 2.4
// times the real size; tests/trace_bound_test.cpp).
struct PartBytes {
    double header;         // the header without the scene's objects
    double per_given;      // each object and light in the header (scene text and given values)
    double sample;         // a sample's own steps: E, the hit, P, N, I_s
    double eye_sphere;     // a sphere tested from the eye
    double eye_plane;      // a plane tested from the eye
    double light;          // a light's own steps: K, |K|², D, cos α, contribution
    double phong;          // a light's Phong steps (R, V, R·V and its squarings up to n), when a material has them
    double shadow_sphere;  // a sphere tested on the way to a light (with P + s₁K and its distance when it blocks)
    double shadow_plane;   // a plane tested on the way to a light
};
constexpr PartBytes double_bytes{1000, 200, 700, 520, 400, 800, 700, 520, 200};

// The most bytes of traces estimate_trace_size builds to measure them.
constexpr double sampling_budget = 64e6;

// A type other than double writes each number again as its own text
// (measured: float 1.3, long double 1.6, quad 1.75 times double's steps).
double real_factor(RealType real) {
    switch (real) {
        case RealType::float_: return 1.45;
        case RealType::long_double: return 1.8;
        case RealType::quad_: return 1.85;
        default: return 1.0;
    }
}

}  // namespace

double pixel_trace_bytes(const Scene& scene, RealType real, int spp) {
    const PartBytes& b = double_bytes;
    const double spheres = static_cast<double>(scene.spheres.size());
    const double planes = static_cast<double>(scene.planes.size());
    const double lights = static_cast<double>(scene.lights.size());
    const double shadow_tests = scene.shadows ? spheres * b.shadow_sphere + planes * b.shadow_plane : 0.0;
    const bool phong = std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [](const Material& m) { return m.specular > 0; });
    const double light = b.light + (phong ? b.phong : 0.0);
    const double sample = b.sample + spheres * b.eye_sphere + planes * b.eye_plane + lights * (light + shadow_tests);
    const double header = b.header + (spheres + planes + lights) * b.per_given;
    return header + real_factor(real) * static_cast<double>(std::max(spp, 1)) * sample;
}

std::int64_t count_traced_pixels(const TracedPixels& traced, int w) {
    if (traced.all) return static_cast<std::int64_t>(w) * w;
    std::int64_t count = 0;
    for_each_run(traced, w, [&](int, int j0, int j1) {
        if (j1 >= j0) count += j1 - j0 + 1;
        return true;
    });
    return count;
}

std::vector<std::pair<int, int>> sample_traced_pixels(const TracedPixels& traced, int w, int samples) {
    const std::int64_t count = count_traced_pixels(traced, w);
    std::vector<std::pair<int, int>> chosen;
    if (count == 0 || samples <= 0) return chosen;
    // Indices into the chosen pixels in row order, spread by the golden
    // ratio's fractional parts: evenly spread, and (unlike evenly spaced
    // indices, which for a whole pane can all fall in column 0, a miss)
    // spread across the columns as well as the rows.
    std::vector<std::int64_t> wanted;
    if (count <= samples) {
        for (std::int64_t k = 0; k < count; ++k) wanted.push_back(k);
    } else {
        const double step = 0.6180339887498949;  // 1/φ
        for (int k = 0; k < samples; ++k) {
            const double position = 0.5 + step * k;
            const double fraction = position - static_cast<double>(static_cast<std::int64_t>(position));
            wanted.push_back(std::min(count - 1, static_cast<std::int64_t>(fraction * static_cast<double>(count))));
        }
        std::sort(wanted.begin(), wanted.end());
        wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    }
    std::size_t k = 0;
    std::int64_t seen = 0;  // chosen pixels before the current run
    for_each_run(traced, w, [&](int i, int j0, int j1) {
        if (j1 < j0) return true;
        const std::int64_t length = j1 - j0 + 1;
        for (; k < wanted.size() && wanted[k] < seen + length; ++k)
            chosen.emplace_back(i, j0 + static_cast<int>(wanted[k] - seen));
        seen += length;
        return k < wanted.size();
    });
    return chosen;
}

TraceSizeEstimate estimate_trace_size(const Scene& scene, int w, const TracedPixels& traced, int samples,
                                      RealType real, Formula formula, int spp) {
    TraceSizeEstimate estimate;
    estimate.pixels = count_traced_pixels(traced, w);
    // Sampling builds whole traces: at most sampling_budget bytes of them,
    // and none when a single pixel's would be larger; then the model's
    // estimate stands for every pixel (an upper bound: misses are smaller).
    const double bound = pixel_trace_bytes(scene, real, spp);
    estimate.bytes_per_trace = bound;
    samples = static_cast<int>(std::min<double>(samples, std::floor(sampling_budget / bound)));
    const auto sample = sample_traced_pixels(traced, w, samples);
    if (sample.empty()) return estimate;
    const std::unique_ptr<Kernel> kernel = make_kernel(scene, real, formula, spp);
    const TraceHeader header = trace_header(scene, w);
    std::string line;
    std::size_t total = 0;
    for (const auto& [i, j] : sample) {
        throw_if_interrupted();
        line.clear();
        append_trace_json(line, kernel->trace(header, i, j));
        total += line.size() + 1;  // the newline
    }
    estimate.bytes_per_trace = static_cast<double>(total) / static_cast<double>(sample.size());
    return estimate;
}

}  // namespace promyk
