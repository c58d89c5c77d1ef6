// How a row is walked a vector of pixels at a time, for the article's rows
// (render/article_row_lanes.hpp) and the general tracer's
// (render/general_row_lanes.hpp): every vector whole, the last filled past
// the row's end; or whole vectors in a pipeline, each vector's hit found
// while the one before it is shaded.
#pragma once

#include <cstring>

#include "render/lanes.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// Calls f(j, n, x, kept) for each vector of row pixels j .. j + n - 1, x
// their x_E and kept the lanes within the row. The last vector is filled
// past n with x_E[j] (computed, and not kept).
template <class Vector, class Real, class F>
PROMYK_LANES_INLINE void for_each_vector(const Real* x_E, int w, F&& f) {
    constexpr int width = LaneTraits<Vector>::width;
    using Mask = MaskOf<Vector>;
    int j = 0;
    for (; j + width <= w; j += width) {
        Vector x;
        std::memcpy(&x, x_E + j, sizeof x);
        f(j, width, x, ~Mask{});
    }
    if (j < w) {
        Vector x = splat<Vector>(x_E[j]);
        Mask kept{};
        for (int k = 0; k < w - j; ++k) x[k] = x_E[j + k], kept[k] = -1;
        f(j, w - j, x, kept);
    }
}

// The whole vectors of a row of w pixels, as take(j, shade(hit(x))) for
// the vector at column j, with vector j + 1's hit found before vector j is
// shaded: a hit (where the ray meets the sphere: a square root and a
// division) and a shading (the light's: another pair) are independent
// chains, so the processor keeps both in flight, where one vector's steps
// would wait on each other (docs/bench.md). Returns the columns done, a
// multiple of the width; the rest is for for_each_vector.
template <class Vector, class Real, class Hit, class Shade, class Take>
PROMYK_LANES_INLINE int pipelined_vectors(const Real* x_E, int w, Hit&& hit, Shade&& shade, Take&& take) {
    constexpr int width = LaneTraits<Vector>::width;
    if (w < width) return 0;
    Vector x;
    std::memcpy(&x, x_E, sizeof x);
    auto ahead = hit(x);
    int j = 0;
    for (; j + 2 * width <= w; j += width) {
        std::memcpy(&x, x_E + j + width, sizeof x);
        const auto next = hit(x);
        take(j, shade(ahead));
        ahead = next;
    }
    take(j, shade(ahead));
    return j + width;
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
