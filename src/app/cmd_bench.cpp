// promyk bench: measurements side by side in one run, reported as ratios.
#include <memory>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "bench/speed.hpp"
#include "util/errors.hpp"

namespace promyk::app {

std::function<int()> setup_bench(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("bench", "Measure what the engine costs, side by side in one run");
    cmd->require_subcommand(1);
    auto speed = std::make_shared<bench::SpeedOptions>();
    CLI::App* speed_cmd = cmd->add_subcommand(
        "speed", "The engine against the article's literal program, all threads against one, trace writing");
    speed_cmd->add_option("--w", speed->w, "Pane size for the image timings")->type_name("N")->capture_default_str();
    speed_cmd->add_option("--repetitions", speed->repetitions, "Alternating rounds (medians are reported)")
        ->type_name("N")
        ->capture_default_str();
    speed_cmd->add_option("--threads", speed->threads, "Threads for the threaded timings; 0 means all cores")
        ->type_name("N")
        ->capture_default_str();
    speed_cmd->add_option("--trace-w", speed->trace_w, "Pane size for the traces' throughput")
        ->type_name("N")
        ->capture_default_str();
    return [speed] {
        cli::check_w(speed->w);
        cli::check_w(speed->trace_w);
        if (speed->repetitions < 1) throw UsageError("--repetitions must be at least 1");
        cli::check_threads(speed->threads);
        return bench::run_speed_bench(*speed);
    };
}

}  // namespace promyk::app
