// Options several subcommands share, declared once so their names, value
// names, checks and help read the same in every command.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geometry/formula.hpp"
#include "math/real.hpp"

namespace promyk::app {

// A check for a whole number from min to max in plain decimal; its message
// names the range and the plain form of what was typed ("write 10").
CLI::Validator whole_number(long min, long max);

// A check that refuses an empty value (`--scene ''` must not mean "none").
CLI::Validator non_empty();

// A check that accepts only one of `names` (never a number: CLI11 would take
// `--real 0` for the enum's value 0); a typo gets "did you mean". With
// `values`, the name becomes values[k] (an enum's number) for CLI11 to store.
CLI::Validator one_of(const std::string& option, const std::vector<std::string>& names,
                      const std::vector<int>& values = {});

// "a|b|c": the names as --help shows them after the option.
std::string names_shown(const std::vector<std::string>& names);

// --scene FILE: a scene file; not given means the article's built-in scene.
CLI::Option* add_scene_option(CLI::App& cmd, std::string& scene_file);

// --w N: the pane's size in pixels, with the command's default shown.
CLI::Option* add_w_option(CLI::App& cmd, int& w);

// --threads N: 0 (the default) means all the cores this process may use.
CLI::Option* add_threads_option(CLI::App& cmd, int& threads);

// --real float|double|long-double|quad: the type the whole computation is
// done in (default double, the article's).
CLI::Option* add_real_option(CLI::App& cmd, RealType& real);

// --format text|json (or the names given): what the command writes; the
// first name is the default.
CLI::Option* add_format_option(CLI::App& cmd, std::string& format, const std::vector<std::string>& names,
                               const std::string& description);

// --formula article|stable|fma|geometric: how the eye's rays meet a sphere
// (default article, the article's quadratic).
CLI::Option* add_formula_option(CLI::App& cmd, Formula& formula);

// --spp N: samples per pixel, a square from 1 (the pixel's centre, the
// default) to max_spp, on the deterministic pattern of render/samples.hpp.
CLI::Option* add_spp_option(CLI::App& cmd, int& spp);

}  // namespace promyk::app
