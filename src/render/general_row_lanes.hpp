// A row of the general tracer, a vector of pixels at a time: the
// intensities of render/general_lanes.hpp turned into bytes and counted (by
// branch, and the shadow rays and tests). Included by one translation unit
// per instruction set (render/general_row.cpp for the baseline,
// render/general_row_avx2.cpp, ..._avx512.cpp), each compiling it in its own
// namespace (PROMYK_LANES_ISA). Calls nothing that is not inlined.
#pragma once

#include <cstdint>
#include <cstring>

#include "render/article_row_lanes.hpp"  // put_grey_levels
#include "render/general_lanes.hpp"
#include "render/general_row_one_sphere.hpp"
#include "render/general_row.hpp"
#include "render/kernel.hpp"
#include "render/row_vectors.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// Calls visit(LaneSwitches<...>{}) with the stages (and whether the row is
// one sphere's and one light's) as types: the one place the stages chosen
// at run time become template arguments.
template <bool Shadows, bool Phong, bool Ambient, class Visit>
PROMYK_LANES_INLINE decltype(auto) with_many(bool many, bool one, bool plain, Visit&& visit) {
    if (many) return visit(LaneSwitches<Shadows, Phong, Ambient, true>{});
    if (one && plain) return visit(LaneSwitches<Shadows, Phong, Ambient, false, true, true>{});
    if (one) return visit(LaneSwitches<Shadows, Phong, Ambient, false, true>{});
    return visit(LaneSwitches<Shadows, Phong, Ambient, false>{});
}
template <bool Shadows, bool Phong, class Visit>
PROMYK_LANES_INLINE decltype(auto) with_ambient(GeneralLaneStages stages, bool one, bool plain, Visit&& visit) {
    if (stages.ambient) return with_many<Shadows, Phong, true>(stages.many, one, plain, visit);
    return with_many<Shadows, Phong, false>(stages.many, one, plain, visit);
}
template <bool Rgb, class Visit>
PROMYK_LANES_INLINE decltype(auto) with_switches(GeneralLaneStages stages, const GeneralRow<Rgb>& row, Visit&& visit) {
    const bool one = !stages.many && one_sphere_and_light(row);
    const bool plain = one && plain_surface_and_light(row);
    if (stages.shadows) {
        if (stages.phong) return with_ambient<true, true>(stages, one, plain, visit);
        return with_ambient<true, false>(stages, one, plain, visit);
    }
    if (stages.phong) return with_ambient<false, true>(stages, one, plain, visit);
    return with_ambient<false, false>(stages, one, plain, visit);
}

// The row's pixels, a vector at a time, by the stages' pixel function: the
// one-sphere row's numbers in every lane once a row (OneSphereRow), or the
// general tracer's, which reads the row itself.
template <class Sw, bool Rgb, class Vector, bool One = Sw::one>
struct RowLanes {
    const GeneralRow<Rgb>& row;
    PROMYK_LANES_INLINE GeneralLanePixel<Vector, Rgb> operator()(Vector x_E, MaskOf<Vector> kept,
                                                                LaneWork<Vector>& work) const {
        return general_lanes<Sw>(row, x_E, kept, work);
    }
};
template <class Sw, bool Rgb, class Vector>
struct RowLanes<Sw, Rgb, Vector, true> {
    OneSphereRow<Vector, Rgb> one;
    explicit RowLanes(const GeneralRow<Rgb>& row) : one(row) {}
    PROMYK_LANES_INLINE GeneralLanePixel<Vector, Rgb> operator()(Vector x_E, MaskOf<Vector> kept,
                                                                LaneWork<Vector>& work) const {
        return one_sphere_lanes<Sw>(one, x_E, kept, work);
    }
    // The two halves, for a row that finds one vector's hits while it
    // shades the one before.
    PROMYK_LANES_INLINE OneSphereHit<Vector, Rgb> hit(Vector x_E) const { return one_sphere_hit(one, x_E); }
    PROMYK_LANES_INLINE GeneralLanePixel<Vector, Rgb> shade(const OneSphereHit<Vector, Rgb>& h, MaskOf<Vector> kept,
                                                           LaneWork<Vector>& work) const {
        return one_sphere_shade<Sw>(one, h, kept, work);
    }
};

