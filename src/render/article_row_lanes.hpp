// A drawn row of the article's scene, a vector of pixels at a time: the
// intensities of render/article_lanes.hpp turned into grey levels and counted
// by branch. Included by one translation unit per instruction set
// (render/article_row_avx2.cpp, ..._avx512.cpp), each compiling it in its own
// namespace (PROMYK_LANES_ISA). Calls nothing that is not inlined: a shared
// function compiled here would carry this instruction set into the others.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "render/article_lanes.hpp"
#include "render/kernel.hpp"
#include "render/row_vectors.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// A vector's grey levels as 64-bit integers, and its bytes, lane for lane.
typedef std::int64_t Int64x2 __attribute__((vector_size(16)));
typedef std::int64_t Int64x4 __attribute__((vector_size(32)));
typedef std::int64_t Int64x8 __attribute__((vector_size(64)));
typedef std::uint8_t Byte2 __attribute__((vector_size(2)));
typedef std::uint8_t Byte4 __attribute__((vector_size(4)));
typedef std::uint8_t Byte8 __attribute__((vector_size(8)));
template <class Vector>
struct GreyTypes;
template <>
struct GreyTypes<Double2> {
    using Ints = Int64x2;
    using Bytes = Byte2;
};
template <>
struct GreyTypes<Double4> {
    using Ints = Int64x4;
    using Bytes = Byte4;
};
template <>
struct GreyTypes<Double8> {
    using Ints = Int64x8;
    using Bytes = Byte8;
};

// The low byte of each 64-bit lane, as __builtin_convertvector narrows
// them. GCC 12 narrows AVX2's four lanes (and SSE2's two) one at a time
// through general registers, fifteen instructions for four; a shuffle of
// the bytes takes five. AVX-512 narrows in one instruction (vpmovqb).
template <class Bytes, class Ints>
PROMYK_LANES_INLINE Bytes low_bytes(Ints x) {
#if !defined(__AVX512F__)
    typedef std::uint8_t Octets16 __attribute__((vector_size(16)));
    typedef std::uint8_t Octets32 __attribute__((vector_size(32)));
    if constexpr (sizeof(Ints) == 32) {
        const Octets32 b = reinterpret_cast<Octets32>(x);
        return __builtin_shufflevector(b, b, 0, 8, 16, 24);
    } else if constexpr (sizeof(Ints) == 16) {
        const Octets16 b = reinterpret_cast<Octets16>(x);
        return __builtin_shufflevector(b, b, 0, 8);
    }
#endif
    return __builtin_convertvector(x, Bytes);
}

// image/quantize.hpp's to_byte, lane by lane: clamp to [0, 1] (NaN to 0),
// scale by 255, and round a half up; the same bytes by another way that
// stays in double lanes (to_byte's truncation to int and back crossed
// between lane widths twice). y + 2^52 rounds y (0 <= y <= 255) to the
// nearest integer, a tie to the even one, and holds that integer in its
// low bits; r = (y + 2^52) - 2^52 is it as a double (both exact). A tie
// rounded down (y - r = +1/2) goes up, as to_byte rounds it; one rounded up
// (y - r = -1/2) already has. tests/grey_levels_test.cpp compares every
// width with to_byte at every tie and its neighbours.
template <class Vector, std::enable_if_t<std::is_same_v<typename LaneTraits<Vector>::Real, double>, int> = 0>
PROMYK_LANES_INLINE void put_grey_levels(Vector v, std::uint8_t* out, int n) {
    using Ints = typename GreyTypes<Vector>::Ints;
    using Bytes = typename GreyTypes<Vector>::Bytes;
    constexpr double two_52 = 4503599627370496.0;  // 2^52: from here on, doubles are integers
    const Vector positive = select(v > 0.0, v, splat<Vector>(0.0));  // also NaN -> 0
    const Vector clamped = select(positive < 1.0, positive, splat<Vector>(1.0));
    const Vector y = clamped * 255.0;
    const Vector shifted = y + two_52;  // 2^52 + round(y), a tie to even
    const Vector r = shifted - two_52;
    Ints bits;
    std::memcpy(&bits, &shifted, sizeof bits);  // round(y) in the low bits
    const Ints tie_down = (y - r) == 0.5;       // -1 where true
    const Bytes grey = low_bytes<Bytes>(bits - tie_down);
    std::memcpy(out, &grey, static_cast<std::size_t>(n));
}

