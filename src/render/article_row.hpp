// A row of the article's scene computed lanes at a time
// (render/article_lanes.hpp), in double and in float; the tests compare it
// with the traced path pixel by pixel. render_row (render/renderer.hpp, defined
// in article_row.cpp) does not use it yet: on the baseline instruction set
// it measured slower than the one-pixel loop.
#pragma once

#include <cstdint>

#include "render/tracer.hpp"

namespace promyk {

// How many pixels of a row took each branch (lit: the rest).
struct ArticleRowCounts {
    int miss = 0, dark = 0, non_finite = 0;
};

// Row i's intensities into I_P[0 .. w), and, when `branches` is given, each
// pixel's Branch as a byte. Bit for bit what trace_ray gives each pixel.
ArticleRowCounts article_row_intensities(const ArticleWorld<double>& world, int w, int i, double* I_P,
                                         std::uint8_t* branches = nullptr);
// The same in float (four floats a vector, two doubles in double).
ArticleRowCounts article_row_intensities(const ArticleWorld<float>& world, int w, int i, float* I_P,
                                         std::uint8_t* branches = nullptr);

// Pixel (i, j) through the same template with one lane, the instantiation
// the row's last pixels take: for the tests.
PixelResult<double> article_pixel_one_lane(const ArticleWorld<double>& world, int w, int i, int j);
PixelResult<float> article_pixel_one_lane(const ArticleWorld<float>& world, int w, int i, int j);

}  // namespace promyk
