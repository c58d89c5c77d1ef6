// Options several subcommands share, declared once so their names, value
// names and help read the same in every command.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace promyk::app {

// --scene FILE: a scene file; empty means the article's built-in scene.
CLI::Option* add_scene_option(CLI::App& cmd, std::string& scene_file);

// --w N: the pane's size in pixels, with the command's default shown.
CLI::Option* add_w_option(CLI::App& cmd, int& w);

}  // namespace promyk::app
