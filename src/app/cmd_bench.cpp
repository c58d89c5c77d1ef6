// promyk bench: measurements side by side in one run, reported as ratios.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/progress.hpp"
#include "bench/accuracy.hpp"
#include "bench/effects.hpp"
#include "bench/speed.hpp"
#include "render/samples.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/output_file.hpp"
#include "util/printable.hpp"
#include "util/text.hpp"
#include "util/standard_output.hpp"

namespace promyk::app {

namespace {

// The items of a comma-separated list ("1, 4,16"), trimmed; UsageError for an
// empty item, which would otherwise silently mean nothing.
std::vector<std::string> list_items(const std::string& list, const std::string& option) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        std::string item(trim(std::string_view(list).substr(start, comma - start)));
        if (item.empty())
            throw UsageError(ui_message("bench_empty_item", {{"option", option}, {"list", printable(list)}}));
        items.push_back(std::move(item));
        start = comma + 1;
    }
    return items;
}

// The named items of `known` that the list chooses, in `known`'s order.
template <class T>
std::vector<T> chosen(const std::string& list, const std::string& option,
                      const std::vector<std::pair<std::string, T>>& known) {
    std::vector<bool> picked(known.size(), false);
    for (const std::string& item : list_items(list, option)) {
        const auto it = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.first == item; });
        if (it == known.end()) {
            std::string names;
            for (const auto& k : known) names += (names.empty() ? "" : ", ") + k.first;
            throw UsageError(ui_message("bench_unknown_value",
                                        {{"option", option}, {"value", printable(item)}, {"values", names}}));
        }
        picked[static_cast<std::size_t>(it - known.begin())] = true;
    }
    std::vector<T> values;
    for (std::size_t k = 0; k < known.size(); ++k)
        if (picked[k]) values.push_back(known[k].second);
    return values;
}

std::vector<int> chosen_spps(const std::string& list) {
    std::vector<int> spps;
    for (const std::string& item : list_items(list, "--spp")) {
        const int spp = cli::parse_whole_number(item, "--spp", 1, max_spp);
        if (!valid_spp(spp))
            throw UsageError(ui_message("bench_spp_not_square", {{"spp", item}, {"max", std::to_string(max_spp)}}));
        spps.push_back(spp);
    }
    std::sort(spps.begin(), spps.end());
    spps.erase(std::unique(spps.begin(), spps.end()), spps.end());
    return spps;
}

struct AccuracyCommand {
    bench::AccuracyOptions bench;
    std::string spps = "1,4,16,64";
    std::string reals = "float,double,long-double,quad";
    std::string formulas = "article,stable,fma,geometric";
    std::string json;  // empty: no JSON
};

int run_accuracy(AccuracyCommand& command) {
    bench::AccuracyOptions& options = command.bench;
    options.spps = chosen_spps(command.spps);
    options.reals = chosen<RealType>(command.reals, "--real",
                                     {{"float", RealType::float_},
                                      {"double", RealType::double_},
                                      {"long-double", RealType::long_double},
                                      {"quad", RealType::quad_}});
    std::vector<std::pair<std::string, Formula>> formulas;
    for (const Formula f : all_formulas) formulas.emplace_back(std::string(formula_name(f)), f);
    options.formulas = chosen<Formula>(command.formulas, "--formula", formulas);

    // The output is looked at and opened (its temporary created) before the
    // minute of work, so a bad path fails at once and a failure leaves nothing.
    std::optional<OutputFile> json;
    if (!command.json.empty()) json.emplace(command.json);
    const bool json_to_stdout = json && json->target().kind == OutputKind::standard_output;

    std::unique_ptr<Progress> progress;
    std::string phase_shown;
    options.progress = [&](std::string_view phase, long done, long total) {
        if (phase != phase_shown) {
            progress.reset();
            phase_shown = std::string(phase);
            const bool timing = phase_shown == "timing";
            progress = std::make_unique<Progress>(ui_message(timing ? "bench_progress_timing" : "bench_progress_errors"),
                                                  ui_message(timing ? "bench_unit_timed_runs" : "bench_unit_pixel_samples"));
        }
        progress->update(done, total);
    };
    const bench::AccuracyReport report = bench::run_accuracy_bench(options);
    progress.reset();

    // Standard output carries the product: the table, or the JSON with --json -
    // (the table then goes to standard error).
    const std::string table = bench::accuracy_table(report);
    if (json_to_stdout)
        std::fputs(table.c_str(), stderr);
    else
        write_standard_output(table);
    if (json) {
        const std::string text = bench::accuracy_json(report);
        json->write(text);
        json->commit();
        if (!json_to_stdout)
            fmt::print(stderr, "{}\n",
                       ui_message("bench_wrote_json", {{"file", printable(command.json)},
                                                       {"count", std::to_string(report.rows.size())}}));
    }
    return 0;
}

}  // namespace

