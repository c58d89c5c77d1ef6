// promyk: an educational ray tracer that shows its work.
// main only wires the subcommands and maps errors to exit codes:
// 0 success, 1 a negative answer (diff found a divergence, --answers a wrong number), 2 bad command line, 3 bad input file, 4 output not written,
// 128 + signal after SIGHUP, SIGINT or SIGTERM, 141 when the reader of
// standard output quits; 70 an internal error (a bug).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>
#include <exception>
#include <functional>
#include <new>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "app/cli_errors.hpp"
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/global_options.hpp"
#include "render/isa.hpp"
#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"
#include "util/wrap.hpp"
#include "util/interrupt.hpp"
#include "util/output_file.hpp"
#include "util/standard_output.hpp"

namespace {

// Messages carry input (paths, keys, values): printable() keeps terminal
// control sequences out of them, and a very long one is cut to a screenful.
std::string shown(const std::string& text) {
    constexpr std::size_t most = 2000;
    std::string safe = promyk::printable(text);
    if (safe.size() > most) {
        safe.resize(most);
        while (!safe.empty() && (static_cast<unsigned char>(safe.back()) & 0xC0) == 0x80) safe.pop_back();
        if (!safe.empty() && static_cast<unsigned char>(safe.back()) >= 0xC0) safe.pop_back();
        safe += " … (cut)";
    }
    return safe;
}

// One message, wrapped to 80 columns (continuation lines indented).
void report(const std::string& what) { fmt::print(stderr, "{}\n", promyk::wrap_text("promyk: " + shown(what), 4)); }

// "unknown command 'Render'; did you mean 'render'? ..."
std::string unknown_command_message(const std::string& typed, const std::vector<std::string>& commands) {
    std::string list;
    for (const std::string& command : commands) list += (list.empty() ? "" : ", ") + command;
    // the same but for case, or a letter or two off (rendr, trcae)
    const std::string suggestion = promyk::cli::closest_name(typed, commands);
    if (!suggestion.empty())
        return promyk::ui_message("cli_unknown_command_suggest",
                                  {{"command", typed}, {"suggestion", suggestion}, {"names", list}});
    return promyk::ui_message("cli_unknown_command", {{"command", typed}, {"names", list}});
}

// A command with commands of its own (scene, bench) says how to see theirs;
// its own footer, if any, follows. The top-level footer is set after the
// commands, so they do not inherit its "promyk COMMAND" line.
void add_command_footers(CLI::App& app, const std::string& path) {
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        const std::string sub_path = path + " " + sub->get_name();
        if (!sub->get_subcommands([](CLI::App*) { return true; }).empty()) {
            const std::string own = sub->get_footer();
            sub->footer(fmt::format("Run '{} COMMAND --help' for a command's options.{}", sub_path,
                                    own.empty() ? "" : "\n" + own));
        }
        add_command_footers(*sub, sub_path);
    }
}

std::string where_of(const promyk::InputError& error) {
    if (error.where.empty()) return error.file;
    return fmt::format("{}: {}", error.file, error.where);
}

const char* signal_name(int signal_number) {
    switch (signal_number) {
        case SIGHUP:
            return "SIGHUP";
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        default:
            return "a signal";
    }
}

// Reports the exception being handled and returns the exit code for it;
// `path` is the command ("promyk scene check") a usage error points to.
int exit_code_for_failure(const std::string& path) {
    // A signal that arrives while promyk is blocked (reading a scene from a
    // FIFO, opening a FIFO for output) makes the call fail with EINTR, which
    // surfaces as an input or output error: the signal is what happened.
    if (const int signal_number = promyk::interrupt_signal()) {
        report(promyk::ui_message("cli_interrupted", {{"signal", signal_name(signal_number)}}));
        return 128 + signal_number;
    }
    try {
        throw;
    } catch (const promyk::UsageError& error) {
        report(error.what());
        fmt::print(stderr, "{}\n", promyk::app::run_help_line(path));
        return 2;
    } catch (const promyk::SceneErrors& errors) {
        // Every fault of the scene, each on its line with its pointer.
        for (const promyk::SceneFault& fault : errors.faults)
            report(fault.where.empty() ? fmt::format("{}: {}", errors.file, fault.what)
                                       : fmt::format("{}: {}: {}", errors.file, fault.where, fault.what));
        if (errors.more > 0 || !errors.counted)
            report(fmt::format("{}: {}", errors.file,
                               promyk::ui_message(errors.counted ? "scene_more_faults" : "scene_more_faults_at_least",
                                                  {{"count", std::to_string(errors.more)},
                                                   {"limit", std::to_string(promyk::max_collected_faults)}})));
        return 3;
    } catch (const promyk::InputError& error) {
        report(fmt::format("{}: {}", where_of(error), error.what()));
        return 3;
    } catch (const promyk::OutputError& error) {
        report(error.what());
        return 4;
    } catch (const promyk::BrokenPipe&) {
        return 128 + SIGPIPE;  // the reader quit: quietly, as if SIGPIPE had ended us
    } catch (const promyk::Interrupted& error) {
        report(promyk::ui_message("cli_interrupted", {{"signal", signal_name(error.signal_number)}}));
        return 128 + error.signal_number;
    } catch (const std::bad_alloc&) {
        report(promyk::ui_message("cli_out_of_memory"));
        return 70;
    } catch (const std::system_error& error) {
        // fmt::print to standard output when its reader has quit.
        if (error.code().value() == EPIPE) return 128 + SIGPIPE;
        report(promyk::ui_message("cli_internal_error", {{"what", error.what()}}));
        return 70;
    } catch (const std::exception& error) {
        report(promyk::ui_message("cli_internal_error", {{"what", error.what()}}));
        return 70;
    }
}

}  // namespace

