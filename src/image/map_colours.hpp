// The maps' colours (render --map): which maps there are, the branch
// atlas's categories and their Okabe-Ito colours, the viridis scales of the
// error and digits-lost maps and their special colours. Pure colouring: what
// computes a pixel's category or value is render/maps.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "math/real.hpp"

namespace promyk {

enum class MapKind { branch, error, digits_lost };

// "branch", "error", "digits-lost"; the accepted names in order, for --map and messages.
std::string_view map_name(MapKind kind);
inline constexpr MapKind map_kinds[] = {MapKind::branch, MapKind::error, MapKind::digits_lost};
std::optional<MapKind> parse_map_name(std::string_view name);

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    // Parameters not named after the fields (clang's -Wshadow: b is blue).
    friend bool operator==(Rgb8 x, Rgb8 y) { return x.r == y.r && x.g == y.g && x.b == y.b; }
    friend bool operator!=(Rgb8 x, Rgb8 y) { return !(x == y); }
};

// One colour of a legend: what it marks, the colour's name and hex code.
struct LegendColour {
    std::string_view category;  // "miss", "tangent", "exact", ...
    std::string_view colour;    // "sky blue"
    std::string_view hex;       // "#56B4E9"
    Rgb8 rgb;
};

// The branch atlas's categories: the five branches, then the two notes.
enum class BranchCategory { miss, dark, lit, shadowed, non_finite, tangent, behind };
inline constexpr int branch_category_count = 7;

// The colour of each category (Okabe-Ito), indexed by BranchCategory.
const LegendColour& branch_colour(BranchCategory category);
// The id of the message (lessons/messages_words.json) that names a category:
// one definition for the CLI's legends (image/map_legend.cpp) and the web
// page's (web_export/wasm).
const char* branch_category_message(BranchCategory category);

// A perceptually ordered, colour-blind-safe ramp (viridis, 9 stops from
// #440154 to #FDE725, linear between stops in sRGB), from `low` to `high` of
// a value, on a log10 axis or a linear one; values outside are clamped.
class ColourScale {
public:
    // A linear scale's steps (its categories in --stats): `linear_steps` of equal width.
    ColourScale(double low, double high, bool logarithmic, int linear_steps = 10)
        : low_(low), high_(high), log_(logarithmic), linear_steps_(linear_steps) {}
    Rgb8 operator()(double value) const;  // value finite and > 0 on a log axis
    // The ramp at t in [0, 1].
    static Rgb8 ramp(double t);
    double low() const { return low_; }
    double high() const { return high_; }
    bool logarithmic() const { return log_; }
    int linear_steps() const { return linear_steps_; }

private:
    double low_, high_;
    bool log_;
    int linear_steps_;
};

// The error map's scale, log10 viridis from `low` (dark purple) to `high`
// (yellow); errors outside are clamped to its ends.
ColourScale error_scale(double low, double high);
// The scale a run's own errors make: from its smallest non-zero error to its
// largest, widened to whole decades (10^floor(log10 smallest) to
// 10^ceil(log10 largest), at least one decade), so a float's, a double's and
// a quad's map each use the whole ramp. Without a non-zero finite error,
// the fixed scale 1e-20 ... 1.
ColourScale error_scale_of_run(double smallest, double largest);
ColourScale fallback_error_scale();
// The error map's special colours.
const LegendColour& exact_colour();           // |I - I_ref| = 0: white
const LegendColour& branch_differs_colour();  // a branch other than the reference's: vermillion
const LegendColour& non_finite_error_colour();  // both non-finite: reddish purple (the atlas's non-finite)

// The digits-lost map's scale: 0 to the real type's whole digits rounded up
// (float 8, double 16, long double 20, quad 35), linear, one step a digit.
ColourScale digits_lost_scale(RealType real);
const LegendColour& none_lost_colour();  // no step cancels a digit: white

}  // namespace promyk
