// The article's drawn rows compiled for each wider instruction set
// (render/article_row_lanes.hpp in render/article_row_avx2.cpp and
// ..._avx512.cpp; sampled rows, render/sample_lanes.hpp, there too; float
// rows, sampled ones too, in render/float_row_avx2.cpp and ..._avx512.cpp);
// render_row and
// sampled_row_in_lanes (render/article_row.cpp) and float_row_in_lanes
// (render/float_row.cpp) call the one render/isa.hpp chose. Declared in each set's own namespace, which is
// part of every symbol those files define.
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"

namespace promyk::lanes {

template <class Real>
struct ArticleRow;

// Row `row` into out[0 .. w) with the formula (article, stable or
// geometric); x_E[j] = pane_x(j, w) for the whole pane; count_branches
// false: only non-finite pixels counted (render/article_row_lanes.hpp).
// article_row_intensities: the same row's intensities and branches (bytes of
// Branch), for the tests.
// (In a set's own file lanes.hpp has opened its namespace as inline; naming
// it here without `inline` is allowed and keeps it inline, but clang warns.)
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Winline-namespace-reopened-noninline"
#endif
namespace avx2 {
#include "render/article_row_isa.inc"
}
namespace avx512 {
#include "render/article_row_isa.inc"
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace promyk::lanes