// Floats (--real float): to_byte takes each intensity as a double, exactly,
// so the lanes widen to doubles (a float is one exactly) and go on as above,
// a half at a time: half the floats as doubles fill the same register. A
// template, so that only the instruction set that draws a width compiles it.
typedef float Float2 __attribute__((vector_size(8)));
template <class Floats>
struct FloatHalves;
template <>
struct FloatHalves<Float4> {
    using Half = Float2;
    using Doubles = Double2;
};
template <>
struct FloatHalves<Float8> {
    using Half = Float4;
    using Doubles = Double4;
};
template <>
struct FloatHalves<Float16> {
    using Half = Float8;
    using Doubles = Double8;
};
template <class Floats, std::enable_if_t<std::is_same_v<typename LaneTraits<Floats>::Real, float>, int> = 0>
PROMYK_LANES_INLINE void put_grey_levels(Floats v, std::uint8_t* out, int n) {
    using Half = typename FloatHalves<Floats>::Half;
    using Doubles = typename FloatHalves<Floats>::Doubles;
    constexpr int half = LaneTraits<Floats>::width / 2;
    Half low, high;
    std::memcpy(&low, &v, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&v) + sizeof low, sizeof high);
    put_grey_levels(__builtin_convertvector(low, Doubles), out, n < half ? n : half);
    if (n > half) put_grey_levels(__builtin_convertvector(high, Doubles), out + half, n - half);
}

// Pixels j .. j + n - 1 (n <= the width) into out: grey levels, or r, g, b.
template <class Vector>
PROMYK_LANES_INLINE void put_intensities(Vector I_P, std::uint8_t* out, int j, int n) {
    put_grey_levels(I_P, out + j, n);
}
template <class Vector>
PROMYK_LANES_INLINE void put_intensities(const Vec3<Vector>& I_P, std::uint8_t* out, int j, int n) {
    constexpr int width = LaneTraits<Vector>::width;
    std::uint8_t r[width], g[width], b[width];
    put_grey_levels(I_P.x, r, n);
    put_grey_levels(I_P.y, g, n);
    put_grey_levels(I_P.z, b, n);
    for (int k = 0; k < n; ++k) {
        out[3 * (j + k)] = r[k];
        out[3 * (j + k) + 1] = g[k];
        out[3 * (j + k) + 2] = b[k];
    }
}

// The row's non-finite pixels, counted, and the first one's column, into
// counts: the row computed again with its branches' masks, for a row where
// a drawn intensity was not finite (rare: kept out of the drawing loop).
template <class Vector, template <class> class Root, class Real>
__attribute__((noinline, cold)) void count_non_finite(const ArticleRow<Real>& row, const Real* x_E, int w,
                                                      RowCounts& counts) {
    constexpr int width = LaneTraits<Vector>::width;
    int non_finites = 0;
    for_each_vector<Vector>(x_E, w, [&](int j, int, Vector x, MaskOf<Vector> kept) {
        const MaskOf<Vector> non_finite = article_lanes<Root>(row, x).non_finite & kept;
        for (int k = 0; k < width; ++k) {
            if (!lane_of(non_finite, k)) continue;
            if (counts.first_non_finite_j < 0) counts.first_non_finite_j = j + k;
            ++non_finites;
        }
    });
    counts.branches[static_cast<int>(Branch::non_finite)] = non_finites;
}

// How draw_row finds a vector's non-finite pixels, as measured on one Intel
// processor (docs/bench.md): for 8 doubles, by one comparison of the
// intensities; for the others (16 floats included), by the non-finite
// mask that article_shade computes anyway.
template <class Vector>
constexpr bool intensity_tells_finite =
    sizeof(Vector) >= 64 && std::is_same_v<typename LaneTraits<Vector>::Real, double>;

// Row `row` of a w-pixel pane into out[0 .. w), with the sphere's formula
// Root (render/article_lanes.hpp): x_E[j] is pane_x(j, w), given for the
// whole pane (columns share it; computing it here would cost each pixel a
// division). The last vector is filled past w and only its first pixels
// are kept. CountBranches false: the miss and dark counts are left 0; the
// non-finite pixels are always counted.
template <class Vector, template <class> class Root = ArticleRoot, bool CountBranches = true,
          class Real = typename LaneTraits<Vector>::Real>
