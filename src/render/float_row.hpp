// Rows of the article's scene in float (--real float), drawn in lanes:
// render/article_lanes.hpp's kernel with float lanes (four, eight or sixteen
// a vector on the path render/isa.hpp chose), every pixel's grey level and
// branch bit for bit trace_ray<float>'s. No background skipping: its proof
// (render/silhouette.hpp) bounds double's rounding, not float's.
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"
#include "render/tracer.hpp"

namespace promyk {

// Row i of a w-pixel pane in float into out[0 .. w), with the formula
// (article, stable or geometric), counted into `counts`. False, and nothing
// drawn, where there are no lanes (the wasm, the fma formula): the caller
// draws the row a pixel at a time.
bool float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, std::uint8_t* out, Formula formula,
                        RowCounts& counts);

}  // namespace promyk
