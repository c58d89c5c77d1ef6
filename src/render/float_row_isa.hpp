// The float rows (render/float_row.hpp) compiled for each wider instruction
// set (render/float_row_avx2.cpp, ..._avx512.cpp), declared in each set's
// own namespace, as render/article_row_isa.hpp does for double.
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"

namespace promyk::lanes {

template <class Real>
struct ArticleRow;

// Row `row` into out[0 .. w); x_E[j] = pane_x<float>(j, w) for the whole pane.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Winline-namespace-reopened-noninline"
#endif
namespace avx2 {
RowCounts draw_float_row(const ArticleRow<float>& row, const float* x_E, int w, std::uint8_t* out, Formula formula);
}
namespace avx512 {
RowCounts draw_float_row(const ArticleRow<float>& row, const float* x_E, int w, std::uint8_t* out, Formula formula);
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace promyk::lanes
