#include "render/renderer.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "image/quantize.hpp"
#include "render/trace_pixel.hpp"
#include "trace/trace_lines.hpp"
#include "util/interrupt.hpp"

namespace promyk {

int resolve_threads(int threads) {
    if (threads > 0) return threads;
    // The cores this process may run on (taskset, a container's cpuset), not
    // all the machine has, which is what hardware_concurrency() counts.
    cpu_set_t allowed;
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// render_row: in render/article_row.cpp, beside the article's rows in lanes.

namespace {

// Appends the selected pixels of row i as JSON Lines. The header's shared
// text is written once a row (TraceLines), not once a pixel.
void trace_row(const Kernel& kernel, const TraceHeader& header, const PixelSelection& traced, int i,
               std::string& out) {
    const TraceLines lines(header);
    for (int j = 0; j < header.w; ++j)
        if (traced.contains(i, j)) lines.append(out, kernel.trace(lines.pixel_header(), i, j));
}

// Rows per band: enough pixels that thread start-up is noise, few enough
// that the band's buffers stay small (traces are ~1 kB a pixel).
int band_rows(int w, int threads, bool tracing) {
    const long budget = tracing ? (1L << 14) : (1L << 20);
    const long rows = std::max<long>(4L * threads, (budget + w - 1) / w);
    return static_cast<int>(std::min<long>(rows, w));
}

// One band of rows: its pixels and trace lines, and the counter from which
// every thread takes its next row (one at a time, so threads stay balanced).
struct Band {
    int first_row = 0;
    int count = 0;
    std::vector<std::uint8_t> pixels;
    std::vector<std::string> traces;
    std::vector<RowCounts> counts;
    std::atomic<int> next_row{0};

    void start(int first, int rows_per_band, int w) {
        // w: the pane's side; pixels hold w * channels bytes a row.
        first_row = first;
        count = std::min(rows_per_band, w - first);
        next_row = 0;
    }
    bool last(int w) const { return first_row + count >= w; }
};

// Computes the rows of bands; the first failure (or a signal) stops every thread.
class BandWork {
public:
    BandWork(const Kernel& kernel, const TraceHeader& header, const PixelSelection& traced)
        : kernel_(kernel), header_(header), traced_(traced) {}

    void operator()(Band& band) noexcept {
        const int w = header_.w;
        try {
            for (int k = band.next_row++; k < band.count && !stop_ && !interrupt_signal(); k = band.next_row++) {
                const int i = band.first_row + k;
                const std::size_t row_bytes = static_cast<std::size_t>(w) * kernel_.channels();
                band.counts[k] = kernel_.row(w, i, &band.pixels[static_cast<std::size_t>(k) * row_bytes]);
                if (traced_.row_has_any(i)) trace_row(kernel_, header_, traced_, i, band.traces[k]);
                rows_done_.fetch_add(1, std::memory_order_relaxed);
            }
        } catch (...) {
            if (!stop_.exchange(true)) failure_ = std::current_exception();
        }
    }

    void stop() { stop_ = true; }
    long long rows_done() const { return rows_done_.load(std::memory_order_relaxed); }

    // After the threads are joined: rethrows a failure, or Interrupted.
    void check() const {
        if (failure_) std::rethrow_exception(failure_);
        throw_if_interrupted();
    }

private:
    const Kernel& kernel_;
    const TraceHeader& header_;
    const PixelSelection& traced_;
    std::atomic<bool> stop_{false};
    std::atomic<long long> rows_done_{0};
    std::exception_ptr failure_;
};

// Helper threads working on one band beside the calling thread. If the
// caller leaves by an exception, the helpers are stopped and joined.
class Helpers {
public:
    explicit Helpers(BandWork& work) : work_(work) {}
    ~Helpers() {
        if (threads_.empty()) return;
        work_.stop();
        join();
    }
    void start(int count, Band& band) {
        for (int t = 0; t < count; ++t) threads_.emplace_back([this, &band] { work_(band); });
    }
    void join() {
        for (std::thread& thread : threads_) thread.join();
        threads_.clear();
    }

private:
    BandWork& work_;
    std::vector<std::thread> threads_;
};

// Adds a delivered band's counts; rows arrive in order, so the first
// non-finite pixel found is the first in row order.
void count(const Band& band, int w, int spp, RenderStats& stats) {
    for (int k = 0; k < band.count; ++k) {
        const RowCounts& row = band.counts[k];
        for (int b = 0; b < branch_count; ++b) stats.branches[b] += row.branches[b];
        stats.disagreeing += row.disagreeing;
        stats.shadow_rays += row.shadow_rays;
        stats.sphere_tests += row.sphere_tests;
        stats.plane_tests += row.plane_tests;
        stats.skipped += row.skipped;
        if (row.first_non_finite_j >= 0 && stats.first_non_finite_i < 0) {
            stats.first_non_finite_i = band.first_row + k;
            stats.first_non_finite_j = row.first_non_finite_j;
        }
    }
    stats.primary_rays += static_cast<long long>(band.count) * w * spp;
}

// Writes rows_computed when render() leaves, by return or by exception.
struct RowsComputed {
    const BandWork& work;
    RenderStats& stats;
    ~RowsComputed() { stats.rows_computed = work.rows_done(); }
};

void deliver(Band& band, int w, int spp, RenderSink& sink, RenderStats& stats) {
    count(band, w, spp, stats);
    sink.image_rows(band.pixels.data(), band.count);
    for (int k = 0; k < band.count; ++k) {
        if (band.traces[k].empty()) continue;
        sink.trace_lines(band.traces[k]);
        band.traces[k].clear();
    }
    sink.progress(band.first_row + band.count, w);
}

}  // namespace

int image_channels(const Scene& scene) { return is_coloured(scene) ? 3 : 1; }

void render(const Scene& scene, const RenderSettings& settings, const PixelSelection& traced, RenderSink& sink,
            RenderStats* stats) {
    const std::unique_ptr<Kernel> kernel = make_kernel(scene, settings.real, settings.formula, settings.spp);
    render(*kernel, scene, settings, traced, sink, stats);
}

void render(const Kernel& kernel, const Scene& scene, const RenderSettings& settings, const PixelSelection& traced,
            RenderSink& sink, RenderStats* stats) {
    RenderStats local_stats;
    RenderStats& out_stats = stats != nullptr ? *stats : local_stats;
    out_stats = RenderStats{};
    const int w = settings.w;
    const int threads = std::min(resolve_threads(settings.threads), w);
    const int rows_per_band = band_rows(w, threads, !traced.empty());
    TraceHeader header = trace_header(scene, w);
    header.spp = kernel.spp();

    // Two bands: while the helpers compute one, the calling thread hands the
    // other to the sink (PNG compression, trace writing), then joins them.
    Band bands[2];
    for (Band& band : bands) {
        band.pixels.resize(static_cast<std::size_t>(rows_per_band) * w * kernel.channels());
        band.traces.resize(static_cast<std::size_t>(rows_per_band));
        band.counts.resize(static_cast<std::size_t>(rows_per_band));
    }
    BandWork work(kernel, header, traced);
    const RowsComputed rows_computed{work, out_stats};
    Helpers helpers(work);

    bands[0].start(0, rows_per_band, w);
    helpers.start(threads - 1, bands[0]);
    work(bands[0]);
    helpers.join();
    for (int b = 0;; ++b) {
        work.check();
        Band& done = bands[b % 2];
        Band& next = bands[(b + 1) % 2];
        const bool more = !done.last(w);
        if (more) {
            next.start(done.first_row + done.count, rows_per_band, w);
            helpers.start(threads - 1, next);
        }
        deliver(done, w, kernel.spp(), sink, out_stats);
        if (!more) break;
        work(next);
        helpers.join();
    }
}

}  // namespace promyk
