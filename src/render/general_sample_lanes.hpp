// A row of the general tracer drawn from spp > 1 samples a pixel, in lanes:
// render/sample_lanes.hpp's sampled row (each lane one pixel, all taking
// sample s at once, summed in sample order, the centre sample's branch kept)
// with the general tracer's pixel in place of the article's, its height
// y_E each lane's own (LaneHeights, or OneSphereRow's for one sphere and one
// light). Every pixel has sample_pixel over trace_general's bits and branch,
// every row its counts (tests/general_sample_lanes_test.cpp). Included,
// like render/general_row_lanes.hpp, by each instruction set's translation
// unit (render/general_row.cpp, ..._avx2.cpp, ..._avx512.cpp), which
// compiles it in its own namespace.
#pragma once

#include <cstdint>

#include "render/general_lanes.hpp"
#include "render/general_row.hpp"
#include "render/general_row_lanes.hpp"  // with_switches
#include "render/general_row_one_sphere.hpp"
#include "render/kernel.hpp"
#include "render/sample_lanes.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// The general tracer's samples, a shooter of draw_sampled_row: each traced
// at its points E and taken into the pixels, the work of the lanes kept
// counted. Sw::one: one sphere and one light, from OneSphereRow's registers.
template <class Sw, bool Rgb, class Lane, bool One = Sw::one>
struct GeneralSamples {
    template <class L>
    using Intensity = LaneIntensity<L, Rgb>;
    const GeneralRow<Rgb>& row;
    LaneWork<Lane> work;
    explicit GeneralSamples(const GeneralRow<Rgb>& r) : row(r) {}
    PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> pixel(Lane x, Lane y, MaskOf<Lane> kept) {
        return general_lanes<Sw>(row, LaneHeights<Rgb, Lane>(row, y), x, kept, work);
    }
};
template <class Sw, bool Rgb, class Lane>
struct GeneralSamples<Sw, Rgb, Lane, true> {
    template <class L>
    using Intensity = LaneIntensity<L, Rgb>;
    const GeneralRow<Rgb>& row;
    LaneWork<Lane> work;
    OneSphereRow<Lane, Rgb> one;
    explicit GeneralSamples(const GeneralRow<Rgb>& r) : row(r), one(r) {}
    PROMYK_LANES_INLINE GeneralLanePixel<Lane, Rgb> pixel(Lane x, Lane y, MaskOf<Lane> kept) {
        return one_sphere_lanes<Sw>(OneSphereRow<Lane, Rgb>(one, y), x, kept, work);
    }
};

template <class Sw, bool Rgb, class Lane>
struct GeneralShooter : GeneralSamples<Sw, Rgb, Lane> {
    using GeneralSamples<Sw, Rgb, Lane>::GeneralSamples;
    using Mask = MaskOf<Lane>;
    PROMYK_LANES_INLINE SampleResult<Lane, LaneIntensity<Lane, Rgb>> operator()(const SamplePoint<Lane>& E,
                                                                                Mask kept) {
        const GeneralLanePixel<Lane, Rgb> pixel = this->pixel(E.x, E.y, kept);
        const Mask dark = lane_not(either(either(pixel.miss, pixel.non_finite), either(pixel.lit, pixel.shadowed)));
        return {pixel.I_P, branch_code<CodeOf<Lane>>(pixel.miss, dark, pixel.non_finite, pixel.shadowed)};
    }
    // The intensity of a sample that misses (BackgroundSum).
    template <class L>
    PROMYK_LANES_INLINE LaneIntensity<L, Rgb> background() const {
        return splat_of<L>(this->row.background);
    }
    // The row's rays and tests (count_work): one eye's ray a sample.
    PROMYK_LANES_INLINE void count(RowCounts& counts, int pixels, int spp) const {
        count_work<Sw::many>(counts, this->work, this->row, static_cast<long long>(pixels) * spp);
    }
};

// Row i of a w-pixel pane, spp > 1 samples a pixel, the stages chosen at run
// time (once a row). Every sample's cell is found by division (by_cell not
// specialised for powers of two: the same bits, one instantiation per stage
// where the article's kernel has two). count_branches false (render
// without --stats): only the non-finite pixels are counted.
template <class Lane, bool Rgb, class Out>
PROMYK_LANES_INLINE RowCounts draw_sampled_general_row(const GeneralRow<Rgb>& row, GeneralLaneStages stages, int w,
                                                       int i, int spp, std::uint8_t* out, Out* I_P,
                                                       std::uint8_t* branches, bool count_branches) {
    const SampleGrid grid = sample_grid(w, i, spp);
    const bool count = count_branches || I_P != nullptr || branches != nullptr;
    return with_switches(stages, row, [&](auto sw) {
        GeneralShooter<decltype(sw), Rgb, Lane> shoot(row);
        return count ? draw_sampled_row<Lane, false, true>(shoot, grid, 0, w, out, I_P, branches)
                     : draw_sampled_row<Lane, false, false>(shoot, grid, 0, w, out, I_P, branches);
    });
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
