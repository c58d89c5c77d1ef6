// Samples per pixel (--spp N, PRODUCT.md section 9): spp = 1 is the pixel's
// centre exactly, the article's ray. More samples split the pixel into an
// n x n grid of strata (N = n^2) and put one sample in each stratum, jittered
// by a hash of (i, j, sample): every run, every build and the web page give
// the same samples. The arithmetic is integers and exact binary fractions, so
// a JavaScript port (Math.imul) reproduces it bit for bit.
#pragma once

#include <cstdint>

#include "math/vec3.hpp"

namespace promyk {

inline constexpr int max_spp = 1024;  // a 32 x 32 grid

// Whether N can be a number of samples: a square from 1 to max_spp.
bool valid_spp(int spp);

// n for N = n^2 samples.
int spp_side(int spp);

// A sample's position in its pixel, from the pixel's centre, in pixels:
// u to the right (along j), v down (along i), each in [-1/2, 1/2).
struct SampleOffset {
    double u = 0;
    double v = 0;
};

// The 32-bit hash of (i, j, s) that jitters sample s of pixel (i, j).
std::uint32_t sample_hash(int i, int j, int s);

// Sample s (0 .. spp-1, row by row through the strata) of pixel (i, j).
SampleOffset sample_offset(int i, int j, int s, int spp);

// The sample nearest the pixel's centre (the lowest index on a tie): its
// branch is the pixel's branch.
int centre_sample(int i, int j, int spp);

// The sample's point on the pane: the article's x_E = (2j + 1)/w - 1 and
// y_E = -(2i + 1)/w + 1 with j + 1/2 + u in place of j + 1/2 (and i + 1/2 + v),
// so for spp = 1 (u = v = 0) the same operations give the same bits.
template <class Real>
Vec3<Real> sample_point(int i, int j, int w, Real z_E, SampleOffset o) {
    const Real x = Real(2.0 * j + 1.0 + 2.0 * o.u) / Real(w) - Real(1);
    const Real y = -Real(2.0 * i + 1.0 + 2.0 * o.v) / Real(w) + Real(1);
    return {x, y, z_E};
}

}  // namespace promyk
