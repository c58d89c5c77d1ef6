// The float rows in avx2: compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx2, so every template here is
// promyk::lanes::avx2::..., apart from the baseline's copies.
// First: it opens the inline namespace the declarations below extend.
#include "render/article_row_lanes.hpp"
#include "render/article_row_isa.hpp"
#include "render/sample_lanes.hpp"

namespace promyk::lanes {
inline namespace avx2 {  // inline, as lanes.hpp opened it in this file

RowCounts draw_float_row(const ArticleRow<float>& row, const float* x_E, int w, std::uint8_t* out, Formula formula) {
    return draw_row<Float8>(row, x_E, w, out, formula);
}

RowCounts draw_sampled_float_row(const ArticleRow<float>& row, int w, int i, int spp, int lo, int hi,
                                 std::uint8_t* out, float* I_P, std::uint8_t* branches, Formula formula,
                                 bool count_branches) {
    return draw_sampled_row<Float8>(row, w, i, spp, lo, hi, out, I_P, branches, formula, count_branches);
}

}  // namespace avx2
}  // namespace promyk::lanes
