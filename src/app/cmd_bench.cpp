// promyk bench: measurements side by side in one run, reported as ratios.
#include <memory>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "bench/effects.hpp"
#include "bench/speed.hpp"
#include "util/errors.hpp"

namespace promyk::app {

std::function<int()> setup_bench(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("bench", "Measure what the engine costs, side by side in one run");
    cmd->require_subcommand(1);
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
        "Ratios are printed only when every timed run takes at least 20 ms; smaller panes print the\n"
        "times and say why there is no ratio.");
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
    return [speed_cmd, speed, effects] {
        return speed_cmd->parsed() ? bench::run_speed_bench(*speed) : bench::run_effects_bench(*effects);
    };
}

}  // namespace promyk::app
