// The article's drawn rows compiled for each wider instruction set
// (render/article_row_lanes.hpp in render/article_row_avx2.cpp and
// ..._avx512.cpp); render_row (render/article_row.cpp) calls the one
// render/isa.hpp chose. Declared in each set's own namespace, which is
// part of every symbol those files define.
#pragma once

#include <cstdint>

#include "render/kernel.hpp"

namespace promyk::lanes {

template <class Real>
struct ArticleRow;

// Row `row` into out[0 .. w); x_E[j] = pane_x(j, w) for the whole pane.
namespace avx2 {
RowCounts draw_article_row(const ArticleRow<double>& row, const double* x_E, int w, std::uint8_t* out);
}
namespace avx512 {
RowCounts draw_article_row(const ArticleRow<double>& row, const double* x_E, int w, std::uint8_t* out);
}

}  // namespace promyk::lanes
