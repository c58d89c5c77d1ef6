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
#include "bench/timing.hpp"
#include "render/quantize.hpp"
#include "render/renderer.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/standard_output.hpp"

namespace promyk::bench {

namespace {

using Clock = std::chrono::steady_clock;

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
        if (!file_) throw OutputError(ui_message("bench_temp_create"));
    }
    void image_rows(const std::uint8_t*, int) override {}
    void trace_lines(std::string_view lines) override {
        if (std::fwrite(lines.data(), 1, lines.size(), file_.get()) != lines.size())
            throw OutputError(ui_message("bench_temp_write"));
        bytes_ += lines.size();
    }
    void finish() {
        if (std::fflush(file_.get()) != 0) throw OutputError(ui_message("bench_temp_write"));
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
    std::vector<TimedWork> jobs;  // per core: literal, engine; then the threaded engine
    for (const int cpu : cpus) {
        jobs.push_back([&, cpu](long count) {
            std::optional<PinnedToCpu> pin;
            if (pinned) pin.emplace(cpu);
            for (long k = 0; k < count; ++k) literal_render(literal, w, literal_t);
        });
        jobs.push_back([&, cpu](long count) {
            std::optional<PinnedToCpu> pin;
            if (pinned) pin.emplace(cpu);
            for (long k = 0; k < count; ++k) {
                MemorySink sink(engine_image.data(), w);
                render(scene, {w, 1}, PixelSelection{}, sink);
            }
        });
    }
    jobs.push_back(repeated([&] {
        MemorySink sink(threaded_image.data(), w);
        render(scene, {w, threads}, PixelSelection{}, sink);
    }));

    print_standard_output("promyk bench speed: the article's scene, w = {} ({} pixels),\n  {} alternating round{}, medians\n", w,
               w * static_cast<long>(w), options.repetitions, options.repetitions == 1 ? "" : "s");
    print_standard_output(
        "  literal: the article's program compiled from the pseudocode (one file, t[i, j]\n"
        "  of doubles); engine: promyk's renderer, including the conversion of every\n"
        "  intensity to an 8-bit grey level; each timed run repeats the pane until it\n"
        "  lasts at least {:.0f} ms\n\n",
        TimingPolicy{}.min_run_seconds * 1e3);
    flush_standard_output();
    TimingPolicy policy;
    policy.rounds = options.repetitions;
    const std::vector<Timing> timings = time_side_by_side(jobs, policy);
    const Timing& threaded = timings.back();

    const std::vector<std::uint8_t> literal_image = to_bytes(literal_t);
    const bool identical = engine_image == literal_image && threaded_image == literal_image;
    const auto ns_per_pixel = [&](const Timing& t) { return t.median_seconds_per_unit / pixels * 1e9; };

    print_standard_output("  single thread          literal ns/pixel  engine ns/pixel  engine/literal\n");
    std::vector<double> ratios;
    std::vector<std::string> problems;
    double throughput_sum = 0;  // panes per second, summed over cores
    bool all_timed = threaded.timed;
    if (!threaded.timed) problems.push_back(ui_message("bench_speed_untimed_threaded", {{"why", threaded.problem}}));
    for (std::size_t c = 0; c < cpus.size(); ++c) {
        const Timing& lit = timings[2 * c];
        const Timing& eng = timings[2 * c + 1];
        const std::string where = pinned ? fmt::format("on core {}", cpus[c]) : "any core";
        std::string ratio = "-";
        if (lit.timed && eng.timed) {
            // Per round, the two runs that were taken next to each other.
            for (std::size_t r = 0; r < lit.seconds_per_unit.size(); ++r)
                ratios.push_back(eng.seconds_per_unit[r] / lit.seconds_per_unit[r]);
            throughput_sum += 1 / eng.median_seconds_per_unit;
            ratio = fmt::format("{:.3f}", eng.median_seconds_per_unit / lit.median_seconds_per_unit);
        } else {
            all_timed = false;
            for (const Timing* t : {&lit, &eng})
                if (!t->timed)
                    problems.push_back(ui_message("bench_speed_untimed_core",
                                                  {{"what", t == &lit ? "literal" : "engine"},
                                                   {"where", where},
                                                   {"why", t->problem}}));
        }
        print_standard_output("  {:<22} {:>16} {:>16} {:>15}\n", where,
                   lit.timed ? fmt::format("{:.2f}", ns_per_pixel(lit)) : "-",
                   eng.timed ? fmt::format("{:.2f}", ns_per_pixel(eng)) : "-", ratio);
    }
    if (threaded.timed)
        print_standard_output("  engine, {} thread{}: {:.2f} ns/pixel\n\n", threads, threads == 1 ? "" : "s",
                   ns_per_pixel(threaded));
    else
        print_standard_output("  engine, {} thread{}: -\n\n", threads, threads == 1 ? "" : "s");

    if (!ratios.empty())
        print_standard_output("  engine / literal, 1 thread (median over rounds and cores): {:.3f}\n  (target <= 1.05)\n",
                   median_of(ratios));
    if (all_timed) {
        const double t_one = 1 / (throughput_sum / static_cast<double>(cpus.size()));  // the average core
        print_standard_output("  {} threads / 1 thread speed-up (1 thread: the average core): {:.2f}\n  (target >= 1.8 on 2 cores)\n",
                   threads, t_one / threaded.median_seconds_per_unit);
        if (pinned && threads == static_cast<int>(cpus.size()))
            print_standard_output("  parallel efficiency (threaded throughput / sum of the cores' own): {:.2f}\n",
                       (1 / threaded.median_seconds_per_unit) / throughput_sum);
    }
    for (const std::string& problem : problems) print_standard_output("  {}\n", problem);
    print_standard_output("  images identical (engine, threaded, literal): {}\n\n", identical ? "yes" : "NO");
    flush_standard_output();

    const int tw = options.trace_w;
    TraceFileSink trace_sink;
    const double t_traces = seconds_of([&] {
        render(scene, {tw, threads}, PixelSelection::all(), trace_sink);
        trace_sink.finish();
    });
    const double trace_pixels = static_cast<double>(tw) * tw;
    print_standard_output("  traces, JSON Lines of every pixel at w = {}, {} thread{}, to a temporary file:\n", tw, threads,
               threads == 1 ? "" : "s");
    print_standard_output("    {:.0f} pixels/s, {:.1f} MB/s, {:.0f} bytes a pixel\n", trace_pixels / t_traces,
               trace_sink.bytes() / t_traces / 1e6, trace_sink.bytes() / trace_pixels);
    return identical ? 0 : 1;
}

}  // namespace promyk::bench
