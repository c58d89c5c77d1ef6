// Parsing and checking the values users type on the command line. Every
// failure is a UsageError (exit 2) whose message names the option.
#pragma once

#include <string>
#include <vector>

#include "render/pixel_selection.hpp"
#include "scene/scene.hpp"

namespace promyk::cli {

// The largest pane side accepted: beyond it a render would take hours.
inline constexpr int max_w = 32768;

struct Pixel {
    int i, j;  // row from the top, column from the left
};

// "I,J" -> pixel; checks 0 <= i, j < w.
Pixel parse_pixel(const std::string& text, const std::string& option, int w);

// "I0,J0,I1,J1" -> region (corners inclusive), inside the pane, I0 <= I1, J0 <= J1.
PixelRegion parse_region(const std::string& text, const std::string& option, int w);

// Checks 1 <= w <= max_w.
void check_w(int w);

// The most threads accepted: far more than any machine promyk runs on has cores.
inline constexpr int max_threads = 1024;

// Checks 0 (all cores) <= threads <= max_threads.
void check_threads(int threads);

// The built-in article scene, or the scene file when a path is given.
Scene load_scene_option(const std::string& path);

}  // namespace promyk::cli
