#include "bench/accuracy.hpp"
#include "bench/bench_text.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/timing.hpp"
#include "render/renderer.hpp"
#include "scene/scene_json.hpp"
#include "trace/json_text.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/interrupt.hpp"
#include "util/text_table.hpp"
#include "util/wrap.hpp"

namespace promyk::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The length aimed at for each timed run at the default pane; it grows with
// w², so --w scales the timing as it scales the errors' work.
constexpr double target_seconds_at_default_w = 0.040;

double median(std::vector<double> values) { return median_of(std::move(values)); }

// Runs work(k, thread) for k = 0 .. count-1 on `threads` threads, the k
// handed out one at a time (as the renderer hands out rows). Stops early
// when a signal asks to; the caller checks throw_if_interrupted().
template <class Work>
void parallel_for(int count, int threads, Work&& work) {
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::atomic<bool> failed{false};
    auto worker = [&](int thread) {
        try {
            for (int k = next++; k < count && !failed && interrupt_signal() == 0; k = next++) work(k, thread);
        } catch (...) {
            if (!failed.exchange(true)) failure = std::current_exception();
        }
    };
    const int n = std::max(1, std::min(threads, count));
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker, t);
    worker(0);
    for (std::thread& thread : pool) thread.join();
    if (failure) std::rethrow_exception(failure);
}

// A rendering job timed round after round: the whole pane at its own size
// (side × side pixels, rows handed out to the threads as the renderer does),
// chosen so that a run takes about the target time. Every combination thus
// renders the scene's whole framing: the same share of misses, dark and lit
// pixels, whatever the pane's size (rows of a pane would not be: a few rows
// across a sphere's middle hit it more often than the pane does).
struct TimedJob {
    const Kernel* kernel = nullptr;
    int side = 0;

    void run(int threads) const {
        std::vector<std::vector<std::uint8_t>> buffers(static_cast<std::size_t>(std::max(1, threads)),
                                                       std::vector<std::uint8_t>(static_cast<std::size_t>(side)));
        parallel_for(side, threads, [&](int i, int thread) {
            kernel->row(side, i, buffers[static_cast<std::size_t>(thread)].data());
        });
        throw_if_interrupted();
    }
    double pixels() const { return static_cast<double>(side) * side; }
};

// The smallest pane whose rendering would take about `seconds` at a cost per
// pixel (at least 4 × 4, so the framing still shows; at most the largest pane).
int side_for(double seconds, double seconds_per_pixel) {
    const double side = std::sqrt(seconds / std::max(seconds_per_pixel, 1e-12));
    return static_cast<int>(std::clamp(std::lround(side), 4L, 32768L));
}

// The scene's numbers as the trace's "given" line writes them: in Polish a
// decimal comma, so a semicolon between values.
std::string separator() { return coordinate_separator(ui_language()); }

std::string value_text(double value) { return number_text(value, ui_language()); }

// "z_E = 2, S = (0, 0, 3.2), r = 1.1, L = (1.5, 1, 1), I = 1" (one sphere, one light).
std::string scene_parameters(const Scene& scene) {
    std::string text = "z_E = " + value_text(scene.z_E);
    for (const Sphere& s : scene.spheres)
        text += separator() + "S = " + point_text(s.S, ui_language()) + separator() + "r = " + value_text(s.r);
    for (const Light& l : scene.lights)
        text += separator() + "L = " + point_text(l.L, ui_language()) + separator() + "I = " + value_text(l.I);
    return text;
}

// An error in the table: three significant digits, 0 as "0", infinity as "inf".
std::string error_text(double e) {
    if (e == 0) return "0";
    if (!std::isfinite(e)) return "inf";
    return local_number_text(fmt::format("{:.2e}", e), ui_language());
}

void append_error(std::string& out, double e) {
    json_text::append_number(out, std::isfinite(e) ? e : NAN);  // infinity: null
}

}  // namespace