int main(int argc, char** argv) {
    promyk::reserve_standard_descriptors();
    promyk::install_interrupt_handlers();
    CLI::App app{
        "promyk: an educational ray tracer that shows its work.\n"
        "It follows the Delta article \"Śledzenie promieni\": an eye at the origin, a pane of w × w pixels\n"
        "at z = z_E, a sphere, a point light, Lambert shading. Every number behind a pixel can be shown.",
        "promyk"};
    app.set_version_flag("--version", fmt::format("promyk {}", PROMYK_VERSION));
    app.require_subcommand(1);
    app.get_formatter()->label("REQUIRED", "(required)");

    const auto render = promyk::app::setup_render(app);
    const auto trace = promyk::app::setup_trace(app);
    const auto bench = promyk::app::setup_bench(app);
    const auto lesson = promyk::app::setup_lesson(app);
    const auto scene = promyk::app::setup_scene(app);
    const auto diff = promyk::app::setup_diff(app);
    const auto export_page = promyk::app::setup_export(app);
    const std::vector<std::string> commands = {"render", "trace", "lesson", "scene", "diff", "bench", "export"};
    add_command_footers(app, "promyk");
    promyk::app::describe_global_options(app);
    app.footer(
        "Run 'promyk COMMAND --help' for a command's options. --help is always in English; --lang\n"
        "chooses the language of everything else.\n"
        "Exit codes: 0 success, 1 a negative answer (diff diverges, --answers wrong), 2 bad command line,\n"
        "3 bad input file, 4 output not written (export: also a promyk built without the web page),\n"
        "129/130/143 interrupted (nothing half-written), 141 reader of standard output quit,\n"
        "70 internal error.");

    // --lang and --digits first, wherever they stand: the language words
    // every error after them.
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        promyk::app::take_global_options(args);
        promyk::choose_isa_from_environment();  // PROMYK_ISA, in the language just chosen
    } catch (const promyk::UsageError& error) {
        report(error.what());
        const auto command = std::find_if(args.begin(), args.end(), [&](const std::string& arg) {
            return std::find(commands.begin(), commands.end(), arg) != commands.end();
        });
        fmt::print(stderr, "{}\n", promyk::app::run_help_line(command == args.end() ? "promyk" : "promyk " + *command));
        return 2;
    }

    // The command is the first argument that is not an option; check it
    // here, so that a typo gets a suggestion and `promyk help` gets help.
    if (!args.empty() && args[0] == "help") {
        // promyk help [COMMAND ...]: the same as promyk [COMMAND ...] --help.
        args.erase(args.begin());
        args.push_back("--help");
    }
    if (!args.empty() && !args[0].empty() && args[0][0] != '-' &&
        std::find(commands.begin(), commands.end(), args[0]) == commands.end()) {
        report(unknown_command_message(args[0], commands));
        return 2;
    }
    if (args.empty()) {
        fmt::print(stderr, "{}", app.help());
        report(promyk::ui_message("cli_no_command"));
        return 2;
    }
    const std::string name = !args[0].empty() && args[0][0] != '-' ? args[0] : "";
    std::string path = "promyk";

    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
        app.parse(reversed);
    } catch (const CLI::Success& done) {
        // --help or --version: to standard output, checked like any product
        std::ostringstream text;
        const int code = app.exit(done, text);
        try {
            promyk::write_standard_output(text.str());
            promyk::flush_standard_output();
        } catch (...) {
            return exit_code_for_failure("promyk");
        }
        return code;
    } catch (const CLI::ParseError& error) {
        report(promyk::app::parse_error_message(error, app));
        fmt::print(stderr, "{}\n", promyk::app::run_help_line(promyk::app::command_path(app)));
        return 2;
    }
    path = promyk::app::command_path(app);

    const std::function<int()>& run = name == "render"  ? render
                                      : name == "trace"  ? trace
                                      : name == "lesson" ? lesson
                                      : name == "scene"  ? scene
                                      : name == "diff"   ? diff
                                      : name == "export" ? export_page
                                                         : bench;
    try {
        const int code = run();
        // Standard output is flushed here, not at exit, so that a failure
        // (a reader that quit, a full disk) changes the exit code.
        promyk::flush_standard_output();
        return code;
    } catch (...) {
        return exit_code_for_failure(path);
    }
}
