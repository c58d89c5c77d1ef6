// Parsing and checking the values users type on the command line. Numbers
// are plain decimal (no octal 010, no hexadecimal 0x10, no spaces, no
// exponent); every failure is a UsageError (exit 2) whose message names the
// option and, where one exists, the plain form of what was meant.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "render/pixel_selection.hpp"
#include "scene/scene.hpp"

namespace promyk::cli {

// The largest pane side accepted: beyond it a render would take hours.
inline constexpr int max_w = 32768;

// The most threads accepted: far more than any machine promyk runs on has cores.
inline constexpr int max_threads = 1024;

// render's pane side when --w is not given: the pane a pixel from a default
// render lives in (named in the hint of a pixel outside a smaller pane).
inline constexpr int render_default_w = 512;

struct Pixel {
    int i, j;  // row from the top, column from the left
};

// The message for a text that is not a whole number from min to max in plain
// decimal, or nothing when it is one. `option` names the option ("--w").
std::optional<std::string> whole_number_problem(const std::string& text, long min, long max);

// `text` as a whole number from min to max; UsageError naming `option` otherwise.
int parse_whole_number(const std::string& text, const std::string& option, long min, long max);

// The message for `typed` when it is not one of `names` (empty when it is):
// "unknown value 'flaot' for --real; did you mean 'float'? (float, double, ...)".
// A suggestion is a name equal but for case, or one or two letters off.
std::string choice_problem(const std::string& typed, const std::string& option, const std::vector<std::string>& names);

// The name in `names` that `typed` probably means, or empty: equal but for
// case, or within edit distance 2 (and not a complete rewrite).
std::string closest_name(const std::string& typed, const std::vector<std::string>& names);

// The smallest pane side w that contains pixel (i, j): max(i, j) + 1.
inline long smallest_w_containing(long i, long j) { return (i > j ? i : j) + 1; }

// "I,J" -> pixel; also "I, J" and "(I, J)" as `promyk trace` prints it.
// Checks 0 <= i, j < w; a pixel outside names the smallest --w holding it.
// Numbers beyond the largest pane are refused with the range (exit 2).
Pixel parse_pixel(const std::string& text, const std::string& option, int w);

// "I0,J0,I1,J1" -> region (corners inclusive), inside the pane, I0 <= I1, J0 <= J1.
PixelRegion parse_region(const std::string& text, const std::string& option, int w);

// The built-in article scene, or the scene file when a path is given.
Scene load_scene_option(const std::string& path);

// The whole text of an input file, or of standard input for "-"; InputError
// (exit 3) for a folder or a file that cannot be read. `reads` completes
// "is a folder; ... a file" ("--answers reads"). Reading stops past
// `max_bytes` (InputError naming the limit and `who`, "diff" or "--answers"),
// so /dev/zero or an endless pipe ends at once, not at the out-of-memory killer.
std::string read_input_file(const std::string& path, const std::string& reads, std::size_t max_bytes,
                            const std::string& who);

// The most bytes diff reads from either side: a trace of many samples of a
// large scene fits; /dev/zero does not.
constexpr std::size_t max_diff_input_bytes = std::size_t(128) << 20;

}  // namespace promyk::cli
