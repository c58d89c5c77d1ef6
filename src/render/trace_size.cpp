#include "render/trace_size.hpp"

#include <algorithm>
#include <string>

#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"
#include "trace/trace.hpp"

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

}  // namespace

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
    const auto sample = sample_traced_pixels(traced, w, samples);
    if (sample.empty()) return estimate;
    const std::unique_ptr<Kernel> kernel = make_kernel(scene, real, formula, spp);
    const TraceHeader header = trace_header(scene, w);
    std::string line;
    std::size_t total = 0;
    for (const auto& [i, j] : sample) {
        line.clear();
        append_trace_json(line, kernel->trace(header, i, j));
        total += line.size() + 1;  // the newline
    }
    estimate.bytes_per_trace = static_cast<double>(total) / static_cast<double>(sample.size());
    return estimate;
}

}  // namespace promyk
