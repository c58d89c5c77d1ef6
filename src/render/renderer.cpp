#include "render/renderer.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
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

// Rows per band: enough pixels that handing a band to the sink is rare,
// few enough that the ring's buffers stay small (traces are ~1 kB a pixel).
int band_rows(int w, int threads, bool tracing) {
    const long budget = tracing ? (1L << 14) : (1L << 19);
    const long rows = std::max<long>(4L * threads, (budget + w - 1) / w);
    return static_cast<int>(std::min<long>(rows, w));
}

// Bands in flight: the one being delivered and the next ones being drawn.
constexpr int ring_size = 3;

// One band of rows: its pixels, trace lines and counts, and how many of its
// rows are drawn.
struct Band {
    int first_row = 0;
    int count = 0;
    std::unique_ptr<std::uint8_t[]> pixels;  // null when the rows are drawn in place
    std::vector<std::string> traces;
    std::vector<RowCounts> counts;
    std::atomic<int> rows_done{0};

    void start(int first, int rows_per_band, int w) {
        first_row = first;
        count = std::min(rows_per_band, w - first);
        rows_done = 0;
    }
};

// The rows of the pane, drawn by every thread from one counter (one row at a
// time, so the threads stay evenly loaded) into a ring of bands, which the
// calling thread hands to the sink in order. Threads live for the whole
// render and never wait for each other at a band's end: a row waits only
// when its band's buffer is still being delivered. The first failure (or a
// signal) stops every thread.
class RowPipeline {
public:
    // in_place: the sink's image memory (RenderSink::image_memory), or null.
    RowPipeline(const Kernel& kernel, const TraceHeader& header, const PixelSelection& traced, int rows_per_band,
                std::uint8_t* in_place)
        : kernel_(kernel), header_(header), traced_(traced), rows_per_band_(rows_per_band),
          rows_a_claim_(rows_a_claim(header.w, !traced.empty())), in_place_(in_place) {
        const int w = header.w;
        bands_total_ = (w + rows_per_band - 1) / rows_per_band;
        for (int b = 0; b < ring_size; ++b) {
            Band& band = ring_[b];
            // Only the buffers the pane's bands use (one at w <= 1024), left
            // uninitialised: the kernel writes every byte of its rows, and
            // zeroing three RGB bands cost colour scenes about 2.4 MB of
            // page faults and memset a render (bench effects, w = 512).
            if (in_place_ == nullptr && b < bands_total_)
                band.pixels.reset(new std::uint8_t[static_cast<std::size_t>(rows_per_band) * w * kernel.channels()]);
            band.traces.resize(static_cast<std::size_t>(rows_per_band));
            band.counts.resize(static_cast<std::size_t>(rows_per_band));
            if (b < bands_total_) band.start(b * rows_per_band, rows_per_band, w);
        }
    }

    int bands_total() const { return bands_total_; }
    Band& band(int b) { return ring_[b % ring_size]; }

    // A helper thread: draws rows until none is left or the work stops.
    void help() noexcept {
        try {
            for (;;) {
                int i = next_row_.load(std::memory_order_relaxed);
                int n = 0;
                do {
                    if (i >= header_.w) return;
                    n = claimable(i, header_.w);
                } while (!next_row_.compare_exchange_weak(i, i + n));
                if (stopped()) return;
                if (!wait_for_band_buffer(i / rows_per_band_)) return;
                draw(i, n);
            }
        } catch (...) {
            fail();
        }
    }

    // The calling thread: waits until band b is drawn, drawing rows itself
    // meanwhile (only rows whose buffer is free: it is the one that frees
    // them). Returns false if the work stopped.
    bool wait_for_band(int b) {
        Band& waited = band(b);
        while (waited.rows_done.load(std::memory_order_acquire) < waited.count) {
            if (stopped()) return false;
            int i = next_row_.load();
            const int free_rows = std::min(header_.w, (delivered_.load() + ring_size) * rows_per_band_);
            int n = i < free_rows ? claimable(i, free_rows) : 0;
            if (n > 0 && next_row_.compare_exchange_weak(i, i + n)) {
                try {
                    draw(i, n);
                } catch (...) {
                    fail();
                }
                continue;
            }
            const auto drawn = [&] {
                return waited.rows_done.load(std::memory_order_acquire) >= waited.count || stop_.load();
            };
            if (spin_until(drawn)) continue;
            std::unique_lock<std::mutex> lock(mutex_);
            band_drawn_.wait_for(lock, std::chrono::milliseconds(5), drawn);
        }
        return !stopped();
    }

    // After band b went to the sink: its buffer takes band b + ring_size.
    void delivered(int b) {
        const int reused = b + ring_size;
        if (reused < bands_total_) band(b).start(reused * rows_per_band_, rows_per_band_, header_.w);
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            delivered_.store(b + 1);
        }
        buffer_free_.notify_all();
    }

    void stop() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        buffer_free_.notify_all();
        band_drawn_.notify_all();
    }
    long long rows_done() const { return rows_done_.load(std::memory_order_relaxed); }

    // Rethrows a failure, or Interrupted.
    void check() const {
        if (stop_.load()) {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (failure_) std::rethrow_exception(failure_);
        }
        throw_if_interrupted();
    }