Scene far_sphere_scene() {
    Scene scene;
    scene.name = "far_sphere";
    scene.z_E = 8000;
    scene.spheres.push_back({{0, 0, 1e4}, 1.0});
    scene.lights.push_back({{5000, 5000, 0}, 1.0});
    scene.source = "built-in (promyk bench accuracy)";
    return scene;
}

PaneValues pane_values(const Kernel& kernel, int w, int threads) {
    PaneValues values;
    values.w = w;
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(w);
    values.I.assign(n, 0);
    values.exact.assign(n, 0);
    values.branch.assign(n, Branch::miss);
    parallel_for(w, resolve_threads(threads), [&](int i, int) {
        for (int j = 0; j < w; ++j) {
            const std::size_t k = static_cast<std::size_t>(i) * static_cast<std::size_t>(w) + static_cast<std::size_t>(j);
            values.exact[k] = kernel.exact_intensity(w, i, j, &values.branch[k]).x;
            values.I[k] = static_cast<double>(values.exact[k]);
        }
    });
    throw_if_interrupted();
    return values;
}

ErrorStats compare_to_reference(const PaneValues& run, const PaneValues& reference) {
    ErrorStats stats;
    stats.pixels = static_cast<long long>(reference.I.size());
    std::vector<double> sphere_errors;
    for (std::size_t k = 0; k < reference.I.size(); ++k) {
        const bool finite = std::isfinite(run.I[k]) && std::isfinite(reference.I[k]);
        const bool exact = run.exact.size() == run.I.size() && reference.exact.size() == reference.I.size();
        const double error = !finite ? INFINITY
                             : exact ? static_cast<double>(fabsq(run.exact[k] - reference.exact[k]))
                                     : std::fabs(run.I[k] - reference.I[k]);
        if (!finite) ++stats.non_finite;
        stats.max_error = std::max(stats.max_error, error);
        if (run.branch[k] != reference.branch[k]) ++stats.branch_differs;
        if (reference.branch[k] != Branch::miss) sphere_errors.push_back(error);
    }
    stats.sphere_pixels = static_cast<long long>(sphere_errors.size());
    stats.median_error = median(std::move(sphere_errors));
    return stats;
}

