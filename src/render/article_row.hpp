// Rows of the article's scene computed lanes at a time
// (render/article_lanes.hpp) with the article's, the stable or the
// geometric formula, in double and in float; the tests compare them with
// the traced path pixel by pixel. render_row draws rows for rendering.
#pragma once

#include <cstdint>

#include "geometry/formula.hpp"
#include "render/kernel.hpp"
#include "render/tracer.hpp"

namespace promyk {

// How many pixels of a row took each branch (lit: the rest).
struct ArticleRowCounts {
    int miss = 0, dark = 0, non_finite = 0;
};

// Row i of a w-pixel pane of the article's scene into out[0 .. w), with the
// sphere's formula: in lanes on the path render/isa.hpp chose (the wasm: one
// pixel at a time through trace_ray). Each grey level is to_byte of
// trace_ray's intensity, each branch trace_ray's. render/renderer.hpp's
// render_row is this with the article's formula. count_branches false:
// only non-finite pixels are counted (Kernel::counts_branches).
RowCounts render_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* out, Formula formula,
                     bool count_branches = true);

// Row i drawn from spp > 1 samples a pixel (render/samples.hpp), in lanes
// on the path render/isa.hpp chose (render/sample_lanes.hpp), with the
// sphere's formula: each pixel's grey level, branch and counts (RowCounts,
// disagreeing pixels too) bit for bit as render/sampling.hpp's sample_pixel
// over trace_ray gives them. When I_P and branches are given, each pixel's
// mean and Branch (a byte) too, for the tests. count_branches false: only
// non-finite pixels are counted (Kernel::counts_branches). False, and
// nothing drawn, where there are no lanes (the wasm, the fma formula).
bool sampled_row_in_lanes(const ArticleWorld<double>& world, int w, int i, int spp, std::uint8_t* out, Formula formula,
                          RowCounts& counts, double* I_P = nullptr, std::uint8_t* branches = nullptr,
                          bool count_branches = true);

// Row i's intensities into I_P[0 .. w), and, when `branches` is given, each
// pixel's Branch as a byte. Bit for bit what trace_ray gives each pixel
// (article, stable or geometric). In double, on the path render/isa.hpp
// chose (2, 4 or 8 lanes), every column computed.
ArticleRowCounts article_row_intensities(const ArticleWorld<double>& world, int w, int i, double* I_P,
                                         std::uint8_t* branches = nullptr, Formula formula = Formula::article);
// The same in float (four floats a vector, two doubles in double).
ArticleRowCounts article_row_intensities(const ArticleWorld<float>& world, int w, int i, float* I_P,
                                         std::uint8_t* branches = nullptr, Formula formula = Formula::article);

// Pixel (i, j) through the same template with one lane, the instantiation
// the row's last pixels take: for the tests.
PixelResult<double> article_pixel_one_lane(const ArticleWorld<double>& world, int w, int i, int j,
                                           Formula formula = Formula::article);
PixelResult<float> article_pixel_one_lane(const ArticleWorld<float>& world, int w, int i, int j,
                                          Formula formula = Formula::article);

}  // namespace promyk
