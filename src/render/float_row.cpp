// --real float's rows in lanes (render/float_row.hpp). Compiled with
// -fno-math-errno (src/CMakeLists.txt), as render/article_row.cpp.
#include "render/float_row.hpp"

#include <cmath>

#include "render/article_lanes.hpp"
#include "render/article_row.hpp"
#include "render/article_row_lanes.hpp"
#include "render/article_row_isa.hpp"
#include "render/isa.hpp"
#include "render/pane.hpp"
#include "render/pane_columns.hpp"
#include "render/sample_lanes.hpp"
#include "render/sample_lanes_span.hpp"
#include "render/silhouette.hpp"
#include "render/skipped_columns.hpp"
#include "render/skipping.hpp"

namespace promyk {

bool float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, std::uint8_t* out, Formula formula,
                        RowCounts& counts) {
#if defined(PROMYK_ISA_KERNELS)
    const lanes::ArticleRow<float> row(world, pane_y<float>(i, w));
    const float* x_E = pane_columns_float(w);
    // Only the columns that may meet the sphere are computed, as in double
    // (render/article_row.cpp), proven with float's bounds on the float
    // scene's own numbers (each exact in double).
    RowSpan span{0, w};
    if (background_skipping()) {
        const lanes::ArticleRow<double> row_d(world_as<double>(world), row.y_E);
        span = row_hit_span(row_d, x_E, w, formula, rounding_of<float>());
    }
    const int n = span.hi - span.lo;
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_float_row(row, x_E + span.lo, n, out + span.lo, formula);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_float_row(row, x_E + span.lo, n, out + span.lo, formula);
            break;
        default:
            counts = lanes::draw_row<lanes::Float4>(row, x_E + span.lo, n, out + span.lo, formula);  // SSE2's four floats
    }
    fill_skipped(span, w, world.background, out, counts);
    // The kernel counted from its first column (the sampled rows count from 0).
    if (counts.first_non_finite_j >= 0) counts.first_non_finite_j += span.lo;
    return true;
#else
    (void)world, (void)w, (void)i, (void)out, (void)formula, (void)counts;
    return false;
#endif
}

bool sampled_float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, int spp, std::uint8_t* out,
                                Formula formula, RowCounts& counts, float* I_P, std::uint8_t* branches,
                                bool count_branches) {
#if defined(PROMYK_ISA_KERNELS)
    if (spp <= 1) return false;
    const float background = sampled_background(world.background, spp);
    // Only the columns whose samples may meet the sphere are computed
    // (render/sample_lanes_span.hpp, with float's bounds).
    const RowSpan span = background_skipping() && std::isfinite(background)
                             ? sampled_row_hit_span(world_as<double>(world), w, i, formula, rounding_of<float>())
                             : RowSpan{0, w};
    // y_E is each sample's own: the row's is not used.
    const lanes::ArticleRow<float> row(world, pane_y<float>(i, w));
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_sampled_float_row(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
                                                           formula, count_branches);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_sampled_float_row(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
                                                         formula, count_branches);
            break;
        default:  // SSE2's four floats, their points in two registers of doubles
            counts = lanes::draw_sampled_row<lanes::Float4>(row, w, i, spp, span.lo, span.hi, out, I_P, branches,
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

}  // namespace promyk