private:
    // Waits a short while without sleeping: a wait here is usually shorter
    // than waking a sleeping thread (on a virtual machine, an idle processor
    // takes longer still). True if `ready` came true.
    template <class Ready>
    static bool spin_until(Ready&& ready) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
        while (std::chrono::steady_clock::now() < until) {
            if (ready()) return true;
            std::this_thread::yield();
        }
        return ready();
    }

    bool stopped() const { return stop_.load(std::memory_order_relaxed) || interrupt_signal() != 0; }

    // Waits until band b's buffer is free; false if the work stopped.
    bool wait_for_band_buffer(int b) {
        const auto free = [&] { return delivered_.load() + ring_size > b; };
        while (!free()) {
            if (stopped()) return false;
            if (spin_until([&] { return free() || stop_.load(); })) continue;
            std::unique_lock<std::mutex> lock(mutex_);
            // Timed: a signal sets a flag and notifies nobody.
            buffer_free_.wait_for(lock, std::chrono::milliseconds(5), [&] { return free() || stop_.load(); });
        }
        return !stopped();
    }

    // Rows a thread claims at once: each claim and each count is an atomic
    // the threads share (a cache line passed from core to core), which cost
    // a row of background about as much as drawing it; a few rows a claim,
    // about 16,000 pixels, pay it once (two threads: 0.88 to 0.90 of the
    // cores' sum before, bench speed). One when tracing: a traced row is
    // long work of its own.
    static int rows_a_claim(int w, bool tracing) {
        return tracing ? 1 : std::max(1, std::min(8, (1 << 14) / std::max(1, w)));
    }

    // How many rows from row i one claim takes: at most rows_a_claim_, none
    // at or past `end`, all in row i's band (a band is counted whole).
    int claimable(int i, int end) const {
        const int band_end = (i / rows_per_band_ + 1) * rows_per_band_;
        return std::min({rows_a_claim_, end - i, band_end - i});
    }

    // Rows first .. first + n - 1, all in one band; a signal is heeded
    // between them.
    void draw(int first, int n) {
        Band& into = band(first / rows_per_band_);
        int drawn = 0;
        for (; drawn < n; ++drawn) {
            if (drawn > 0 && stopped()) break;
            draw_row(first + drawn, into);
        }
        rows_done_.fetch_add(drawn, std::memory_order_relaxed);
        // Read before the rows are counted: once the band is complete, the
        // calling thread may deliver it and start the buffer's next band.
        const int count = into.count;
        if (into.rows_done.fetch_add(drawn, std::memory_order_acq_rel) + drawn == count) {
            { const std::lock_guard<std::mutex> lock(mutex_); }  // the waiter is waiting or sees the count
            band_drawn_.notify_all();
        }
    }

    void draw_row(int i, Band& into) {
        const int w = header_.w;
        const int k = i - into.first_row;
        const std::size_t row_bytes = static_cast<std::size_t>(w) * kernel_.channels();
        std::uint8_t* out = in_place_ != nullptr ? in_place_ + static_cast<std::size_t>(i) * row_bytes
                                                 : into.pixels.get() + static_cast<std::size_t>(k) * row_bytes;
        into.counts[k] = kernel_.row(w, i, out);
        if (traced_.row_has_any(i)) trace_row(kernel_, header_, traced_, i, into.traces[k]);
    }

    void fail() noexcept {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (!failure_) failure_ = std::current_exception();
        }
        stop();
    }

    const Kernel& kernel_;
    const TraceHeader& header_;
    const PixelSelection& traced_;
    const int rows_per_band_;
    const int rows_a_claim_;
    std::uint8_t* const in_place_;  // rows drawn straight into the sink's image, or null
    int bands_total_ = 0;
    Band ring_[ring_size];
    std::atomic<int> next_row_{0};
    std::atomic<int> delivered_{0};  // bands handed to the sink
    std::atomic<bool> stop_{false};
    std::atomic<long long> rows_done_{0};
    mutable std::mutex mutex_;
    std::condition_variable band_drawn_, buffer_free_;
    std::exception_ptr failure_;
};

// Helper threads drawing rows beside the calling thread. However the caller
// leaves, the helpers are stopped and joined.
class Helpers {
public:
    Helpers(RowPipeline& pipeline, int count) : pipeline_(pipeline) {
        for (int t = 0; t < count; ++t) threads_.emplace_back([this] { pipeline_.help(); });
    }
    ~Helpers() {
        pipeline_.stop();
        for (std::thread& thread : threads_) thread.join();
    }

private:
    RowPipeline& pipeline_;
    std::vector<std::thread> threads_;
};

// Adds a delivered band's counts; bands arrive in order, so the first
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
    const RowPipeline& pipeline;
    RenderStats& stats;
    ~RowsComputed() { stats.rows_computed = pipeline.rows_done(); }
};

void deliver(Band& band, int w, int spp, RenderSink& sink, RenderStats& stats) {
    count(band, w, spp, stats);
    if (band.pixels) sink.image_rows(band.pixels.get(), band.count);  // else drawn in place
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
    kernel->set_branch_counting(settings.count_branches);
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

    RowPipeline pipeline(kernel, header, traced, rows_per_band, sink.image_memory());
    const RowsComputed rows_computed{pipeline, out_stats};
    const Helpers helpers(pipeline, threads - 1);
    for (int b = 0; b < pipeline.bands_total(); ++b) {
        // The sink's work (PNG compression, trace writing) runs while the
        // helpers draw the next bands.
        if (!pipeline.wait_for_band(b)) {
            pipeline.check();  // throws the failure, or Interrupted
            break;
        }
        deliver(pipeline.band(b), w, kernel.spp(), sink, out_stats);
        pipeline.delivered(b);
    }
}

}  // namespace promyk
