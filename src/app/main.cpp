// promyk: an educational ray tracer that shows its work.
// main only wires the subcommands and maps errors to exit codes:
// 0 success, 2 bad command line, 3 bad input file, 4 output not written,
// 128 + signal after SIGHUP, SIGINT or SIGTERM, 141 when the reader of
// standard output quits; 70 an internal error (a bug).
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <exception>
#include <functional>
#include <new>
#include <string>
#include <system_error>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/output_file.hpp"

namespace {

void report(const char* what) { fmt::print(stderr, "promyk: {}\n", what); }

std::string where_of(const promyk::InputError& error) {
    if (error.where.empty()) return error.file;
    return fmt::format("{}: {}", error.file, error.where);
}

const char* signal_name(int signal_number) {
    switch (signal_number) {
        case SIGHUP: return "SIGHUP";
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        default: return "a signal";
    }
}

// Reports the exception being handled and returns the exit code for it.
int exit_code_for_failure(const std::string& name) {
    // A signal that arrives while promyk is blocked (reading a scene from a
    // FIFO, opening a FIFO for output) makes the call fail with EINTR, which
    // surfaces as an input or output error: the signal is what happened.
    if (const int signal_number = promyk::interrupt_signal()) {
        report(fmt::format("interrupted by {}; no output file was written", signal_name(signal_number)).c_str());
        return 128 + signal_number;
    }
    try {
        throw;
    } catch (const promyk::UsageError& error) {
        report(error.what());
        fmt::print(stderr, "Run 'promyk {} --help' for the options.\n", name);
        return 2;
    } catch (const promyk::InputError& error) {
        fmt::print(stderr, "promyk: {}: {}\n", where_of(error), error.what());
        return 3;
    } catch (const promyk::OutputError& error) {
        report(error.what());
        return 4;
    } catch (const promyk::BrokenPipe&) {
        return 128 + SIGPIPE;  // the reader quit: quietly, as if SIGPIPE had ended us
    } catch (const promyk::Interrupted& error) {
        report(fmt::format("interrupted by {}; no output file was written", signal_name(error.signal_number)).c_str());
        return 128 + error.signal_number;
    } catch (const std::bad_alloc&) {
        report("out of memory");
        return 70;
    } catch (const std::system_error& error) {
        // fmt::print to standard output when its reader has quit.
        if (error.code().value() == EPIPE) return 128 + SIGPIPE;
        report(fmt::format("internal error (a bug in promyk, please report it): {}", error.what()).c_str());
        return 70;
    } catch (const std::exception& error) {
        report(fmt::format("internal error (a bug in promyk, please report it): {}", error.what()).c_str());
        return 70;
    }
}

}  // namespace

int main(int argc, char** argv) {
    promyk::install_interrupt_handlers();
    CLI::App app{
        "promyk: an educational ray tracer that shows its work.\n"
        "It follows the Delta article \"Śledzenie promieni\": an eye at the origin, a pane of w x w pixels\n"
        "at z = z_E, a sphere, a point light, Lambert shading. Every number behind a pixel can be shown.",
        "promyk"};
    app.set_version_flag("--version", fmt::format("promyk {}", PROMYK_VERSION));
    app.require_subcommand(1);
    app.footer(
        "Run 'promyk COMMAND --help' for a command's options.\n"
        "Exit codes: 0 success, 2 bad command line, 3 bad input file, 4 output not written,\n"
        "129/130/143 interrupted (nothing half-written), 141 reader of standard output quit,\n"
        "70 internal error.");

    std::function<int()> run;
    const auto render = promyk::app::setup_render(app);
    const auto trace = promyk::app::setup_trace(app);
    const auto bench = promyk::app::setup_bench(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);  // prints help, version or the error
        return code == 0 ? 0 : 2;
    }

    const std::string name = app.get_subcommands().front()->get_name();
    run = name == "render" ? render : name == "trace" ? trace : bench;
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
