// Maps (render --map): an RGB image of a per-pixel quantity instead of the
// shading, so that a teacher can find the interesting pixels and trace them.
//
// - branch: the pixel-case atlas, one Okabe-Ito colour per branch (miss,
//   dark, lit, shadowed, non-finite) and per note (tangent, behind the eye:
//   render/notes.hpp), notes over branches (branch_category).
// - error: |I - I_ref| against the same pixel in quad with the geometric
//   formula at the same samples per pixel, on a logarithmic viridis scale
//   (error_scale), with exact 0, a branch that differs from the reference's
//   and a non-finite error in colours of their own.
//
// A map is a Kernel (render/kernel.hpp) whose rows are colours, so render()
// streams it with its threads, bands, progress and traces unchanged; it
// counts its pixels per category as it goes (MapKernel::tally). A map of
// another per-pixel number is a ScalarMap (maps.cpp) with its own value
// function and scale: the error map is one.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/formula.hpp"
#include "math/real.hpp"
#include "render/kernel.hpp"
#include "scene/scene.hpp"

namespace promyk {

enum class MapKind { branch, error, digits_lost };

// "branch", "error", "digits-lost"; the accepted names in order, for --map and messages.
std::string_view map_name(MapKind kind);
inline constexpr MapKind map_kinds[] = {MapKind::branch, MapKind::error, MapKind::digits_lost};
std::optional<MapKind> parse_map_name(std::string_view name);

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(Rgb8 a, Rgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
    friend bool operator!=(Rgb8 a, Rgb8 b) { return !(a == b); }
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

// The category a pixel is drawn in. Precedence: non-finite (nothing was
// decided), then tangent (the branch itself was decided by rounding), then
// behind the eye, then the branch.
BranchCategory branch_category(const PixelNotes& notes);

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

// What a map counted: per category its pixels and the first in row order
// (i, then j), for `promyk trace --pixel I,J`; and for a scalar map its
// largest finite value and where.
struct MapTally {
    struct Category {
        std::string name;
        long long count = 0;
        int first_i = -1, first_j = -1;
        bool listed_if_empty = true;  // false: a step of a scale, listed only when it has pixels
    };
    std::vector<Category> categories;
    bool has_largest = false;
    double largest = 0;
    int largest_i = -1, largest_j = -1;
};

class MapKernel : public Kernel {
public:
    // The counts so far, summed row by row (call after render()).
    virtual MapTally tally() const = 0;
    // What the map shows, for the status line: "branch map", "error map ...".
    virtual std::string description() const = 0;
    virtual MapKind kind() const = 0;
    // The colour scale of a scalar map (nullptr for the branch map, and for
    // a deferred map before settle()).
    virtual const ColourScale* colour_scale() const { return nullptr; }
    // Whether the map's scale comes from the run's own values (the error map
    // without --range): then row() only records each pixel (its rows are
    // black placeholders and tally() is empty), and after render() the
    // caller calls settle(), which fixes the scale, and then takes the
    // coloured rows from replay_row(), in order, which also counts them.
    virtual bool deferred() const { return false; }
    virtual void settle() {}
    virtual void replay_row(int w, int i, std::uint8_t* out) const { (void)w, (void)i, (void)out; }

protected:
    using Kernel::Kernel;
};

// The largest --w at which the error map finds its own range (it keeps a
// double a pixel until the render ends: 128 MiB); above it, --range is needed.
inline constexpr int max_w_for_run_range = 4096;

// The map of `kind` for the scene computed in `real` with `formula` and spp
// samples per pixel, on a w x w pane (the map keeps w rows of counts). The
// error map uses `error_range` (low, high) if given, else its run's own
// range (deferred()).
std::unique_ptr<MapKernel> make_map_kernel(MapKind kind, const Scene& scene, RealType real, Formula formula,
                                           int spp, int w,
                                           std::optional<std::pair<double, double>> error_range = std::nullopt);

}  // namespace promyk
