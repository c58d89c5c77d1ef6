// Rows of the article's scene in float (--real float), drawn in lanes:
// render/article_lanes.hpp's kernel with float lanes (four, eight or sixteen
// a vector on the path render/isa.hpp chose), every pixel's grey level and
// branch bit for bit trace_ray<float>'s; from spp > 1 samples a pixel too
// (render/sample_lanes.hpp), as sample_pixel over trace_ray<float> gives
// them. Background is skipped as in double, proven with float's bounds
// (render/silhouette.hpp, render/sample_lanes_span.hpp).
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"
#include "render/tracer.hpp"

namespace promyk {

// Row i of a w-pixel pane in float into out[0 .. w), with the formula,
// counted into `counts`. False, and nothing drawn, where there are no lanes
// (the wasm): the caller draws the row a pixel at a time.
bool float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, std::uint8_t* out, Formula formula,
                        RowCounts& counts);

// The same from spp > 1 samples a pixel (false, too, for spp 1): each
// pixel's grey level, branch and counts (disagreeing pixels too) bit for
// bit sample_pixel's over trace_ray<float>. When I_P and branches are given,
// each pixel's mean and Branch (a byte) too, for the tests. count_branches
// false: only non-finite pixels are counted.
bool sampled_float_row_in_lanes(const ArticleWorld<float>& world, int w, int i, int spp, std::uint8_t* out,
                                Formula formula, RowCounts& counts, float* I_P = nullptr,
                                std::uint8_t* branches = nullptr, bool count_branches = true);

}  // namespace promyk
