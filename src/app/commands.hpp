// The subcommands: each has an options struct, a setup that declares its
// options on a CLI11 subcommand, and a run that does the work (parsing apart
// from doing). Runs throw promyk's error types; main maps them to exit codes.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace promyk::app {

// Declares the subcommand on `app`; returns the function that runs it once
// the command line is parsed.
std::function<int()> setup_render(CLI::App& app);
std::function<int()> setup_trace(CLI::App& app);
std::function<int()> setup_bench(CLI::App& app);
std::function<int()> setup_lesson(CLI::App& app);
std::function<int()> setup_scene(CLI::App& app);
std::function<int()> setup_diff(CLI::App& app);
std::function<int()> setup_export(CLI::App& app);

}  // namespace promyk::app