// A row's rays and tests beyond its branches: the shadow rays' and their
// tests, counted lane by lane, and the eye's, `rays` of them, each testing
// every object (one object: its one test). Shared by the rows and the
// sampled rows (render/general_sample_lanes.hpp).
template <bool Many, bool Rgb, class Vector>
PROMYK_LANES_INLINE void count_work(RowCounts& counts, const LaneWork<Vector>& work, const GeneralRow<Rgb>& row,
                                    long long rays) {
    for (int k = 0; k < LaneTraits<Vector>::width; ++k) {
        counts.shadow_rays += work.shadow_rays[k];
        counts.sphere_tests += work.sphere_tests[k];
        counts.plane_tests += work.plane_tests[k];
    }
    if constexpr (Many) {
        counts.sphere_tests += rays * row.sphere_count;
        counts.plane_tests += rays * row.plane_count;
    } else if (row.sphere_count > 0) {
        counts.sphere_tests += rays;
    } else {
        counts.plane_tests += rays;
    }
}

// The row's intensities and branches, every column computed, as
// draw_general_row computes them: for the tests, and for the first
// non-finite pixel of a row that has one (rare). One copy of the pixel's
// steps for both: every copy is compiled once per stage combination and
// instruction set. Its work is not counted.
template <class Sw, bool Rgb, class Vector, class Intensity>
__attribute__((noinline, cold)) void row_pixels(const GeneralRow<Rgb>& row, const double* x_E, int w, Intensity* I_P,
                                                std::uint8_t* branches) {
    LaneWork<Vector> work;
    const RowLanes<Sw, Rgb, Vector> pixels_at{row};
    for_each_vector<Vector>(x_E, w, [&](int j, int n, Vector x, MaskOf<Vector> kept) __attribute__((always_inline)) {
        const GeneralLanePixel<Vector, Rgb> pixel = pixels_at(x, kept, work);
        for (int k = 0; k < n; ++k) {
            if constexpr (Rgb)
                I_P[j + k] = {pixel.I_P.x[k], pixel.I_P.y[k], pixel.I_P.z[k]};
            else
                I_P[j + k] = pixel.I_P[k];
            const Branch branch = pixel.miss[k]         ? Branch::miss
                                  : pixel.non_finite[k] ? Branch::non_finite
                                  : pixel.lit[k]        ? Branch::lit
                                  : pixel.shadowed[k]   ? Branch::shadowed
                                                        : Branch::dark;
            branches[j + k] = static_cast<std::uint8_t>(branch);
        }
    });
}

// The column of the row's first non-finite pixel, the row computed again
// (rare: only a row that has one), a stretch of columns at a time into
// buffers of its own (no heap: std::vector's code, compiled here, could be
// the copy the linker gives every instruction set).
template <class Sw, bool Rgb, class Vector>
__attribute__((noinline, cold)) int first_non_finite(const GeneralRow<Rgb>& row, const double* x_E, int w) {
    using Intensity = typename GeneralRow<Rgb>::Intensity;  // double, or Vec3d for r, g, b
    constexpr int stretch = 256;
    Intensity I_P[stretch];
    std::uint8_t branches[stretch];
    for (int j = 0; j < w; j += stretch) {
        const int n = w - j < stretch ? w - j : stretch;
        row_pixels<Sw, Rgb, Vector>(row, x_E + j, n, I_P, branches);
        for (int k = 0; k < n; ++k)
            if (branches[k] == static_cast<std::uint8_t>(Branch::non_finite)) return j + k;
    }
    return -1;
}