AccuracyReport run_accuracy_bench(const AccuracyOptions& options) {
    const auto started = Clock::now();
    AccuracyReport report;
    report.w = options.w;
    report.threads = resolve_threads(options.threads);
    report.rounds = options.repetitions;
    const int w = options.w;
    const double pixels = static_cast<double>(w) * w;
    const AccuracyOptions defaults;
    // At least a little over the shortest run that counts, so that most
    // jobs need no repetition (a pane at its own size is one unit of work).
    const double target = std::max(TimingPolicy{}.min_run_seconds * 1.25,
                                   target_seconds_at_default_w * pixels / (static_cast<double>(defaults.w) * defaults.w));
    report.target_ms = target * 1e3;

    Scene article = article_scene();
    article.name = "article";
    report.scenes.push_back({"article", article, 0});
    report.scenes.push_back({"far_sphere", far_sphere_scene(), 0});

    // The errors' work, in pixel-samples, for the progress: every selected
    // combination and the reference, at every spp, on both scenes.
    const long combinations = static_cast<long>(options.reals.size() * options.formulas.size());
    long total_work = 0;
    for (const int spp : options.spps) total_work += 2 * (combinations + 1) * spp;
    long work_done = 0;
    auto report_progress = [&](std::string_view phase, long done, long total) {
        if (options.progress) options.progress(phase, done, total);
    };

    // The errors, scene by scene and spp by spp, against quad/geometric at the
    // same spp; each pass's time gives a first estimate of the combination's cost.
    std::vector<std::unique_ptr<Kernel>> kernels;  // kept for the timing
    std::vector<TimedJob> jobs;
    std::vector<double> estimates;  // seconds per pixel, from the errors' pass
    std::vector<std::size_t> row_job;
    std::vector<std::size_t> base_job(report.scenes.size());
    auto add_job = [&](std::unique_ptr<Kernel> kernel, double seconds_per_pixel) {
        // Timed as `promyk render` runs without --stats (and bench speed and
        // effects time it): only the non-finite pixels counted.
        kernel->set_branch_counting(false);
        jobs.push_back({kernel.get(), 0});
        kernels.push_back(std::move(kernel));
        estimates.push_back(seconds_per_pixel);
        return jobs.size() - 1;
    };
    auto timed_values = [&](const Kernel& kernel, double* seconds_per_pixel) {
        const auto start = Clock::now();
        PaneValues values = pane_values(kernel, w, report.threads);
        *seconds_per_pixel = std::chrono::duration<double>(Clock::now() - start).count() / pixels;
        return values;
    };
    report_progress("errors", 0, total_work * static_cast<long>(pixels));
    for (std::size_t s = 0; s < report.scenes.size(); ++s) {
        const Scene& scene = report.scenes[s].scene;
        bool base_found = false;
        for (const int spp : options.spps) {
            double reference_cost = 0;
            const PaneValues reference =
                timed_values(*make_kernel(scene, RealType::quad_, Formula::geometric, spp), &reference_cost);
            work_done += spp;
            report_progress("errors", work_done * static_cast<long>(pixels), total_work * static_cast<long>(pixels));
            for (const RealType real : options.reals) {
                for (const Formula formula : options.formulas) {
                    std::unique_ptr<Kernel> kernel = make_kernel(scene, real, formula, spp);
                    // The reference's own combination is not computed twice:
                    // its values are the reference's (errors 0 by construction).
                    const bool is_reference = real == RealType::quad_ && formula == Formula::geometric;
                    double cost = reference_cost;
                    const PaneValues values = is_reference ? reference : timed_values(*kernel, &cost);
                    AccuracyRow row;
                    row.scene = s;
                    row.spp = spp;
                    row.real = real;
                    row.formula = formula;
                    row.errors = compare_to_reference(values, reference);
                    report.rows.push_back(row);
                    const bool is_base = spp == 1 && real == RealType::double_ && formula == Formula::article;
                    row_job.push_back(add_job(std::move(kernel), cost));
                    if (is_base) base_job[s] = row_job.back(), base_found = true;
                    work_done += spp;
                    report_progress("errors", work_done * static_cast<long>(pixels),
                                    total_work * static_cast<long>(pixels));
                }
            }
        }
        if (!base_found) {
            // The baseline is timed even when the run leaves it out of its rows.
            std::unique_ptr<Kernel> kernel = make_kernel(scene, RealType::double_, Formula::article, 1);
            double cost = 0;
            timed_values(*kernel, &cost);
            base_job[s] = add_job(std::move(kernel), cost);
        }
    }

    // Each job renders the whole scene on a pane of its own, sized to take
    // about the target: first from the errors' pass, then again from a run
    // long enough to say what a pixel costs (the errors' pass of a fast
    // combination takes well under a millisecond, thread start-up included),
    // so that starting the threads is a small part of every run. The timing
    // helper repeats a run that is still too short (a small --w, a machine
    // busy while the pane was sized).
    const long jobs_count = static_cast<long>(jobs.size());
    const long total_runs = jobs_count * (options.repetitions + 2);
    TimingPolicy policy;
    policy.rounds = options.repetitions;
    std::vector<TimedWork> work;
    report_progress("timing", 0, total_runs);
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        jobs[k].side = side_for(target, estimates[k]);
        work.push_back(repeated([&, k] { jobs[k].run(report.threads); }));
        const Calibration sizing = calibrate(work.back(), policy);
        jobs[k].side = side_for(target, sizing.seconds / (static_cast<double>(sizing.count) * jobs[k].pixels()));
        report_progress("timing", static_cast<long>(k + 1), total_runs);
    }
    policy.progress = [&](long done, long) { report_progress("timing", jobs_count + done, total_runs); };
    const std::vector<Timing> timings = time_side_by_side(work, policy);

    auto ns_per_pixel = [&](std::size_t k) { return timings[k].median_seconds_per_unit / jobs[k].pixels() * 1e9; };
    double shortest = INFINITY;
    report.timeable = true;
    for (const Timing& t : timings) {
        if (t.timed) shortest = std::min(shortest, t.shortest_run_seconds);
        report.timeable = report.timeable && t.timed;
    }
    report.shortest_ms = std::isfinite(shortest) ? shortest * 1e3 : 0;
    report.counted_branches = std::any_of(kernels.begin(), kernels.end(), [](const std::unique_ptr<Kernel>& kernel) {
        return kernel->counts_branches();
    });
    for (std::size_t s = 0; s < report.scenes.size(); ++s)
        report.scenes[s].base_ns_per_pixel = timings[base_job[s]].timed ? ns_per_pixel(base_job[s]) : 0;
    for (std::size_t r = 0; r < report.rows.size(); ++r) {
        AccuracyRow& row = report.rows[r];
        const std::size_t k = row_job[r];
        const Timing& base = timings[base_job[row.scene]];
        row.timed_w = jobs[k].side;
        if (!timings[k].timed) {
            row.untimed = timings[k].problem;
            continue;
        }
        row.ns_per_pixel = ns_per_pixel(k);
        if (base.timed)
            row.ratio = row.ns_per_pixel / report.scenes[row.scene].base_ns_per_pixel;
        else
            row.untimed = ui_message("bench_accuracy_untimed_base", {{"why", base.problem}});
    }
    report.seconds = std::chrono::duration<double>(Clock::now() - started).count();
    return report;
}

