// The article's rows, with the article's, stable or geometric formula: lanes
// at a time (article_chunk, for the tests) and as rendering draws them
// (render_row: the path render/isa.hpp chose, or one pixel at a time where
// there are no lanes, as in the wasm, and for the fma formula).
// Compiled with -fno-math-errno (src/CMakeLists.txt): a square root that need
// not set errno becomes one sqrtpd for its lanes, with the same bits.
#include "render/article_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "image/quantize.hpp"
#include "render/article_lanes.hpp"
#include "render/article_row_isa.hpp"
#include "render/article_row_lanes.hpp"
#include "render/isa.hpp"
#include "render/pane_columns.hpp"
#include "render/renderer.hpp"
#include "render/sample_lanes.hpp"
#include "render/sample_lanes_span.hpp"
#include "render/silhouette.hpp"
#include "render/skipped_columns.hpp"
#include "render/skipping.hpp"

namespace promyk {

namespace {

template <class Lane, class Real>
void put_branches(const lanes::LanePixel<Lane>& pixel, int width, std::uint8_t* out) {
    for (int k = 0; k < width; ++k) {
        const Branch branch = lanes::lane_of(pixel.miss, k)         ? Branch::miss
                              : lanes::lane_of(pixel.non_finite, k) ? Branch::non_finite
                              : lanes::lane_of(pixel.dark, k)       ? Branch::dark
                                                                    : Branch::lit;
        out[k] = static_cast<std::uint8_t>(branch);
    }
}

// Columns j0 .. j0 + n - 1 of row i into I_P[0 .. n): whole vectors first,
// then the last pixels one lane at a time, through the same template.
template <class Vector, template <class> class Root, class Real>
ArticleRowCounts article_chunk(const ArticleWorld<Real>& world, int w, int i, int j0, int n, Real* I_P,
                               std::uint8_t* branches = nullptr) {
    constexpr int width = lanes::LaneTraits<Vector>::width;
    const lanes::ArticleRow<Real> row(world, pane_y<Real>(i, w));
    ArticleRowCounts counts;
    // Counted lane by lane in vectors (a mask is -1 where true), summed once.
    lanes::MaskOf<Vector> miss{}, dark{}, non_finite{};
    const int end = j0 + n;
    int j = j0;
    for (; j + width <= end; j += width) {
        // x_E := (2j + 1)/w - 1, lane by lane.
        Vector x_E;
        for (int k = 0; k < width; ++k) x_E[k] = Real(2 * (j + k) + 1);
        x_E = x_E / Real(w) - Real(1);
        const lanes::LanePixel<Vector> pixel = lanes::article_lanes<Root>(row, x_E);
        std::memcpy(I_P + (j - j0), &pixel.I_P, sizeof pixel.I_P);
        miss -= pixel.miss;
        dark -= pixel.dark;
        non_finite -= pixel.non_finite;
        if (branches) put_branches<Vector, Real>(pixel, width, branches + (j - j0));
    }
    for (int k = 0; k < width; ++k) {
        counts.miss += static_cast<int>(miss[k]);
        counts.dark += static_cast<int>(dark[k]);
        counts.non_finite += static_cast<int>(non_finite[k]);
    }
    for (; j < end; ++j) {
        const lanes::LanePixel<Real> pixel = lanes::article_lanes<Root>(row, pane_x<Real>(j, w));
        I_P[j - j0] = pixel.I_P;
        counts.miss += pixel.miss;
        counts.dark += pixel.dark;
        counts.non_finite += pixel.non_finite;
        if (branches) put_branches<Real, Real>(pixel, 1, branches + (j - j0));
    }
    return counts;
}

#if !defined(PROMYK_ISA_KERNELS)
// n grey levels of I_P[0 .. n) into out: to_byte (image/quantize.hpp) two
// pixels at a time, by the drawn rows' put_grey_levels (as a loop of scalar
// to_byte, GCC makes the rounding a branch, mispredicted along every
// gradient).
void put_row_bytes(const double* I_P, int n, std::uint8_t* out) {
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        lanes::Double2 v;
        std::memcpy(&v, I_P + k, sizeof v);
        lanes::put_grey_levels(v, out + k, 2);
    }
    for (; k < n; ++k) out[k] = to_byte(I_P[k]);
}
#endif

template <template <class> class Root, class Real>
PixelResult<Real> one_lane(const ArticleWorld<Real>& world, int w, int i, int j) {
    const lanes::LanePixel<Real> pixel =
        lanes::article_lanes<Root>(lanes::ArticleRow<Real>(world, pane_y<Real>(i, w)), pane_x<Real>(j, w));
    std::uint8_t branch;
    put_branches<Real, Real>(pixel, 1, &branch);
    return {pixel.I_P, static_cast<Branch>(branch)};
}

template <class Real>
PixelResult<Real> one_lane(const ArticleWorld<Real>& world, int w, int i, int j, Formula formula) {
    return lanes::with_root(formula, [&](auto root) { return one_lane<decltype(root)::template Root>(world, w, i, j); });
}

template <class Vector, class Real>
ArticleRowCounts row_intensities(const ArticleWorld<Real>& world, int w, int i, Real* I_P, std::uint8_t* branches,
                                 Formula formula) {
    return lanes::with_root(formula, [&](auto root) {
        return article_chunk<Vector, decltype(root)::template Root>(world, w, i, 0, w, I_P, branches);
    });
}

}  // namespace

