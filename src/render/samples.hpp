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

// A well-mixed 32-bit integer hash (the "lowbias32" of Chris Wellons's hash
// prospector): every input bit affects every output bit. Inline, with the
// offsets below: rendering computes them for every sample.
// Its constants, and sample_hash's, are named for the lanes' copy
// (render/sample_lanes.hpp), which must compute the same integers.
inline constexpr std::uint32_t mix32_k1 = 0x7feb352dU, mix32_k2 = 0x846ca68bU;
inline constexpr std::uint32_t hash_i = 0x9e3779b1U, hash_j = 0x85ebca6bU, hash_s = 0x632be5abU;
inline std::uint32_t mix32(std::uint32_t x) {
    x ^= x >> 16;
    x *= mix32_k1;
    x ^= x >> 15;
    x *= mix32_k2;
    x ^= x >> 16;
    return x;
}

// The 32-bit hash of (i, j, s) that jitters sample s of pixel (i, j). The
// constants keep (0, 0, 0) from hashing to 0 (mix32(0) is 0).
inline std::uint32_t sample_hash(int i, int j, int s) {
    const auto u32 = [](int x) { return static_cast<std::uint32_t>(x); };
    return mix32(u32(i) * hash_i ^ mix32(u32(j) * hash_j ^ mix32(u32(s) + hash_s)));
}

// x / d for a whole number d known before a loop: x times 1/d where d is a
// power of two (1/d is then exact, and both round the same exact quotient
// once: the same bits, subnormal ones too), else the division itself.
template <class Real>
struct DivideBy {
    Real d, inverse;
    bool power_of_two;
    explicit DivideBy(int whole)
        : d(Real(whole)), inverse(Real(1) / Real(whole)), power_of_two(whole > 0 && (whole & (whole - 1)) == 0) {}
    Real operator()(Real x) const { return power_of_two ? x * inverse : x / d; }
};

// Sample s of pixel (i, j) in cell (column, row) = (s mod n, s div n) of an
// n x n grid (by_n divides by n), 16 bits of jitter along each axis (exact
// binary fractions). A loop over the samples counts the cell along.
inline SampleOffset sample_offset_in_cell(int i, int j, int s, int column, int row, const DivideBy<double>& by_n) {
    const std::uint32_t h = sample_hash(i, j, s);
    const double jitter_u = static_cast<double>(h & 0xffffU) / 65536.0;
    const double jitter_v = static_cast<double>(h >> 16) / 65536.0;
    return {by_n(column + jitter_u) - 0.5, by_n(row + jitter_v) - 0.5};
}

// Sample s of pixel (i, j) on an n x n grid (n = spp_side(spp) > 1).
inline SampleOffset sample_offset_on(int i, int j, int s, int n) {
    return sample_offset_in_cell(i, j, s, s % n, s / n, DivideBy<double>(n));
}

// Sample s (0 .. spp-1, row by row through the strata) of pixel (i, j).
SampleOffset sample_offset(int i, int j, int s, int spp);

// The sample nearest the pixel's centre (the lowest index on a tie): its
// branch is the pixel's branch.
int centre_sample(int i, int j, int spp);

// The sample's point on the pane: the article's x_E = (2j + 1)/w - 1 and
// y_E = -(2i + 1)/w + 1 with j + 1/2 + u in place of j + 1/2 (and i + 1/2 + v),
// so for spp = 1 (u = v = 0) the same operations give the same bits.
// by_w divides by Real(w).
template <class Real>
Vec3<Real> sample_point(int i, int j, const DivideBy<Real>& by_w, Real z_E, SampleOffset o) {
    const Real x = by_w(Real(2.0 * j + 1.0 + 2.0 * o.u)) - Real(1);
    const Real y = by_w(-Real(2.0 * i + 1.0 + 2.0 * o.v)) + Real(1);
    return {x, y, z_E};
}
template <class Real>
Vec3<Real> sample_point(int i, int j, int w, Real z_E, SampleOffset o) {
    return sample_point(i, j, DivideBy<Real>(w), z_E, o);
}

}  // namespace promyk
