// --real float's rows in lanes (render/float_row.hpp). Compiled with
// -fno-math-errno (src/CMakeLists.txt), as render/article_row.cpp.
#include "render/float_row.hpp"

#include "render/article_lanes.hpp"
#include "render/article_row.hpp"
#include "render/article_row_lanes.hpp"
#include "render/article_row_isa.hpp"
#include "render/isa.hpp"
#include "render/pane.hpp"
#include "render/pane_columns.hpp"
#include "render/sample_lanes.hpp"

namespace promyk {

bool float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, std::uint8_t* out, Formula formula,
                        RowCounts& counts) {
#if defined(PROMYK_ISA_KERNELS)
    const lanes::ArticleRow<float> row(world, pane_y<float>(i, w));
    const float* x_E = pane_columns_float(w);
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_float_row(row, x_E, w, out, formula);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_float_row(row, x_E, w, out, formula);
            break;
        default:
            counts = lanes::draw_row<lanes::Float4>(row, x_E, w, out, formula);  // SSE2's four floats
    }
    return true;
#else
    (void)world, (void)w, (void)i, (void)out, (void)formula, (void)counts;
    return false;
#endif
}

bool sampled_float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, int spp, std::uint8_t* out,
                                Formula formula, RowCounts& counts, float* I_P, std::uint8_t* branches) {
#if defined(PROMYK_ISA_KERNELS)
    if (spp <= 1) return false;
    // y_E is each sample's own: the row's is not used.
    const lanes::ArticleRow<float> row(world, pane_y<float>(i, w));
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_sampled_float_row(row, w, i, spp, out, I_P, branches, formula);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_sampled_float_row(row, w, i, spp, out, I_P, branches, formula);
            break;
        default:  // SSE2's four floats, their points in two registers of doubles
            counts = lanes::draw_sampled_row<lanes::Float4>(row, w, i, spp, 0, w, out, I_P, branches, formula);
    }
    return true;
#else
    (void)world, (void)w, (void)i, (void)spp, (void)out, (void)formula, (void)counts, (void)I_P, (void)branches;
    return false;
#endif
}

}  // namespace promyk