std::function<int()> setup_bench(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("bench", "Measure what the engine costs, side by side in one run");
    cmd->require_subcommand(1);
    // Set here, else CLI11 copies promyk's own footer, whose 'promyk COMMAND
    // --help' is one level short for bench.
    cmd->footer(
        "Run 'promyk bench speed --help', 'promyk bench effects --help' or\n"
        "'promyk bench accuracy --help' for a measurement's options.\n"
        "Every timed run repeats its work until it lasts at least 20 ms; medians are reported.");
    auto speed = std::make_shared<bench::SpeedOptions>();
    CLI::App* speed_cmd = cmd->add_subcommand(
        "speed", "The engine against the article's literal program, all threads against one, trace writing");
    speed_cmd->add_option("--w", speed->w, "Pane size for the image timings")
        ->type_name("N")
        ->check(whole_number(1, cli::max_w))
        ->capture_default_str();
    speed_cmd->add_option("--repetitions", speed->repetitions, "Alternating rounds (medians are reported)")
        ->type_name("N")
        ->check(whole_number(1, 1000))
        ->capture_default_str();
    add_threads_option(*speed_cmd, speed->threads);
    speed_cmd->add_option("--trace-w", speed->trace_w, "Pane size for the traces' throughput")
        ->type_name("N")
        ->check(whole_number(1, cli::max_w))
        ->capture_default_str();
    speed_cmd->footer(
        "Each timed run renders the pane again and again until it lasts at least 20 ms, so a small\n"
        "--w still gives ratios (a larger pane is closer to real use). A run that cannot be timed\n"
        "leaves its ratio out and says why.");
    auto effects = std::make_shared<bench::EffectsOptions>();
    CLI::App* effects_cmd = cmd->add_subcommand(
        "effects", "What each effect costs: every example scene's time per pixel against the article's scene");
    effects_cmd->add_option("--w", effects->w, "Pane size")
        ->type_name("N")
        ->check(whole_number(1, cli::max_w))
        ->capture_default_str();
    effects_cmd->add_option("--repetitions", effects->repetitions, "Alternating rounds (medians are reported)")
        ->type_name("N")
        ->check(whole_number(1, 1000))
        ->capture_default_str();
    add_spp_option(*effects_cmd, effects->spp);
    effects_cmd->footer(
        "Each timed run renders the pane again and again until it lasts at least 20 ms; × article is\n"
        "a scene's time per pixel over the article's scene's. With --spp N above 1, every scene is\n"
        "also timed at spp 1 in the same rounds, and \"a sample × spp 1\" is its time per sample over\n"
        "its own time per pixel at spp 1 (the target: at most 1.5).\n"
        "Example: promyk bench effects --w 256 --spp 4");
    auto accuracy = std::make_shared<AccuracyCommand>();
    CLI::App* accuracy_cmd = cmd->add_subcommand(
        "accuracy",
        "What precision, formulas and samples cost in time against what they buy: every real type ×\n"
        "formula × spp on the article's scene and a far sphere, time per pixel and error against quad");
    accuracy_cmd
        ->add_option("--w", accuracy->bench.w,
                     "Pane size for the errors (every pixel of every combination); each timed run's length\n"
                     "grows with w² too, so the whole run's does")
        ->type_name("N")
        ->check(whole_number(1, 4096))
        ->capture_default_str();
    add_threads_option(*accuracy_cmd, accuracy->bench.threads);
    accuracy_cmd->add_option("--repetitions", accuracy->bench.repetitions, "Alternating timing rounds (medians are reported)")
        ->type_name("N")
        ->check(whole_number(1, 1000))
        ->capture_default_str();
    accuracy_cmd->add_option("--spp", accuracy->spps, "Samples per pixel to measure, a list of squares")
        ->type_name("LIST")
        ->check(non_empty())
        ->capture_default_str();
    accuracy_cmd->add_option("--real", accuracy->reals, "Real types to measure")
        ->type_name("LIST")
        ->check(non_empty())
        ->capture_default_str();
    accuracy_cmd->add_option("--formula", accuracy->formulas, "Formulas to measure")
        ->type_name("LIST")
        ->check(non_empty())
        ->capture_default_str();
    accuracy_cmd
        ->add_option("--json", accuracy->json,
                     "Also write the results as JSON (src/bench/accuracy.schema.json) to FILE, written\n"
                     "completely or not at all; - for standard output (the table then goes to standard error)")
        ->type_name("FILE")
        ->check(non_empty());
    accuracy_cmd->footer(
        "Scenes: the article's (z_E = 2, S = (0, 0, 3.2), r = 1.1, L = (1.5, 1, 1)) and a far sphere\n"
        "(z_E = 8000, S = (0, 0, 10000), r = 1, L = (5000, 5000, 0)), which the article's formula loses\n"
        "in float. The reference is quad with the geometric formula at the same spp, on the same pixels,\n"
        "computed in the same run.\n"
        "Error: |I - I_ref| of each pixel's intensity (absolute: I is in [0, 1]), taken in quad between\n"
        "the exact values (so a long double's errors show); max over every pixel, median over the sphere's\n"
        "pixels (where the reference does not miss); branch ≠: pixels whose branch (the centre sample's)\n"
        "differs from the reference's.\n"
        "Timing: every combination renders the whole scene on a pane of its own size, chosen so that a\n"
        "run takes about 40 ms × (w/128)², at least 25 ms (repeated until it lasts 20 ms), all combinations\n"
        "side by side, round after round; ns/pixel is the median wall-clock time per pixel with\n"
        "--threads threads, × base its ratio to double/article at spp 1 on the same scene (left out,\n"
        "with the reason, only for a combination that could not be timed).\n"
        "Example: promyk bench accuracy --w 32 --spp 1,4 --real float,double --json accuracy.json");
    return [speed_cmd, effects_cmd, speed, effects, accuracy] {
        if (speed_cmd->parsed()) return bench::run_speed_bench(*speed);
        if (effects_cmd->parsed()) return bench::run_effects_bench(*effects);
        return run_accuracy(*accuracy);
    };
}

}  // namespace promyk::app
