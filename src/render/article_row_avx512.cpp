// The article's drawn rows in avx512: compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx512, so every template here is
// promyk::lanes::avx512::..., apart from the baseline's copies.
// First: it opens the inline namespace the declarations below extend.
#include "render/article_row_lanes.hpp"
#include "render/article_row_isa.hpp"
#include "render/sample_lanes.hpp"

namespace promyk::lanes {
inline namespace avx512 {  // inline, as lanes.hpp opened it in this file

RowCounts draw_article_row(const ArticleRow<double>& row, const double* x_E, int w, std::uint8_t* out,
                           Formula formula, bool count_branches) {
    return draw_row<Double8>(row, x_E, w, out, formula, count_branches);
}

void article_row_intensities(const ArticleRow<double>& row, const double* x_E, int w, double* I_P,
                             std::uint8_t* branches, Formula formula) {
    row_intensities<Double8>(row, x_E, w, I_P, branches, formula);
}

RowCounts draw_sampled_article_row(const ArticleRow<double>& row, int w, int i, int spp, int lo, int hi,
                                   std::uint8_t* out,
                                   double* I_P, std::uint8_t* branches, Formula formula, bool count_branches) {
    return draw_sampled_row<Double8>(row, w, i, spp, lo, hi, out, I_P, branches, formula, count_branches);
}

}  // namespace avx512
}  // namespace promyk::lanes
