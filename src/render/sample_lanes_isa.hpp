// Sampled rows (render/sample_lanes.hpp) compiled for each wider instruction
// set, in render/article_row_avx2.cpp and ..._avx512.cpp; article_row.cpp's
// sampled_row_in_lanes calls the one render/isa.hpp chose. Declared in each
// set's own namespace, as render/article_row_isa.hpp does.
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"

namespace promyk::lanes {

template <class Real>
struct ArticleRow;

// Columns [lo, hi) of row i of a w-pixel pane from spp > 1 samples a pixel
// into out[lo .. hi)
// with the formula (article, stable or geometric); I_P and branches, when
// given, get each pixel's mean and Branch.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Winline-namespace-reopened-noninline"
#endif
namespace avx2 {
RowCounts draw_sampled_article_row(const ArticleRow<double>& row, int w, int i, int spp, int lo, int hi,
                                   std::uint8_t* out,
                                   double* I_P, std::uint8_t* branches, Formula formula);
}
namespace avx512 {
RowCounts draw_sampled_article_row(const ArticleRow<double>& row, int w, int i, int spp, int lo, int hi,
                                   std::uint8_t* out,
                                   double* I_P, std::uint8_t* branches, Formula formula);
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace promyk::lanes