PixelResult<double> article_pixel_one_lane(const ArticleWorld<double>& world, int w, int i, int j, Formula formula) {
    return one_lane(world, w, i, j, formula);
}
PixelResult<float> article_pixel_one_lane(const ArticleWorld<float>& world, int w, int i, int j, Formula formula) {
    return one_lane(world, w, i, j, formula);
}

ArticleRowCounts article_row_intensities(const ArticleWorld<double>& world, int w, int i, double* I_P,
                                         std::uint8_t* branches, Formula formula) {
#if defined(PROMYK_ISA_KERNELS)
    // The wider paths' own vectors (render/article_row_isa.hpp).
    const Isa isa = article_isa();
    if (isa != Isa::baseline) {
        const lanes::ArticleRow<double> row(world, pane_y<double>(i, w));
        const double* x_E = pane_columns(w);
        std::vector<std::uint8_t> taken(static_cast<std::size_t>(w));
        if (isa == Isa::avx512)
            lanes::avx512::article_row_intensities(row, x_E, w, I_P, taken.data(), formula);
        else
            lanes::avx2::article_row_intensities(row, x_E, w, I_P, taken.data(), formula);
        ArticleRowCounts counts;
        for (const std::uint8_t b : taken) {
            counts.miss += b == static_cast<std::uint8_t>(Branch::miss);
            counts.dark += b == static_cast<std::uint8_t>(Branch::dark);
            counts.non_finite += b == static_cast<std::uint8_t>(Branch::non_finite);
        }
        if (branches) std::memcpy(branches, taken.data(), taken.size());
        return counts;
    }
#endif
    return row_intensities<lanes::Double2>(world, w, i, I_P, branches, formula);
}

ArticleRowCounts article_row_intensities(const ArticleWorld<float>& world, int w, int i, float* I_P,
                                         std::uint8_t* branches, Formula formula) {
    return row_intensities<lanes::Float4>(world, w, i, I_P, branches, formula);
}

namespace {
#if defined(PROMYK_ISA_KERNELS)
// Row i in lanes with the formula, on the path render/isa.hpp chose.
RowCounts lanes_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out, Formula formula,
                    bool count) {
    const lanes::ArticleRow<double> row(world, pane_y<double>(i, w));
    const double* x_E = pane_columns(w);
    // Only the columns that may meet the sphere are computed; the others are
    // proven misses (render/silhouette.hpp) and get the background's grey.
    // The proof is of the program's delta, which the stable formula computes
    // too (the same operations on the same numbers, so the same bits); the
    // geometric formula's delta_g is proven with a margin for its own roundings.
    const RowSpan span = background_skipping() ? row_hit_span(row, x_E, w, formula) : RowSpan{0, w};
    const int n = span.hi - span.lo;
    RowCounts counts;
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_article_row(row, x_E + span.lo, n, out + span.lo, formula, count);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_article_row(row, x_E + span.lo, n, out + span.lo, formula, count);
            break;
        default:
            // SSE2's two lanes: 57 instructions a pixel against 68 one pixel
            // at a time (callgrind, w = 1024), and no slower measured.
            counts = lanes::draw_row<lanes::Double2>(row, x_E + span.lo, n, out + span.lo, formula, count);
    }
    fill_skipped(span, w, world.background, out, counts);
    // The kernel counted from its first column (the sampled rows count from 0).
    if (counts.first_non_finite_j >= 0) counts.first_non_finite_j += span.lo;
    return counts;
}
#endif

