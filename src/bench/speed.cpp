#include "bench/speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "bench/article_literal.hpp"
#include "bench/cpu_pinning.hpp"
#include "render/quantize.hpp"
#include "render/renderer.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"

namespace promyk::bench {

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

template <class F>
double seconds_of(F&& work) {
    const auto start = Clock::now();
    work();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Keeps the image in memory, row after row, for comparison.
class MemorySink final : public RenderSink {
public:
    explicit MemorySink(std::uint8_t* pixels, int w) : out_(pixels), w_(w) {}
    void image_rows(const std::uint8_t* rows, int count) override {
        const std::size_t bytes = static_cast<std::size_t>(count) * w_;
        std::memcpy(out_, rows, bytes);
        out_ += bytes;
    }

private:
    std::uint8_t* out_;
    int w_;
};

// Writes trace lines to an anonymous temporary file and counts the bytes.
class TraceFileSink final : public RenderSink {
public:
    TraceFileSink() : file_(std::tmpfile(), &std::fclose) {
        if (!file_) throw OutputError("bench: cannot create a temporary file for the traces");
    }
    void image_rows(const std::uint8_t*, int) override {}
    void trace_lines(std::string_view lines) override {
        if (std::fwrite(lines.data(), 1, lines.size(), file_.get()) != lines.size())
            throw OutputError("bench: cannot write the temporary traces file");
        bytes_ += lines.size();
    }
    void finish() {
        if (std::fflush(file_.get()) != 0) throw OutputError("bench: cannot write the temporary traces file");
    }
    double bytes() const { return static_cast<double>(bytes_); }

private:
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
    std::size_t bytes_ = 0;
};

LiteralScene literal_scene(const ArticleWorld<double>& world) {
    return {world.S.x, world.S.y, world.S.z, world.r, world.L.x, world.L.y, world.L.z, world.I, world.z_E,
            world.background};
}

// The literal program's t[i, j] as the image's grey levels, for comparison.
std::vector<std::uint8_t> to_bytes(const std::vector<double>& t) {
    std::vector<std::uint8_t> bytes(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) bytes[k] = to_byte(t[k]);
    return bytes;
}

// A ratio of two timings is meaningful only when each timed run is long
// enough for the clock and the scheduler to be noise.
constexpr double min_timed_seconds = 0.020;

}  // namespace

int run_speed_bench(const SpeedOptions& options) {
    const Scene scene = article_scene();
    const ArticleWorld<double> world = article_world(scene);
    const LiteralScene literal = literal_scene(world);
    const int w = options.w;
    const int threads = resolve_threads(options.threads);
    const double pixels = static_cast<double>(w) * w;
    std::vector<double> literal_t;
    literal_render(literal, w, literal_t);  // untimed: allocates and touches t[i, j] once
    std::vector<std::uint8_t> engine_image(literal_t.size());
    std::vector<std::uint8_t> threaded_image(literal_t.size());

    // Single-thread runs visit every core in turn, the literal program and the
    // engine on the same core, so their ratio compares like with like.
    std::vector<int> cpus = allowed_cpus();
    const bool pinned = !cpus.empty();
    if (!pinned) cpus = {-1};
    struct CoreTimes {
        std::vector<double> literal, engine;
    };
    std::vector<CoreTimes> per_core(cpus.size());
    std::vector<double> ratios, threaded_times;

    fmt::print("promyk bench speed: the article's scene, w = {} ({} pixels), {} alternating round{}, medians\n", w,
               w * static_cast<long>(w), options.repetitions, options.repetitions == 1 ? "" : "s");
    fmt::print(
        "  literal: the article's program compiled from the pseudocode (one file, t[i, j] of doubles);\n"
        "  engine: promyk's renderer, including the conversion of every intensity to an 8-bit grey level\n\n");
    std::fflush(stdout);
    for (int round = 0; round < options.repetitions; ++round) {
        for (std::size_t c = 0; c < cpus.size(); ++c) {
            throw_if_interrupted();
            std::optional<PinnedToCpu> pin;
            if (pinned) pin.emplace(cpus[c]);
            const double t_literal = seconds_of([&] { literal_render(literal, w, literal_t); });
            const double t_engine = seconds_of([&] {
                MemorySink sink(engine_image.data(), w);
                render(scene, {w, 1}, PixelSelection{}, sink);
            });
            per_core[c].literal.push_back(t_literal);
            per_core[c].engine.push_back(t_engine);
            ratios.push_back(t_engine / t_literal);
        }
        threaded_times.push_back(seconds_of([&] {
            MemorySink sink(threaded_image.data(), w);
            render(scene, {w, threads}, PixelSelection{}, sink);
        }));
    }
    const std::vector<std::uint8_t> literal_image = to_bytes(literal_t);
    const bool identical = engine_image == literal_image && threaded_image == literal_image;
    const double t_threaded = median(threaded_times);

    const auto ns_per_pixel = [&](double seconds) { return seconds / pixels * 1e9; };
    double shortest = t_threaded;
    for (const CoreTimes& core : per_core)
        shortest = std::min({shortest, median(core.literal), median(core.engine)});
    const bool timeable = shortest >= min_timed_seconds;
    fmt::print("  single thread          literal ns/pixel  engine ns/pixel  engine/literal\n");
    double throughput_sum = 0;  // pixels per second, summed over cores
    for (std::size_t c = 0; c < cpus.size(); ++c) {
        const double t_literal = median(per_core[c].literal), t_engine = median(per_core[c].engine);
        throughput_sum += 1 / t_engine;
        fmt::print("  {:<22} {:>16.2f} {:>16.2f} {:>15}\n", pinned ? fmt::format("on core {}", cpus[c]) : "any core",
                   ns_per_pixel(t_literal), ns_per_pixel(t_engine),
                   timeable ? fmt::format("{:.3f}", t_engine / t_literal) : "-");
    }
    const double t_one = 1 / (throughput_sum / static_cast<double>(cpus.size()));  // the average core
    fmt::print("  engine, {} thread{}: {:.2f} ns/pixel\n\n", threads, threads == 1 ? "" : "s",
               ns_per_pixel(t_threaded));

    if (!timeable) {
        // Time grows with w²: the pane that would make the shortest run long enough.
        const double needed = w * std::sqrt(min_timed_seconds / std::max(shortest, 1e-9));
        const int suggestion = std::min(32768, (static_cast<int>(needed) / 256 + 1) * 256);
        fmt::print(
            "  no ratios: a timed run took {:.2f} ms, and a ratio needs every timed run to take at least {:.0f} ms;\n"
            "  time a larger pane (--w {} or more)\n",
            shortest * 1e3, min_timed_seconds * 1e3, suggestion);
    } else {
        fmt::print("  engine / literal, 1 thread (median over rounds and cores): {:.3f}   (target <= 1.05)\n",
                   median(ratios));
        fmt::print(
            "  {} threads / 1 thread speed-up (1 thread: the average core): {:.2f}   (target >= 1.8 on 2 cores)\n",
            threads, t_one / t_threaded);
        if (pinned && threads == static_cast<int>(cpus.size()))
            fmt::print("  parallel efficiency (threaded throughput / sum of the cores' own): {:.2f}\n",
                       (1 / t_threaded) / throughput_sum);
    }
    fmt::print("  images identical (engine, threaded, literal): {}\n\n", identical ? "yes" : "NO");
    std::fflush(stdout);

    const int tw = options.trace_w;
    TraceFileSink trace_sink;
    const double t_traces = seconds_of([&] {
        render(scene, {tw, threads}, PixelSelection::all(), trace_sink);
        trace_sink.finish();
    });
    const double trace_pixels = static_cast<double>(tw) * tw;
    fmt::print("  traces, JSON Lines of every pixel at w = {}, {} thread{}, to a temporary file:\n", tw, threads,
               threads == 1 ? "" : "s");
    fmt::print("    {:.0f} pixels/s, {:.1f} MB/s, {:.0f} bytes a pixel\n", trace_pixels / t_traces,
               trace_sink.bytes() / t_traces / 1e6, trace_sink.bytes() / trace_pixels);
    return identical ? 0 : 1;
}

}  // namespace promyk::bench
