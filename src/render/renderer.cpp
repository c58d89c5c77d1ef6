#include "render/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "render/quantize.hpp"
#include "render/trace_pixel.hpp"
#include "util/interrupt.hpp"

namespace promyk {

int resolve_threads(int threads) {
    if (threads > 0) return threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out) {
    // A local copy: stores through a uint8_t* may alias anything, so reading the
    // scene through a reference would reload it, and keep |S|^2 from being
    // hoisted, on every pixel.
    // y_E is computed once a row: GCC will not hoist a division out of a loop
    // by itself (it might trap), and the result is the same double.
    const ArticleWorld<double> local = world;
    const double y_E = pane_y<double>(i, w);
    NullRecorder none;
    for (int j = 0; j < w; ++j) out[j] = to_byte(trace_ray(local, {pane_x<double>(j, w), y_E, local.z_E}, none).I_P);
}

namespace {

// Appends the selected pixels of row i as JSON Lines.
void trace_row(const ArticleWorld<double>& world, const TraceHeader& header, const PixelSelection& traced, int i,
               std::string& out) {
    for (int j = 0; j < header.w; ++j) {
        if (!traced.contains(i, j)) continue;
        append_trace_json(out, trace_pixel(world, header, i, j));
        out += '\n';
    }
}

// Rows per band: enough pixels that thread start-up is noise, few enough
// that the band's buffers stay small (traces are ~1 kB a pixel).
int band_rows(int w, int threads, bool tracing) {
    const long budget = tracing ? (1L << 14) : (1L << 20);
    const long rows = std::max<long>(4L * threads, (budget + w - 1) / w);
    return static_cast<int>(std::min<long>(rows, w));
}

}  // namespace

void render(const Scene& scene, const RenderSettings& settings, const PixelSelection& traced, RenderSink& sink) {
    const ArticleWorld<double> world = article_world(scene);
    const int w = settings.w;
    const int threads = std::min(resolve_threads(settings.threads), w);
    const int rows_per_band = band_rows(w, threads, !traced.empty());
    const TraceHeader header = trace_header(scene, w);

    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(rows_per_band) * w);
    std::vector<std::string> traces(static_cast<std::size_t>(rows_per_band));

    for (int i0 = 0; i0 < w; i0 += rows_per_band) {
        const int count = std::min(rows_per_band, w - i0);
        std::atomic<int> next_row{0};
        std::exception_ptr failure;
        std::atomic<bool> failed{false};
        auto work = [&] {
            try {
                for (int k = next_row++; k < count && !failed && !interrupt_signal(); k = next_row++) {
                    render_row(world, w, i0 + k, &pixels[static_cast<std::size_t>(k) * w]);
                    if (traced.row_has_any(i0 + k)) trace_row(world, header, traced, i0 + k, traces[k]);
                }
            } catch (...) {
                if (!failed.exchange(true)) failure = std::current_exception();
            }
        };
        std::vector<std::thread> helpers;
        for (int t = 1; t < threads; ++t) helpers.emplace_back(work);
        work();
        for (std::thread& helper : helpers) helper.join();
        if (failure) std::rethrow_exception(failure);
        throw_if_interrupted();

        sink.image_rows(pixels.data(), count);
        for (int k = 0; k < count; ++k) {
            if (traces[k].empty()) continue;
            sink.trace_lines(traces[k]);
            traces[k].clear();
        }
        sink.progress(i0 + count, w);
    }
}

}  // namespace promyk
