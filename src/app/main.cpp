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
#include <system_error>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "util/edit_distance.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"
#include "util/interrupt.hpp"
#include "util/output_file.hpp"

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

void report(const std::string& what) { fmt::print(stderr, "promyk: {}\n", shown(what)); }

// "unknown command 'Render'; did you mean 'render'? ..."
std::string unknown_command_message(const std::string& typed, const std::vector<std::string>& commands) {
    std::string lower = typed;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string list;
    for (const std::string& command : commands) list += (list.empty() ? "" : ", ") + command;
    for (const std::string& command : commands) {
        // the same but for case, or a letter or two off (rendr, trcae)
        if (promyk::edit_distance(lower, command) <= 2)
            return fmt::format("unknown command '{}'; did you mean '{}'? The commands are {}; see promyk --help",
                               typed, command, list);
    }
    return fmt::format("unknown command '{}'; the commands are {}; see promyk --help", typed, list);
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

// Reports the exception being handled and returns the exit code for it.
int exit_code_for_failure(const std::string& name) {
    // A signal that arrives while promyk is blocked (reading a scene from a
    // FIFO, opening a FIFO for output) makes the call fail with EINTR, which
    // surfaces as an input or output error: the signal is what happened.
    if (const int signal_number = promyk::interrupt_signal()) {
        report(fmt::format("interrupted by {}; no output file was written", signal_name(signal_number)));
        return 128 + signal_number;
    }
    try {
        throw;
    } catch (const promyk::UsageError& error) {
        report(error.what());
        fmt::print(stderr, "Run 'promyk {} --help' for the options.\n", name);
        return 2;
    } catch (const promyk::InputError& error) {
        report(fmt::format("{}: {}", where_of(error), error.what()));
        return 3;
    } catch (const promyk::OutputError& error) {
        report(error.what());
        return 4;
    } catch (const promyk::BrokenPipe&) {
        return 128 + SIGPIPE;  // the reader quit: quietly, as if SIGPIPE had ended us
    } catch (const promyk::Interrupted& error) {
        report(fmt::format("interrupted by {}; no output file was written", signal_name(error.signal_number)));
        return 128 + error.signal_number;
    } catch (const std::bad_alloc&) {
        report("out of memory");
        return 70;
    } catch (const std::system_error& error) {
        // fmt::print to standard output when its reader has quit.
        if (error.code().value() == EPIPE) return 128 + SIGPIPE;
        report(fmt::format("internal error (a bug in promyk, please report it): {}", error.what()));
        return 70;
    } catch (const std::exception& error) {
        report(fmt::format("internal error (a bug in promyk, please report it): {}", error.what()));
        return 70;
    }
}

}  // namespace

int main(int argc, char** argv) {
    promyk::install_interrupt_handlers();
    CLI::App app{
        "promyk: an educational ray tracer that shows its work.\n"
        "It follows the Delta article \"Śledzenie promieni\": an eye at the origin, a pane of w × w pixels\n"
        "at z = z_E, a sphere, a point light, Lambert shading. Every number behind a pixel can be shown.",
        "promyk"};
    app.set_version_flag("--version", fmt::format("promyk {}", PROMYK_VERSION));
    app.require_subcommand(1);
    app.footer(
        "Run 'promyk COMMAND --help' for a command's options.\n"
        "Exit codes: 0 success, 1 a negative answer (diff diverges, --answers wrong), 2 bad command line,\n"
        "3 bad input file, 4 output not written,\n"
        "129/130/143 interrupted (nothing half-written), 141 reader of standard output quit,\n"
        "70 internal error.");

    const auto render = promyk::app::setup_render(app);
    const auto trace = promyk::app::setup_trace(app);
    const auto bench = promyk::app::setup_bench(app);
    const auto lesson = promyk::app::setup_lesson(app);
    const auto scene = promyk::app::setup_scene(app);
    const auto diff = promyk::app::setup_diff(app);
    const std::vector<std::string> commands = {"render", "trace", "lesson", "scene", "diff", "bench"};

    // The command is the first argument that is not an option; check it
    // here, so that a typo gets a suggestion and `promyk help` gets help.
    std::vector<std::string> args(argv + 1, argv + argc);
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
        report("a command is required: render, trace, lesson, scene, diff or bench");
        return 2;
    }
    const std::string name = !args[0].empty() && args[0][0] != '-' ? args[0] : "";

    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
        app.parse(reversed);
    } catch (const CLI::Success& done) {
        return app.exit(done);  // --help or --version: printed to stdout
    } catch (const CLI::ParseError& error) {
        report(error.what());
        fmt::print(stderr, "Run 'promyk {}--help' for the options.\n", name.empty() ? "" : name + " ");
        return 2;
    }

    const std::function<int()>& run = name == "render"  ? render
                                      : name == "trace"  ? trace
                                      : name == "lesson" ? lesson
                                      : name == "scene"  ? scene
                                      : name == "diff"   ? diff
                                                         : bench;
    try {
        const int code = run();
        // Standard output is flushed here, not at exit, so that a failure
        // (a reader that quit, a full disk) changes the exit code.
        if (std::fflush(stdout) != 0) promyk::throw_write_error("standard output", errno);
        return code;
    } catch (...) {
        return exit_code_for_failure(name);
    }
}
