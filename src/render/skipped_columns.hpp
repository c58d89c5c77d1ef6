// The columns of a row proven background (render/silhouette.hpp,
// render/sample_lanes_span.hpp), filled as the kernel would have drawn
// them, for the double and the float rows alike (render/article_row.cpp,
// render/float_row.cpp).
#pragma once

#include <cstdint>
#include <cstring>

#include "image/quantize.hpp"
#include "render/kernel.hpp"
#include "render/silhouette.hpp"

namespace promyk {

// A skipped pixel's intensity from spp samples: spp misses, each the
// background, summed in sample order and divided as sample_pixel does (not
// always the background itself).
template <class Real>
Real sampled_background(Real background, int spp) {
    Real sum = background;
    for (int s = 1; s < spp; ++s) sum = sum + background;
    return sum / static_cast<Real>(spp);
}

// Columns [0, span.lo) and [span.hi, w) of a row: the grey level of
// `background` (the pixel's intensity), and, when given, that intensity
// and the miss branch; counted as skipped misses.
template <class Real>
void fill_skipped(RowSpan span, int w, Real background, std::uint8_t* out, RowCounts& counts, Real* I_P = nullptr,
                  std::uint8_t* branches = nullptr) {
    const std::uint8_t grey = to_byte(background);
    std::memset(out, grey, static_cast<std::size_t>(span.lo));
    std::memset(out + span.hi, grey, static_cast<std::size_t>(w - span.hi));
    if (I_P || branches) {
        for (int j = 0; j < w; ++j) {
            if (j == span.lo) j = span.hi;
            if (j >= w) break;
            if (I_P) I_P[j] = background;
            if (branches) branches[j] = static_cast<std::uint8_t>(Branch::miss);
        }
    }
    const int skipped = w - (span.hi - span.lo);
    counts.skipped = skipped;
    counts.branches[static_cast<int>(Branch::miss)] += skipped;
}

}  // namespace promyk
