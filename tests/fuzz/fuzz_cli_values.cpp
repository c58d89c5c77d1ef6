// The command line's number and pixel parsers (app/cli_values.hpp): any text
// is a value in range or a UsageError (exit 2), never a crash or undefined
// behaviour; a value accepted lies in its range, and whole_number_problem
// agrees with parse_whole_number.
#include <climits>
#include <string>

#include "app/cli_values.hpp"
#include "fuzz_check.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

void whole_number(const std::string& text, long min, long max) {
    const bool problem = cli::whole_number_problem(text, min, max).has_value();
    try {
        const int value = cli::parse_whole_number(text, "--n", min, max);
        if (problem) fuzz::broken("parse_whole_number accepts what whole_number_problem refuses");
        if (value < min || value > max) fuzz::broken("a whole number outside its range is accepted");
    } catch (const UsageError&) {
        if (!problem) fuzz::broken("parse_whole_number refuses what whole_number_problem accepts");
    }
}

void pixel(const std::string& text, int w) {
    try {
        const cli::Pixel p = cli::parse_pixel(text, "--pixel", w);
        if (p.i < 0 || p.j < 0 || p.i >= w || p.j >= w) fuzz::broken("a pixel outside the pane is accepted");
    } catch (const UsageError&) {
    }
    try {
        const PixelRegion r = cli::parse_region(text, "--trace-region", w);
        if (r.i0 < 0 || r.j0 < 0 || r.i0 > r.i1 || r.j0 > r.j1 || r.i1 >= w || r.j1 >= w)
            fuzz::broken("a region outside the pane or inside out is accepted");
    } catch (const UsageError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_ui_language(fuzz::language_of(size));
    const std::string text(fuzz::bytes_of(data, size));
    whole_number(text, 1, cli::max_w);
    whole_number(text, 0, 100);
    whole_number(text, INT_MIN, INT_MAX);
    for (const int w : {1, 8, 512, cli::max_w}) pixel(text, w);
    (void)cli::closest_name(text, {"float", "double", "long-double", "quad"});
    (void)cli::choice_problem(text, "--real", {"float", "double", "long-double", "quad"});
    return 0;
}
