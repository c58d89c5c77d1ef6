// The options of every command: --lang pl|en and --digits N. They may stand
// before or after the command's name. main takes them out of the arguments
// before CLI11 parses the rest, so that the run's language is set before any
// error of the command line is worded.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace promyk::app {

// The range of --digits: significant digits shown.
inline constexpr int min_digits = 1;
inline constexpr int max_digits = 40;

// Removes `--lang X`, `--lang=X`, `--digits N` and `--digits=N` from `args`
// (up to a `--`), checks them and applies them: set_ui_language and
// set_chosen_digits. Without --lang the language comes from LC_ALL,
// LC_MESSAGES or LANG. Throws UsageError (in the chosen language).
void take_global_options(std::vector<std::string>& args);

// Declares both options on `app` and on every subcommand under it, so each
// command's --help lists them (they never reach CLI11's parser).
void describe_global_options(CLI::App& app);

}  // namespace promyk::app
