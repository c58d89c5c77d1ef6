#include "bench/speed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "bench/article_literal.hpp"
#include "bench/bench_text.hpp"
#include "bench/cpu_pinning.hpp"
#include "bench/timing.hpp"
#include "image/quantize.hpp"
#include "render/article_row.hpp"
#include "render/isa.hpp"
#include "render/renderer.hpp"
#include "render/skipping.hpp"
#include "render/world.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/standard_output.hpp"
#include "util/text_table.hpp"
#include "util/wrap.hpp"

namespace promyk::bench {

namespace {

// The engine's settings as `promyk render` runs without --stats: the
// branches are not counted (only non-finite pixels, for its warning).
RenderSettings as_rendered(int w, int threads) {
    RenderSettings settings;
    settings.w = w, settings.threads = threads;
    settings.count_branches = false;
    return settings;
}

// Keeps the image in memory, for comparison: the renderer draws the rows
// there in place (as a program that renders into memory would), so the
// timing has no copy of band buffers in it.
class MemorySink final : public RenderSink {
public:
    explicit MemorySink(std::uint8_t* pixels) : pixels_(pixels) {}
    std::uint8_t* image_memory() override { return pixels_; }
    void image_rows(const std::uint8_t*, int) override {
        throw std::logic_error("MemorySink: the rows are drawn in place");
    }

private:
    std::uint8_t* pixels_;
};

// Counts the trace lines' bytes and keeps nothing: the traces' own cost,
// with no file system in it.
class TraceNullSink final : public RenderSink {
public:
    void image_rows(const std::uint8_t*, int) override {}
    void trace_lines(std::string_view lines) override { bytes_ += lines.size(); }
    std::size_t bytes() const { return bytes_; }

private:
    std::size_t bytes_ = 0;
};

// Writes trace lines to an anonymous temporary file (gone when closed).
class TraceFileSink final : public RenderSink {
public:
    TraceFileSink() : file_(std::tmpfile(), &std::fclose) {
        if (!file_) throw OutputError(ui_message("bench_temp_create"));
    }
    void image_rows(const std::uint8_t*, int) override {}
    void trace_lines(std::string_view lines) override {
        if (std::fwrite(lines.data(), 1, lines.size(), file_.get()) != lines.size())
            throw OutputError(ui_message("bench_temp_write"));
    }
    void finish() {
        if (std::fflush(file_.get()) != 0) throw OutputError(ui_message("bench_temp_write"));
    }

private:
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
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

// --real float beside double on one core: the time ratio, and how far its
// intensities land from double's (untimed: every row of both, in lanes).
void report_float(const ArticleWorld<double>& world, int w, const Timing& float_run, const Timing& double_run,
                  const std::vector<std::uint8_t>& float_image, const std::vector<std::uint8_t>& double_image) {
    const ArticleWorld<float> world_f = world_as<float>(world);
    std::vector<double> I_d(static_cast<std::size_t>(w));
    std::vector<float> I_f(static_cast<std::size_t>(w));
    double largest = 0;
    int at_i = 0, at_j = 0;
    for (int i = 0; i < w; ++i) {
        if ((i & 63) == 0) throw_if_interrupted();
        article_row_intensities(world, w, i, I_d.data());
        article_row_intensities(world_f, w, i, I_f.data());
        for (int j = 0; j < w; ++j) {
            const double d = std::fabs(static_cast<double>(I_f[static_cast<std::size_t>(j)]) - I_d[static_cast<std::size_t>(j)]);
            if (d > largest) largest = d, at_i = i, at_j = j;
        }
    }
    long long grey_differs = 0;
    for (std::size_t k = 0; k < float_image.size(); ++k) grey_differs += float_image[k] != double_image[k];
    const auto line = [](const std::string& text) { print_standard_output("{}\n", indented(text)); };
    line(ui_message("bench_speed_float",
                    {{"ns", float_run.timed ? fixed(float_run.median_seconds_per_unit / (static_cast<double>(w) * w) * 1e9, 2) : "-"},
                     {"ratio", float_run.timed && double_run.timed
                                   ? fixed(float_run.median_seconds_per_unit / double_run.median_seconds_per_unit, 2)
                                   : "-"}}));
    line("  " + ui_message("bench_speed_float_difference",
                           {{"difference", shown_number(largest, ui_language(), 3)},
                            {"i", std::to_string(at_i)},
                            {"j", std::to_string(at_j)},
                            {"pixels", counted(grey_differs, "bench_pixels")}}));
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
    // Every instruction-set path this processor has, each timed single-threaded
    // beside the literal program; the threaded run takes the path in use.
    const Isa in_use = article_isa();
    const std::vector<Isa> paths = supported_isas();
    const std::size_t per_core = 1 + paths.size();  // the literal, then each path
    std::vector<std::vector<std::uint8_t>> engine_images(paths.size(), std::vector<std::uint8_t>(literal_t.size()));
    std::vector<std::uint8_t> threaded_image(literal_t.size());

    // Single-thread runs visit every core in turn, the literal program and the
    // engine on the same core, so their ratio compares like with like.
    std::vector<int> cpus = allowed_cpus();
    const bool pinned = !cpus.empty();
    if (!pinned) cpus = {-1};
    std::vector<TimedWork> jobs;  // per core: literal, engine on each path; then the threaded engine
    for (const int cpu : cpus) {
        jobs.push_back([&, cpu](long count) {
            std::optional<PinnedToCpu> pin;
            if (pinned) pin.emplace(cpu);
            for (long k = 0; k < count; ++k) literal_render(literal, w, literal_t);
        });
        for (std::size_t p = 0; p < paths.size(); ++p)
            jobs.push_back([&, cpu, p](long count) {
                std::optional<PinnedToCpu> pin;
                if (pinned) pin.emplace(cpu);
                set_article_isa(paths[p]);
                for (long k = 0; k < count; ++k) {
                    MemorySink sink(engine_images[p].data());
                    render(scene, as_rendered(w, 1), PixelSelection{}, sink);
                }
                set_article_isa(in_use);
            });
    }
    // The threaded engine without background skipping (every pixel through
    // the kernel), then with it: the two targets, side by side.
    std::vector<std::uint8_t> no_skip_image(literal_t.size());
    jobs.push_back(repeated([&] {
        set_background_skipping(false);
        MemorySink sink(no_skip_image.data());
        render(scene, as_rendered(w, threads), PixelSelection{}, sink);
        set_background_skipping(true);
    }));
    jobs.push_back(repeated([&] {
        MemorySink sink(threaded_image.data());
        render(scene, as_rendered(w, threads), PixelSelection{}, sink);
    }));
    // --real float on the first core, beside the double engine's run there.
    std::vector<std::uint8_t> float_image(literal_t.size());
    const std::size_t double_on_first = 1 + static_cast<std::size_t>(std::find(paths.begin(), paths.end(), in_use) - paths.begin());
    jobs.push_back([&](long count) {
        std::optional<PinnedToCpu> pin;
        if (pinned) pin.emplace(cpus.front());
        for (long k = 0; k < count; ++k) {
            MemorySink sink(float_image.data());
            render(scene, {w, 1, RealType::float_}, PixelSelection{}, sink);
        }
    });

    print_standard_output("{}\n", wrap_text(ui_message("bench_speed_title",
                                                    {{"w", std::to_string(w)},
                                                     {"pixels", counted(w * static_cast<long long>(w), "bench_pixels")},
                                                     {"rounds", counted(options.repetitions, "bench_rounds")}}),
                                         2));
    print_standard_output("{}\n\n", wrap_text("  " + ui_message("bench_speed_explained",
                                                              {{"ms", fixed(TimingPolicy{}.min_run_seconds * 1e3, 0)}}),
                                             2));
    flush_standard_output();
    TimingPolicy policy;
    policy.rounds = options.repetitions;
    const std::vector<Timing> timings = time_side_by_side(jobs, policy);
    const Timing& float_run = timings.back();
    const Timing& threaded = timings[timings.size() - 2];
    const Timing& no_skip = timings[timings.size() - 3];

    const std::vector<std::uint8_t> literal_image = to_bytes(literal_t);
    bool identical = threaded_image == literal_image && no_skip_image == literal_image;
    for (const std::vector<std::uint8_t>& image : engine_images) identical = identical && image == literal_image;
    const auto ns_per_pixel = [&](const Timing& t) { return t.median_seconds_per_unit / pixels * 1e9; };

    TextTable table({{ui_message("bench_col_single_thread"), true},
                     {ui_message("bench_col_literal_ns")},
                     {ui_message("bench_col_engine_ns")},
                     {ui_message("bench_col_engine_over_literal")}});
    std::vector<std::vector<double>> ratios(paths.size());  // by path
    std::vector<std::string> problems;
    double throughput_sum = 0;  // panes per second on the path in use, summed over cores
    bool all_timed = threaded.timed;
    if (!threaded.timed) problems.push_back(ui_message("bench_speed_untimed_threaded", {{"why", threaded.problem}}));
    if (!no_skip.timed) problems.push_back(ui_message("bench_speed_untimed_threaded", {{"why", no_skip.problem}}));
    for (std::size_t c = 0; c < cpus.size(); ++c) {
        const Timing& lit = timings[per_core * c];
        const std::string core = pinned ? ui_message("bench_speed_on_core", {{"cpu", std::to_string(cpus[c])}})
                                        : ui_message("bench_speed_any_core");
        for (std::size_t p = 0; p < paths.size(); ++p) {
            const Timing& eng = timings[per_core * c + 1 + p];
            const std::string where = core + ", " + isa_name(paths[p]);
            std::string ratio = "-";
            if (lit.timed && eng.timed) {
                // Per round, the two runs that were taken next to each other.
                for (std::size_t r = 0; r < lit.seconds_per_unit.size(); ++r)
                    ratios[p].push_back(eng.seconds_per_unit[r] / lit.seconds_per_unit[r]);
                if (paths[p] == in_use) throughput_sum += 1 / eng.median_seconds_per_unit;
                ratio = fixed(eng.median_seconds_per_unit / lit.median_seconds_per_unit, 3);
            } else {
                all_timed = false;
                for (const Timing* t : {&lit, &eng})
                    if (!t->timed)
                        problems.push_back(ui_message(
                            "bench_speed_untimed_core",
                            {{"what", ui_message(t == &lit ? "bench_speed_what_literal" : "bench_speed_what_engine")},
                             {"where", where},
                             {"why", t->problem}}));
            }
            table.add_row({where, lit.timed ? fixed(ns_per_pixel(lit), 2) : "-",
                           eng.timed ? fixed(ns_per_pixel(eng), 2) : "-", ratio});
        }
    }
    print_standard_output("{}", table.text());
    const auto line = [](const std::string& text) { print_standard_output("{}\n", indented(text)); };
    line(ui_message("bench_speed_threaded", {{"threads", counted(threads, "bench_threads")},
                                             {"ns", threaded.timed ? fixed(ns_per_pixel(threaded), 2) : "-"}}));
    line(ui_message("bench_speed_threaded_no_skip",
                    {{"threads", counted(threads, "bench_threads")},
                     {"ns", no_skip.timed ? fixed(ns_per_pixel(no_skip), 2) : "-"}}));
    print_standard_output("\n");
    const char* isa_variable = std::getenv("PROMYK_ISA");
    const bool forced = isa_variable && *isa_variable;
    line(ui_message("bench_speed_path",
                    {{"path", isa_name(in_use)},
                     {"why", ui_message(in_use == supported_isas().back() && !forced
                                            ? "isa_why_widest"
                                            : "isa_why_forced")}}));
    for (std::size_t p = 0; p < paths.size(); ++p)
        if (!ratios[p].empty())
            line(ui_message(paths[p] == in_use ? "bench_speed_ratio" : "bench_speed_ratio_path",
                            {{"path", isa_name(paths[p])}, {"ratio", fixed(median_of(ratios[p]), 3)}}));
    if (all_timed) {
        const double t_one = 1 / (throughput_sum / static_cast<double>(cpus.size()));  // the average core
        line(ui_message("bench_speed_speedup", {{"threads", counted(threads, "bench_threads")},
                                                {"speedup", fixed(t_one / threaded.median_seconds_per_unit, 2)}}));
        // Against the literal program on the average core, as the targets are set.
        double literal_rate = 0;
        for (std::size_t c = 0; c < cpus.size(); ++c) literal_rate += 1 / timings[per_core * c].median_seconds_per_unit;
        const double literal_one = static_cast<double>(cpus.size()) / literal_rate;
        if (no_skip.timed)
            line(ui_message("bench_speed_over_literal",
                            {{"threads", counted(threads, "bench_threads")},
                             {"with", fixed(literal_one / threaded.median_seconds_per_unit, 2)},
                             {"without", fixed(literal_one / no_skip.median_seconds_per_unit, 2)}}));
        if (pinned && threads == static_cast<int>(cpus.size()))
            line(ui_message("bench_speed_efficiency",
                            {{"efficiency", fixed((1 / threaded.median_seconds_per_unit) / throughput_sum, 2)}}));
    }
    for (const std::string& problem : problems) line(problem);
    line(ui_message("bench_speed_identical", {{"answer", ui_message(identical ? "bench_yes" : "bench_no")}}));
    print_standard_output("\n");
    report_float(world, w, float_run, timings[double_on_first], float_image, literal_image);
    print_standard_output("\n");
    flush_standard_output();

    // Every pixel's trace, into a null sink and into a temporary file, side by
    // side: what the traces cost, and what the file system adds.
    const int tw = options.trace_w;
    double trace_bytes = 0;  // one render's lines
    const std::vector<TimedWork> trace_jobs = {
        repeated([&] {
            TraceNullSink sink;
            render(scene, {tw, threads}, PixelSelection::all(), sink);
            trace_bytes = static_cast<double>(sink.bytes());
        }),
        repeated([&] {
            TraceFileSink sink;
            render(scene, {tw, threads}, PixelSelection::all(), sink);
            sink.finish();
        }),
    };
    const std::vector<Timing> trace_timings = time_side_by_side(trace_jobs, policy);
    const double trace_pixels = static_cast<double>(tw) * tw;
    line(ui_message("bench_speed_traces", {{"w", std::to_string(tw)}, {"threads", counted(threads, "bench_threads")}}));
    const char* trace_ids[2] = {"bench_speed_traces_null", "bench_speed_traces_file"};
    for (std::size_t k = 0; k < trace_timings.size(); ++k) {
        const Timing& t = trace_timings[k];
        const auto per_second = [&t](double amount, int decimals) {
            return t.timed ? fixed(amount / t.median_seconds_per_unit, decimals) : std::string("-");
        };
        std::string text = ui_message(trace_ids[k], {{"pixels_per_second", per_second(trace_pixels, 0)},
                                                     {"mb_per_second", per_second(trace_bytes / 1e6, 1)}});
        if (!t.timed) text += " (" + t.problem + ")";
        line("  " + text);
    }
    line("  " + ui_message("bench_speed_traces_size",
                           {{"bytes", fixed(trace_bytes / trace_pixels, 0)}}));
    return identical ? 0 : 1;
}

}  // namespace promyk::bench