#if !defined(PROMYK_ISA_KERNELS)
// A row one pixel at a time through trace_ray with the formula F: where
// there is no lane path (the wasm, processors other than x86-64, the fuzz
// build).
template <class F>
RowCounts one_pixel_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out) {
    // A local copy: stores through a uint8_t* may alias anything, so reading the
    // scene through a reference would reload it, and keep |S|^2 from being
    // hoisted, on every pixel.
    // y_E is computed once a row: GCC will not hoist a division out of a loop
    // by itself (it might trap), and the result is the same double.
    const ArticleWorld<double> local = world;
    const double y_E = pane_y<double>(i, w);
    NullRecorder none;
    // Counted in registers: an array indexed by the branch would be a store
    // and a load per pixel, chained from one pixel to the next.
    int miss = 0, dark = 0, non_finite = 0;
    // Intensities first, a chunk at a time, then their grey levels in a loop
    // of its own: measured 8.0 against 8.6 ns a pixel for one loop doing both.
    constexpr int chunk = 256;
    double I_P[chunk];
    for (int j0 = 0; j0 < w; j0 += chunk) {
        const int n = std::min(chunk, w - j0);
        for (int k = 0; k < n; ++k) {
            const PixelResult<double> pixel = trace_ray<F>(local, {pane_x<double>(j0 + k, w), y_E, local.z_E}, none);
            I_P[k] = pixel.I_P;
            miss += pixel.branch == Branch::miss;
            dark += pixel.branch == Branch::dark;
            non_finite += pixel.branch == Branch::non_finite;
        }
        put_row_bytes(I_P, n, out + j0);
    }
    RowCounts counts;
    counts.sphere_tests = w;  // one sphere, one primary ray a pixel
    counts.branches[static_cast<int>(Branch::miss)] = miss;
    counts.branches[static_cast<int>(Branch::dark)] = dark;
    counts.branches[static_cast<int>(Branch::non_finite)] = non_finite;
    counts.branches[static_cast<int>(Branch::lit)] = w - miss - dark - non_finite;
    // Rare: looked for only when the row has one, so the loop stays lean.
    if (counts.branches[static_cast<int>(Branch::non_finite)] != 0) {
        for (int j = 0; j < w && counts.first_non_finite_j < 0; ++j)
            if (trace_ray<F>(local, {pane_x<double>(j, w), y_E, local.z_E}, none).branch == Branch::non_finite)
                counts.first_non_finite_j = j;
    }
    return counts;
}
#endif

}  // namespace

bool sampled_row_in_lanes(const ArticleWorld<double>& world, int w, int i, int spp, std::uint8_t* out, Formula formula,
                          RowCounts& counts, double* I_P, std::uint8_t* branches, bool count_branches) {
#if defined(PROMYK_ISA_KERNELS)
    if (spp <= 1) return false;
    const double background = sampled_background(world.background, spp);
    // Only the columns whose samples may meet the sphere are computed; the
    // others are proven misses (render/sample_lanes_span.hpp).
    const RowSpan span = background_skipping() && std::isfinite(background)
                             ? sampled_row_hit_span(world, w, i, formula)
                             : RowSpan{0, w};
    // y_E is each sample's own: the row's is not used.
    const lanes::ArticleRow<double> row(world, pane_y<double>(i, w));
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_sampled_article_row(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
                                                             formula, count_branches);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_sampled_article_row(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
                                                           formula, count_branches);
            break;
        default:
            counts = lanes::draw_sampled_row<lanes::Double2>(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
                                                             formula, count_branches);
    }
    fill_skipped(span, w, background, out, counts, I_P, branches);
    return true;
#else
    (void)world, (void)w, (void)i, (void)spp, (void)out, (void)formula, (void)counts, (void)I_P, (void)branches,
        (void)count_branches;
    return false;
#endif
}

RowCounts render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out) {
    return render_row(world, w, i, out, Formula::article);
}

RowCounts render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out, Formula formula,
                     bool count_branches) {
#if defined(PROMYK_ISA_KERNELS)
    return lanes_row(world, w, i, out, formula, count_branches);
#else
    (void)count_branches;  // one pixel at a time, counting costs nothing worth saving
    switch (formula) {
        case Formula::stable:
            return one_pixel_row<SphereFormula<Formula::stable>>(world, w, i, out);
        case Formula::geometric:
            return one_pixel_row<SphereFormula<Formula::geometric>>(world, w, i, out);
        case Formula::fma:
            return one_pixel_row<SphereFormula<Formula::fma>>(world, w, i, out);
        case Formula::article:
            break;
    }
    return one_pixel_row<SphereFormula<Formula::article>>(world, w, i, out);
#endif
}

}  // namespace promyk