PROMYK_LANES_INLINE RowCounts draw_row(const ArticleRow<Real>& row, const Real* x_E, int w, std::uint8_t* out) {
    constexpr int width = LaneTraits<Vector>::width;
    using Mask = MaskOf<Vector>;
    Mask miss{}, dark{};  // counted lane by lane: a mask is -1 where true
    // The lanes that are, or may be, non-finite pixels: the row's own count
    // and first one are found apart, where there are any (rare). A
    // non-finite pixel's intensity is NaN or infinite.
    Mask not_finite{};
    // The background's grey levels, stored as they are where a whole vector
    // misses: without skipping, most of the pane (there 8 to 15 % faster;
    // in the skipped rows' spans, where such vectors are few, 0 to 3 %
    // slower: docs/bench.md).
    std::uint8_t background[width];
    put_grey_levels(splat<Vector>(row.world.background), background, width);
    // Pixels j .. j + n - 1 of the row (the lanes `kept`).
    const auto take = [&](int j, int n, const LanePixel<Vector>& pixel, Mask kept) __attribute__((always_inline)) {
        if (n == width && pixel.background) {
            std::memcpy(out + j, background, width);
            if constexpr (CountBranches) miss -= ~Mask{};
            return;
        }
        put_grey_levels(pixel.I_P, out + j, n);
        if constexpr (CountBranches) {
            miss -= pixel.miss & kept;
            dark -= pixel.dark & kept;
        }
        if constexpr (intensity_tells_finite<Vector>)
            not_finite = either(not_finite, both(kept, lane_not(pixel.I_P <= std::numeric_limits<Real>::max())));
        else
            not_finite = either(not_finite, both(kept, pixel.non_finite));
    };
    // Each vector's hit found while the one before it is shaded
    // (docs/bench.md: 10 % faster on AVX-512, 15 % on SSE2, 23 % on AVX2
    // than whole vectors in turn); then the rest, fewer than a vector's.
    const int j = pipelined_vectors<Vector>(
        x_E, w, [&](Vector x) __attribute__((always_inline)) { return article_hit<Root>(row, x); },
        [&](const LaneHit<Vector>& hit) __attribute__((always_inline)) { return article_shade(row, hit); },
        [&](int k, const LanePixel<Vector>& pixel) __attribute__((always_inline)) { take(k, width, pixel, ~Mask{}); });
    for_each_vector<Vector>(x_E + j, w - j, [&](int k, int n, Vector x, Mask kept) __attribute__((always_inline)) {
        take(j + k, n, article_lanes<Root>(row, x), kept);
    });
    RowCounts counts;
    counts.sphere_tests = w;  // one sphere, one primary ray a pixel
    if (any(not_finite)) count_non_finite<Vector, Root>(row, x_E, w, counts);
    if constexpr (!CountBranches) return counts;
    int missed = 0, darks = 0;
    for (int k = 0; k < width; ++k) {
        missed += static_cast<int>(miss[k]);
        darks += static_cast<int>(dark[k]);
    }
    const int non_finites = counts.branches[static_cast<int>(Branch::non_finite)];
    counts.branches[static_cast<int>(Branch::miss)] = missed;
    counts.branches[static_cast<int>(Branch::dark)] = darks;
    counts.branches[static_cast<int>(Branch::lit)] = w - missed - darks - non_finites;
    return counts;
}

// Row `row`'s intensities into I_P[0 .. w) and each pixel's Branch into
// branches[0 .. w), as draw_row computes them (for the tests: the bits
// before the grey levels).
template <class Vector, template <class> class Root>
PROMYK_LANES_INLINE void row_intensities(const ArticleRow<double>& row, const double* x_E, int w, double* I_P,
                                         std::uint8_t* branches) {
    constexpr int width = LaneTraits<Vector>::width;
    for (int j = 0; j < w; j += width) {
        const int n = w - j < width ? w - j : width;
        Vector x = splat<Vector>(x_E[j]);
        for (int k = 0; k < n; ++k) x[k] = x_E[j + k];
        const LanePixel<Vector> pixel = article_lanes<Root>(row, x);
        for (int k = 0; k < n; ++k) {
            I_P[j + k] = pixel.I_P[k];
            const Branch branch = pixel.miss[k]         ? Branch::miss
                                  : pixel.non_finite[k] ? Branch::non_finite
                                  : pixel.dark[k]       ? Branch::dark
                                                        : Branch::lit;
            branches[j + k] = static_cast<std::uint8_t>(branch);
        }
    }
}

template <class Vector>
PROMYK_LANES_INLINE void row_intensities(const ArticleRow<double>& row, const double* x_E, int w, double* I_P,
                                         std::uint8_t* branches, Formula formula) {
    return with_root(formula, [&](auto root) {
        return row_intensities<Vector, decltype(root)::template Root>(row, x_E, w, I_P, branches);
    });
}

// draw_row with the formula chosen at run time (once a row): the article's,
// stable or geometric; fma has no lanes. count_branches: CountBranches.
template <class Vector, class Real = typename LaneTraits<Vector>::Real>
PROMYK_LANES_INLINE RowCounts draw_row(const ArticleRow<Real>& row, const Real* x_E, int w, std::uint8_t* out,
                                       Formula formula, bool count_branches = true) {
    return with_root(formula, [&](auto root) {
        using R = decltype(root);
        return count_branches ? draw_row<Vector, R::template Root, true>(row, x_E, w, out)
                              : draw_row<Vector, R::template Root, false>(row, x_E, w, out);
    });
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