std::string accuracy_table(const AccuracyReport& report) {
    const std::string threads = counted(report.threads, "bench_threads");
    std::string out =
        wrap_text(ui_message("bench_accuracy_title",
                             {{"w", std::to_string(report.w)},
                              {"pixels", counted(static_cast<long long>(report.w) * report.w, "bench_pixels")},
                              {"threads", threads},
                              {"rounds", counted(report.rounds, "bench_rounds")}}),
                  2) +
        "\n" +
        wrap_text(
            "  " +
                ui_message("bench_accuracy_explained", {{"threads", threads}, {"target", fixed(report.target_ms, 0)}}) +
                (report.counted_branches ? "" : " " + ui_message("bench_timed_as_render")),
            2) +
        "\n";
    for (std::size_t s = 0; s < report.scenes.size(); ++s) {
        const AccuracyScene& scene = report.scenes[s];
        out += "\n" + wrap_text(ui_message("bench_accuracy_scene", {{"name", scene.name},
                                                                    {"parameters", "  " + scene_parameters(scene.scene)}}),
                                4);
        out += "\n" + wrap_text("  " + ui_message("bench_accuracy_base", {{"ns", fixed(scene.base_ns_per_pixel, 2)}}), 4) +
               "\n";
        TextTable table({{ui_message("bench_col_spp")},
                         {ui_message("bench_col_real"), true},
                         {ui_message("bench_col_formula"), true},
                         {ui_message("bench_col_ns_pixel")},
                         {ui_message("bench_col_x_base")},
                         {ui_message("bench_col_max_error")},
                         {ui_message("bench_col_median")},
                         {ui_message("bench_col_branch_differs")}},
                        2, 2);
        // The reference's sphere pixels depend on the spp only: one line a group.
        std::string sphere_pixels;
        int last_spp = 0;
        for (const AccuracyRow& row : report.rows) {
            if (row.scene != s) continue;
            if (row.spp != last_spp) {
                if (last_spp != 0) table.add_break();
                sphere_pixels += wrap_text("  " + ui_message("bench_accuracy_sphere_pixels",
                                                             {{"spp", std::to_string(row.spp)},
                                                              {"pixels", counted(row.errors.sphere_pixels, "bench_pixels")}}),
                                           4) +
                                 "\n";
            }
            last_spp = row.spp;
            table.add_row({std::to_string(row.spp), std::string(real_type_name(row.real)),
                           std::string(formula_name(row.formula)),
                           row.ns_per_pixel > 0 ? fixed(row.ns_per_pixel, 1) : "-",
                           row.untimed.empty() ? fixed(row.ratio, 2) : "-", error_text(row.errors.max_error),
                           error_text(row.errors.median_error), std::to_string(row.errors.branch_differs)});
        }
        out += table.text() + sphere_pixels;
    }
    bool first = true;
    for (const AccuracyRow& row : report.rows) {
        if (row.untimed.empty()) continue;
        out += first ? "\n" : "";
        first = false;
        const std::string note = ui_message("bench_accuracy_untimed_row", {{"scene", report.scenes[row.scene].name},
                                                                     {"spp", std::to_string(row.spp)},
                                                                     {"real", std::string(real_type_name(row.real))},
                                                                     {"formula", std::string(formula_name(row.formula))},
                                                                     {"why", row.untimed}});
        out += indented(note) + "\n";
    }
    out += "\n" + wrap_text("  " + ui_message("bench_accuracy_took", {{"seconds", fixed(report.seconds, 1)}}), 2) + "\n";
    return out;
}

