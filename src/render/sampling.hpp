// A pixel computed from its samples (render/samples.hpp): the mean of the
// samples' intensities, and the centre sample's branch. Shared by both
// kernels, for rendering and for tracing alike, so a traced pixel and a
// rendered one are the same numbers.
#pragma once

#include <cmath>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "render/samples.hpp"
#include "trace/keys.hpp"

namespace promyk {

template <class Intensity>
struct SampledPixel {
    Intensity I_P{};  // the mean of the samples' intensities, summed in sample order
    Branch branch = Branch::miss;  // the centre sample's (non-finite when the mean is)
    int centre = 0;                // the sample nearest the pixel's centre
    int branches[branch_count] = {};  // samples per branch
    bool agree() const {
        for (int count : branches)
            if (count != 0 && count != total()) return false;
        return true;
    }
    int total() const {
        int n = 0;
        for (int count : branches) n += count;
        return n;
    }
};

// Shoots the spp samples of pixel (i, j) of a w x w pane at z_E:
// shoot(s, E) returns the sample's result ({I_P, branch, ...}), and
// on_result(s, result) sees each one (a trace records it; rendering passes a
// no-op).
template <class Intensity, class Real, class Shoot, class OnResult>
SampledPixel<Intensity> sample_pixel(int w, int i, int j, int spp, Real z_E, Shoot&& shoot, OnResult&& on_result) {
    SampledPixel<Intensity> pixel;
    Intensity sum{};
    double nearest = INFINITY;
    Branch centre_branch = Branch::miss;
    // The divisions by n and w, and the cell counted along: no division
    // unit where n or w is a power of two, no integer division ever.
    const int n = spp_side(spp);
    const DivideBy<double> by_n(n);
    const DivideBy<Real> by_w(w);
    int column = 0, row = 0;
    for (int s = 0; s < spp; ++s) {
        const SampleOffset o = spp == 1 ? SampleOffset{} : sample_offset_in_cell(i, j, s, column, row, by_n);
        if (++column == n) column = 0, ++row;
        const auto result = shoot(s, sample_point<Real>(i, j, by_w, z_E, o));
        on_result(s, result);
        sum = s == 0 ? result.I_P : sum + result.I_P;
        ++pixel.branches[static_cast<int>(result.branch)];
        const double d = o.u * o.u + o.v * o.v;
        if (d < nearest) nearest = d, pixel.centre = s, centre_branch = result.branch;
    }
    pixel.I_P = sum / Real(spp);
    pixel.branch = finite_value(pixel.I_P) ? centre_branch : Branch::non_finite;
    return pixel;
}

}  // namespace promyk
