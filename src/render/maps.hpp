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
// The colours, scales and map names are in image/map_colours.hpp; here is
// what computes each pixel's category or value. A map is a Kernel
// (render/kernel.hpp) whose rows are colours, so render() streams it with its
// threads, bands, progress and traces unchanged; it counts its pixels per
// category as it goes (MapKernel::tally). A map of
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
#include "image/map_colours.hpp"
#include "math/real.hpp"
#include "render/kernel.hpp"
#include "scene/scene.hpp"

namespace promyk {

// The category a pixel is drawn in. Precedence: non-finite (nothing was
// decided), then tangent (the branch itself was decided by rounding), then
// behind the eye, then the branch.
BranchCategory branch_category(const PixelNotes& notes);

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
    // One pixel's value as a scalar map keeps it (map_stored_value), computed
    // anew: what export embeds and the page's hover reads. The branch map:
    // the pixel's BranchCategory index.
    virtual double pixel_value(int w, int i, int j) const = 0;

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

// A scalar map's pixel as one double: the value (> 0), or one of the cases
// with a colour of their own.
namespace map_stored_value {
inline constexpr double zero = 0;             // exact (error), none lost (digits-lost)
inline constexpr double branch_differs = -1;  // error map only
inline constexpr double non_finite = -2;
}  // namespace map_stored_value

// The colour `render --map` draws for a stored value of a scalar map (error
// or digits-lost) on `scale`: one definition for the CLI, export and the page.
Rgb8 scalar_map_colour(MapKind kind, const ColourScale& scale, double stored);
// The scale a map's stored values make when no range is given: the error
// map's run range (error_scale_of_run, or the fallback without a non-zero
// finite error), the digits-lost map's type's scale (digits_lost_scale).
ColourScale scalar_map_scale(MapKind kind, RealType real, const double* stored, std::size_t count);

}  // namespace promyk
