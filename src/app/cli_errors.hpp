// CLI11's parse errors in promyk's words and the run's language: an unknown
// option with the one probably meant, a missing value, an extra argument,
// a missing required argument, each naming the command it belongs to.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace promyk::app {

// "promyk", "promyk trace", "promyk scene check": the commands the parser
// entered (also after a parse error: CLI11 records a command on entering it).
std::string command_path(const CLI::App& app);

// The message for a parse error of `app` (after app.parse threw it).
std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app);

// The line after an error of the command line: "Run 'promyk trace --help'
// for the options."
std::string run_help_line(const std::string& path);

}  // namespace promyk::app