std::string accuracy_json(const AccuracyReport& report) {
    using json_text::append_number;
    using json_text::append_string;
    std::string out = "{\"bench\":\"accuracy\",\"schema\":1,\"promyk\":";
    append_string(out, PROMYK_VERSION);
    out += fmt::format(",\"w\":{},\"threads\":{},\"repetitions\":{},\"target_ms\":", report.w, report.threads,
                       report.rounds);
    append_number(out, report.target_ms);
    out += ",\"shortest_ms\":";
    append_number(out, report.shortest_ms);
    out += fmt::format(",\"timeable\":{},\"counts_branches\":{},\"seconds\":", report.timeable ? "true" : "false",
                       report.counted_branches ? "true" : "false");
    append_number(out, report.seconds);
    out += ",\"reference\":{\"real\":\"quad\",\"formula\":\"geometric\"}";
    out += ",\"baseline\":{\"real\":\"double\",\"formula\":\"article\",\"spp\":1}";
    out += ",\"scenes\":[";
    for (std::size_t s = 0; s < report.scenes.size(); ++s) {
        const AccuracyScene& scene = report.scenes[s];
        out += s ? ",{\"name\":" : "{\"name\":";
        append_string(out, scene.name);
        out += ",\"scene_content\":";
        out += nlohmann::json::parse(scene_to_json(scene.scene)).dump();
        out += ",\"base_ns_per_pixel\":";
        append_number(out, scene.base_ns_per_pixel);
        out += '}';
    }
    out += "],\"results\":[";
    for (std::size_t r = 0; r < report.rows.size(); ++r) {
        const AccuracyRow& row = report.rows[r];
        const ErrorStats& e = row.errors;
        out += r ? ",{\"scene\":" : "{\"scene\":";
        append_string(out, report.scenes[row.scene].name);
        out += fmt::format(",\"spp\":{},\"real\":\"{}\",\"formula\":\"{}\",\"ns_per_pixel\":", row.spp,
                           real_type_name(row.real), formula_name(row.formula));
        append_number(out, row.ns_per_pixel);
        out += ",\"ratio\":";
        append_number(out, row.untimed.empty() ? row.ratio : NAN);
        if (!row.untimed.empty()) {
            out += ",\"untimed\":";
            append_string(out, row.untimed);
        }
        out += fmt::format(",\"timed_w\":{},\"pixels\":{},\"sphere_pixels\":{},\"max_error\":", row.timed_w,
                           e.pixels, e.sphere_pixels);
        append_error(out, e.max_error);
        out += ",\"median_error\":";
        append_error(out, e.median_error);
        out += fmt::format(",\"branch_differs\":{},\"non_finite\":{}}}", e.branch_differs, e.non_finite);
    }
    out += "]}\n";
    return out;
}

}  // namespace promyk::bench