// Row `row` of a w-pixel pane into out (x_E[j] = pane_x(j, w)).
// CountBranches false (render without --stats): of the branches only the
// non-finite pixels are counted, the rest left 0, as the article's rows do;
// the rays and tests are counted either way.
template <class Sw, bool Rgb, class Vector, bool CountBranches = true>
PROMYK_LANES_INLINE RowCounts draw_general_row(const GeneralRow<Rgb>& row, const double* x_E, int w,
                                               std::uint8_t* out) {
    constexpr int width = LaneTraits<Vector>::width;
    using Mask = MaskOf<Vector>;
    Mask miss{}, non_finite{}, lit{}, shadowed{};  // counted lane by lane: a mask is -1 where true
    LaneWork<Vector> work;
    // Pixels j .. j + n - 1 of the row (and, past n, filler not kept). The
    // first non-finite pixel is looked for after the row, in a row that has
    // one: a branch on it in every vector cost more than the counting.
    const auto take = [&](int j, int n, const GeneralLanePixel<Vector, Rgb>& pixel, Mask kept)
                          __attribute__((always_inline)) {
        put_intensities(pixel.I_P, out, j, n);
        if constexpr (CountBranches) {
            miss -= pixel.miss & kept;
            lit -= pixel.lit & kept;
            shadowed -= pixel.shadowed & kept;
        }
        non_finite -= pixel.non_finite & kept;
    };
    const Mask all_kept = lane_not(Mask{});
    const RowLanes<Sw, Rgb, Vector> pixels_at{row};
    int j = 0;
    if constexpr (Sw::one) {
        // One sphere: each vector's hit found while the one before it is
        // shaded, as the article's rows are drawn; and as there, a vector
        // whose every lane misses stores the background's bytes, converted
        // once a row (without skipping, most of the article's pane).
        constexpr int channels = Rgb ? 3 : 1;
        std::uint8_t background[width * channels];
        put_intensities(pixels_at.one.background, background, 0, width);
        struct Shaded {
            GeneralLanePixel<Vector, Rgb> pixel;
            bool background;
        };
        j = pipelined_vectors<Vector>(
            x_E, w, [&](Vector x) __attribute__((always_inline)) { return pixels_at.hit(x); },
            [&](const OneSphereHit<Vector, Rgb>& hit) __attribute__((always_inline)) {
                return Shaded{pixels_at.shade(hit, all_kept, work), hit.background};
            },
            [&](int k, const Shaded& shaded) __attribute__((always_inline)) {
                if (shaded.background) {
                    std::memcpy(out + k * channels, background, sizeof background);
                    if constexpr (CountBranches) miss -= all_kept;
                    return;
                }
                take(k, width, shaded.pixel, all_kept);
            });
    } else {
        // Two vectors a step, computed before either is stored: two
        // independent chains of square roots and divisions in flight at once.
        for (; j + 2 * width <= w; j += 2 * width) {
            Vector x0, x1;
            std::memcpy(&x0, x_E + j, sizeof x0);
            std::memcpy(&x1, x_E + j + width, sizeof x1);
            const GeneralLanePixel<Vector, Rgb> p0 = pixels_at(x0, all_kept, work);
            const GeneralLanePixel<Vector, Rgb> p1 = pixels_at(x1, all_kept, work);
            take(j, width, p0, all_kept);
            take(j + width, width, p1, all_kept);
        }
    }
    for_each_vector<Vector>(x_E + j, w - j, [&](int k, int n, Vector x, Mask kept) __attribute__((always_inline)) {
        take(j + k, n, pixels_at(x, kept, work), kept);
    });
    RowCounts counts;
    int misses = 0, lits = 0, shadoweds = 0, non_finites = 0;
    for (int k = 0; k < width; ++k) {
        misses += static_cast<int>(miss[k]);
        lits += static_cast<int>(lit[k]);
        shadoweds += static_cast<int>(shadowed[k]);
        non_finites += static_cast<int>(non_finite[k]);
    }
    counts.branches[static_cast<int>(Branch::non_finite)] = non_finites;
    if constexpr (CountBranches) {
        counts.branches[static_cast<int>(Branch::miss)] = misses;
        counts.branches[static_cast<int>(Branch::lit)] = lits;
        counts.branches[static_cast<int>(Branch::shadowed)] = shadoweds;
        counts.branches[static_cast<int>(Branch::dark)] = w - misses - lits - shadoweds - non_finites;
    }
    if (non_finites > 0) counts.first_non_finite_j = first_non_finite<Sw, Rgb, Vector>(row, x_E, w);
    count_work<Sw::many>(counts, work, row, w);
    return counts;
}

// The same with the stages, and whether to count the branches, chosen at
// run time (once a row). Only the one-sphere rows have an instantiation
// that does not count: there counting was 7 to 8 % of the row's
// instructions, much of its gap to the article's kernel (docs/bench.md);
// a row of several objects counts, then forgets all but its non-finite
// pixels: a second copy of every row would cost compile time for 0 to 4 %.
template <class Vector, bool Rgb>
PROMYK_LANES_INLINE RowCounts draw_general_row(const GeneralRow<Rgb>& row, GeneralLaneStages stages, const double* x_E,
                                               int w, std::uint8_t* out, bool count_branches) {
    return with_switches(stages, row, [&](auto sw) {
        using Sw = decltype(sw);
        if constexpr (Sw::one)
            if (!count_branches) return draw_general_row<Sw, Rgb, Vector, false>(row, x_E, w, out);
        RowCounts counts = draw_general_row<Sw, Rgb, Vector, true>(row, x_E, w, out);
        if (!count_branches)
            for (int b = 0; b < branch_count; ++b)
                if (b != static_cast<int>(Branch::non_finite)) counts.branches[b] = 0;
        return counts;
    });
}

// The row's intensities and branches, as draw_general_row computes them.
template <class Vector, bool Rgb, class Intensity>
PROMYK_LANES_INLINE void general_row_intensities(const GeneralRow<Rgb>& row, GeneralLaneStages stages,
                                                 const double* x_E, int w, Intensity* I_P, std::uint8_t* branches) {
    with_switches(stages, row,
                  [&](auto sw) { row_pixels<decltype(sw), Rgb, Vector>(row, x_E, w, I_P, branches); });
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
