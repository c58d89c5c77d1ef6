// A row drawn from spp > 1 samples a pixel (render/samples.hpp), in lanes:
// each lane one pixel, the vector's pixels side by side, all taking sample s
// at once, s = 0 .. spp - 1 in order. Each lane then sums its pixel's
// intensities in sample order, counts its branches and keeps its centre
// sample's, as render/sampling.hpp's sample_pixel does, and the sample's
// point is computed by the same operations as sample_point, so every pixel
// has the one-pixel path's bits (tests/sample_lanes_test.cpp). In double or
// in float (--real float): a float kernel's points are computed in float
// lanes where n is a power of two (every number exact, sample_point_lanes),
// else in two registers of doubles as sample_point computes them, rounded
// to float where it does. Included by one translation unit per instruction
// set, like render/article_row_lanes.hpp; calls nothing that is not inlined
// but sample_column_hashes, once a row (render/sample_hashes.cpp, compiled
// for the baseline).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "render/article_lanes.hpp"
#include "render/article_row_lanes.hpp"
#include "render/intensity_lanes.hpp"
#include "render/kernel.hpp"
#include "render/sample_hashes.hpp"
#include "render/samples.hpp"
#include "render/whole_divisor.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// n lanes as unsigned 32-bit integers (the hash) and as signed ones (to
// convert the jitter to double: it is below 2^16).
template <int n>
struct SampleInts;
template <>
struct SampleInts<2> {
    typedef std::uint32_t U __attribute__((vector_size(8)));
    typedef std::int32_t I __attribute__((vector_size(8)));
};
template <>
struct SampleInts<4> {
    typedef std::uint32_t U __attribute__((vector_size(16)));
    typedef std::int32_t I __attribute__((vector_size(16)));
};
template <>
struct SampleInts<8> {
    typedef std::uint32_t U __attribute__((vector_size(32)));
    typedef std::int32_t I __attribute__((vector_size(32)));
};
template <>
struct SampleInts<16> {
    typedef std::uint32_t U __attribute__((vector_size(64)));
    typedef std::int32_t I __attribute__((vector_size(64)));
};
template <class Vector>
using UintsOf = typename SampleInts<LaneTraits<Vector>::width>::U;
template <class Vector>
using IntsOf = typename SampleInts<LaneTraits<Vector>::width>::I;

// The double vector a kernel's samples are placed in where they are
// computed in double (sample_point computes in double): the kernel's own in
// double; in float, a register of doubles, half as many as the floats, so a
// float vector's points are two of them (a vector of sixteen doubles, wider
// than any register, GCC keeps in memory and compares lane by lane).
// `real`: a part's coordinates rounded to the kernel's Real.
template <class Lane>
struct PointLanes {
    using type = Lane;
    using real = Lane;
};
template <>
struct PointLanes<Float4> {
    using type = Double2;
    using real = Float2;
};
template <>
struct PointLanes<Float8> {
    using type = Double4;
    using real = Float4;
};
template <>
struct PointLanes<Float16> {
    using type = Double8;
    using real = Float8;
};
template <class Lane>
using PointsOf = typename PointLanes<Lane>::type;
// How many point vectors a kernel's vector has: 1 in double, 2 in float.
template <class Lane>
inline constexpr int parts_of = LaneTraits<Lane>::width / LaneTraits<PointsOf<Lane>>::width;

// Part k of a vector v of `parts` parts (a half, a register's worth): by
// memcpy, which GCC compiles to an extract. A vector joined from its parts:
// by a shuffle of the two registers (through memory, GCC stored the halves
// and loaded them as one, a store-forwarding stall a sample).
template <class Part, class Vector>
PROMYK_LANES_INLINE Part part_of(const Vector& v, int k) {
    Part part;
    std::memcpy(&part, reinterpret_cast<const char*>(&v) + k * sizeof part, sizeof part);
    return part;
}
template <class Part, std::size_t... k>
PROMYK_LANES_INLINE auto joined_lanes(Part low, Part high, std::index_sequence<k...>) {
    return __builtin_shufflevector(low, high, k...);
}
template <class Vector, class Part, int parts>
PROMYK_LANES_INLINE Vector joined(const Part (&p)[parts]) {
    static_assert(parts == 1 || parts == 2);
    static_assert(sizeof(Vector) == parts * sizeof(Part));
    if constexpr (parts == 1) {
        return p[0];
    } else {
        constexpr std::size_t n = sizeof(Part) / sizeof(p[0][0]);
        return joined_lanes(p[0], p[1], std::make_index_sequence<2 * n>{});
    }
}

// Signed 32-bit lanes to doubles, __builtin_convertvector's value: GCC 12
// splits a widening conversion into halves (AVX2's four lanes: two
// conversions, a shuffle and an insert; AVX-512's eight likewise), where
// one vcvtdq2pd converts them all. SSE2's two lanes it converted one at a
// time through general registers (seven instructions where cvtdq2pd and a
// move are two).
template <class Points, class Ints>
PROMYK_LANES_INLINE Points widened(Ints x) {
    static_assert(std::is_same_v<std::remove_cv_t<std::remove_reference_t<decltype(x[0])>>, std::int32_t>);
    static_assert(std::is_same_v<std::remove_cv_t<std::remove_reference_t<decltype(Points{}[0])>>, double>);
#if defined(__AVX512F__)
    if constexpr (sizeof(Ints) == 32 && sizeof(Points) == 64)
        // Every lane kept (GCC drops the mask); the unmasked intrinsic
        // warns of an uninitialised variable inside GCC 12's header.
        return reinterpret_cast<Points>(_mm512_maskz_cvtepi32_pd(0xff, reinterpret_cast<__m256i>(x)));
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(Ints) == 8 && sizeof(Points) == 16) {
        long long bits;
        std::memcpy(&bits, &x, sizeof bits);
        return reinterpret_cast<Points>(_mm_cvtepi32_pd(_mm_cvtsi64_si128(bits)));
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(Ints) == 16 && sizeof(Points) == 32)
        return reinterpret_cast<Points>(_mm256_cvtepi32_pd(reinterpret_cast<__m128i>(x)));
#endif
    return __builtin_convertvector(x, Points);
}

// Half k (0 or 1) of two vectors' 32-bit lanes side by side (a pair's
// jitter, draw_sampled_row), to doubles: the half's conversion reads its
// part of the register (no move to a register of its own first).
template <class Points, class Pair>
PROMYK_LANES_INLINE Points widened_half(Pair x, int k) {
#if defined(__AVX__)
    if constexpr (sizeof(Pair) == 32 && sizeof(Points) == 32) {
        const __m256i v = reinterpret_cast<__m256i>(x);
        return reinterpret_cast<Points>(
            _mm256_cvtepi32_pd(k == 0 ? _mm256_castsi256_si128(v) : _mm256_extractf128_si256(v, 1)));
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(Pair) == 16 && sizeof(Points) == 16) {
        const __m128i v = reinterpret_cast<__m128i>(x);
        return reinterpret_cast<Points>(_mm_cvtepi32_pd(k == 0 ? v : _mm_unpackhi_epi64(v, v)));
    }
#endif
    using Half = typename SampleInts<LaneTraits<Points>::width>::I;
    return widened<Points>(part_of<Half>(x, k));
}

// A sample's branch code a lane: unsigned integers as wide as the kernel's
// masks (64 bits in double, 32 in float).
template <class Lane>
struct CodeLanes {
    using Mask = MaskOf<Lane>;
    using Element = std::make_unsigned_t<std::remove_cv_t<std::remove_reference_t<decltype(Mask{}[0])>>>;
    typedef Element type __attribute__((vector_size(sizeof(Mask))));
};
template <class Lane>
using CodeOf = typename CodeLanes<Lane>::type;

// render/samples.hpp's mix32, on one integer or on lanes (its own copy:
// the shared inline one must not be compiled here).
template <class U>
PROMYK_LANES_INLINE U mix32_lanes(U x) {
    x ^= x >> 16;
    x *= mix32_k1;
    x ^= x >> 15;
    x *= mix32_k2;
    x ^= x >> 16;
    return x;
}

#if defined(__SSE2__) && !defined(__SSE4_1__)
// Two lanes without SSE4.1's 32-bit multiply (the baseline path's double
// lanes): GCC multiplies each lane apart in a general register (25
// instructions a hash). Here each lane sits in the low half of a 64-bit
// lane, where SSE2's pmuludq multiplies both at once; the product's low 32
// bits are mix32's (arithmetic mod 2^32), the high ones cleared before the
// shifts read them: 13 instructions, the same bits.
PROMYK_LANES_INLINE SampleInts<2>::U mix32_lanes(SampleInts<2>::U x) {
    typedef std::uint64_t Wide __attribute__((vector_size(16)));
    const Wide low = {0xffffffffU, 0xffffffffU};
    Wide y = reinterpret_cast<Wide>(__builtin_shufflevector(x, SampleInts<2>::U{}, 0, 2, 1, 3));
    const auto times = [&](Wide v, std::uint32_t k) __attribute__((always_inline)) {
        return reinterpret_cast<Wide>(_mm_mul_epu32(reinterpret_cast<__m128i>(v), _mm_set1_epi32(static_cast<int>(k)))) &
               low;
    };
    y ^= y >> 16;
    y = times(y, mix32_k1);
    y ^= y >> 15;
    y = times(y, mix32_k2);
    y ^= y >> 16;
    const SampleInts<4>::U halves = reinterpret_cast<SampleInts<4>::U>(y);
    return __builtin_shufflevector(halves, halves, 0, 2);
}
#endif

// ArticleRow with the sample's height in each lane: y_E and the products
// with it are lanes, the rest the row's (the same products, the same bits).
template <class Lane>
struct SampleRow {
    using Real = typename LaneTraits<Lane>::Real;
    const ArticleWorld<Real>& world;
    Lane y_E, yy, ySy;
    Real zz, zSz, SS, rr, SS_rr;
    PROMYK_LANES_INLINE SampleRow(const ArticleRow<Real>& row, Lane y)
        : world(row.world), y_E(y), yy(y * y), ySy(y * row.world.S.y), zz(row.zz), zSz(row.zSz), SS(row.SS),
          rr(row.rr), SS_rr(row.SS_rr) {}
};

// x * (1/d) in place of x / d where d is a power of two (Exact): 1/d is
// exact, so both are the correctly rounded value of the same exact x / d,
// the same bits (subnormal results too: IEEE rounds both the same way; the
// product cannot overflow, and a NaN or infinity stays what it was).
// Otherwise a division, or for the samples' coordinates in double (Whole)
// two fmas (render/whole_divisor.hpp). Chosen once a row: the cell's as a
// template argument, so the sample loop has no branch on it; w's at run
// time (divided_by_w); the mean's once a pixel (MeanDivisor). d is n in the lanes' own precision, as sample_point's
// Real(w) and sample_pixel's Real(spp).
PROMYK_LANES_INLINE bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }
template <class Vector, bool Exact, bool Whole = false>
struct Divisor {
    using Real = typename LaneTraits<Vector>::Real;
    static constexpr bool fused = Whole && fused_multiply_add && std::is_same_v<Real, double>;
    static constexpr bool exact = Exact;
    Real d, reciprocal;
    WholeDivisor<Vector, fused> whole;
    explicit Divisor(double b) : d(Real(b)), reciprocal(Real(1) / Real(b)), whole(b) {}
    PROMYK_LANES_INLINE Vector divide(Vector x) const {
        if constexpr (Exact) return x * reciprocal;
        else if constexpr (fused) return whole.divide(x);
        else return x / d;
    }
};
template <class Vector>
struct MeanDivisor {
    using Real = typename LaneTraits<Vector>::Real;
    Real d, reciprocal;
    bool exact;
    explicit MeanDivisor(int n) : d(Real(n)), reciprocal(Real(1) / Real(n)), exact(power_of_two(n)) {}
    PROMYK_LANES_INLINE Vector divide(Vector x) const { return exact ? x * reciprocal : x / d; }
};

// A sample's branch as one unsigned integer a lane, its fields 11 bits wide
// (spp is at most 1024 = 2^10): 1 at bit 0 if it missed, at bit 11 if dark,
// at bit 22 if non-finite, at bit 33 if shadowed (the general tracer's, in
// double: 64-bit codes), lit: none (the branches exclude each other).
// Summed, the fields count a pixel's samples per branch; the centre sample's
// is kept whole. One vector where three masks were: a third of the selects
// and registers. In 32 bits the non-finite field holds 1023: 1024 such
// samples wrap the sum to 0, "all lit", which agrees as "all non-finite"
// does, and the sums serve only to tell whether the samples agree.
constexpr int miss_field = 0, dark_field = 11, non_finite_field = 22, shadowed_field = 33;
template <class Code>
inline constexpr bool has_shadowed_field = sizeof(Code{}[0]) == 8;
template <class Code, class Mask>
PROMYK_LANES_INLINE Code branch_code(Mask miss, Mask dark, Mask non_finite) {
    using Element = std::remove_reference_t<decltype(Code{}[0])>;
    constexpr Element one = 1;
    return (reinterpret_cast<Code>(miss) & (one << miss_field)) | (reinterpret_cast<Code>(dark) & (one << dark_field)) |
           (reinterpret_cast<Code>(non_finite) & (one << non_finite_field));
}
template <class Code, class Mask>
PROMYK_LANES_INLINE Code branch_code(Mask miss, Mask dark, Mask non_finite, Mask shadowed) {
    static_assert(has_shadowed_field<Code>);
    using Element = std::remove_reference_t<decltype(Code{}[0])>;
    constexpr Element one = 1;
    return branch_code<Code>(miss, dark, non_finite) | (reinterpret_cast<Code>(shadowed) & (one << shadowed_field));
}

// a == b lane by lane, a mask. SSE2 has no 64-bit compare (pcmpeqq is
// SSE4.1's): GCC compared each lane of the baseline path's codes in a
// general register, about ten instructions a lane and nine compares a
// pixel vector. Here the 32-bit halves are compared and each lane's two
// halves joined: three instructions a vector, the same mask.
template <class Code>
PROMYK_LANES_INLINE auto equal_codes(Code a, Code b) {
    using Mask = decltype(a == b);
#if defined(__SSE2__) && !defined(__SSE4_1__)
    if constexpr (sizeof(Code) == 16 && sizeof(a[0]) == 8) {
        typedef std::int32_t Halves __attribute__((vector_size(16)));
        const Halves equal = reinterpret_cast<Halves>(a) == reinterpret_cast<Halves>(b);
        return reinterpret_cast<Mask>(equal & __builtin_shufflevector(equal, equal, 1, 0, 3, 2));
    }
#endif
    return Mask(a == b);
}

// The pixels of one vector of the kernel's lanes: their sums (grey levels,
// or r, g, b), branch counts and centre samples.
template <class Lane, class Intensity = Lane>
struct SampledLanes {
    using Points = PointsOf<Lane>;
    static constexpr int parts = parts_of<Lane>;
    using Code = CodeOf<Lane>;
    int j;                // the first lane's column
    Points x0[parts]{};   // 2 j + 1, each lane's pixel, divided by SampleGrid::s
    Points x_base[parts]{};  // (2 j + 1) / w - 1, on a whole grid (SampleGrid::whole)
    Points x_magic[parts]{};  // SampleGrid::magic_half - x_base (magic_pair_points)
    Lane x0_real{};       // the same in the lanes' Real (each set only where it is read)
    // The nearest sample yet when the points are in float (nearer_in_real):
    // its float d (infinite before the first sample), u and v.
    Lane nearest_real = splat<Lane>(INFINITY), nearest_u{}, nearest_v{};
    UintsOf<Lane> j_hash{};  // j hash_j (on the baseline, only without the column table)
    // The first sample's intensity x is -0 + x, all of x's bits (+0 + x
    // would make a -0 +0), and its d is below infinity.
    Intensity sum = every_channel<Lane, !std::is_same_v<Intensity, Lane>>(-0.0);
    Points nearest[parts]{};  // each part's from splat<Points>(INFINITY)
    Code branches{};  // samples per branch, summed branch_codes
    Code centre{};    // the centre sample's branch_code
};

// The row's numbers that do not change from sample to sample.
struct SampleGrid {
    int i, w, spp, n;
    double minus_y0;  // -(2 i + 1)
    // The scale of the points' steps in double (sample_point_lanes): w
    // where it is a power of two (w_exact), else 1; its reciprocal (exact,
    // kept: a sample reads it, never divides) and minus_y0 / s.
    double s = 1, one_over_s = 1, minus_y0_s = 0;
    // n and w powers of two (double lanes): each sample's point is a whole
    // number of `step`s from the pixel's centre, computed without dividing
    // (sample_point_lanes): y_base = 1 - (2 i + 1) / w, step = 2^-15 / (n w),
    // half_cell = 2^15 n. w_exact: w a power of two, whatever n.
    bool whole = false, w_exact = false;
    double y_base = 0, step = 0;
    std::int32_t half_cell = 0;
    // A whole grid's points from the jitter's bits (magic_pair_points):
    // magic = 2^52 step, magic_half = magic + 1/w (half_cell steps) and
    // y_magic = (y_base + 1/w) + magic, each a multiple of step below
    // 2 magic (exact) where n w <= 2^30 (magic_fits; w is at most 2^15).
    bool magic_fits = false;
    double magic = 0, magic_half = 0, y_magic = 0;
    std::uint32_t magic_high = 0;  // magic's high 32 bits (its low ones are 0)
    std::uint32_t i_hash;
    ColumnHashes columns;  // the hash's (j, s) part (render/sample_hashes.hpp), or null
};

// Sample s, its cell (column, row) = (s mod n, s div n), counted along (no
// division a sample). Its hash, mix32(s + hash_s), only where the column
// hashes are not in a table (sample_point_lanes): computed on every sample,
// it was twelve instructions a pair of vectors that nothing read.
struct SampleCounter {
    std::uint32_t column = 0, row = 0;
    int s = 0;
    PROMYK_LANES_INLINE void next(std::uint32_t n) {
        ++s;
        if (++column == n) column = 0, ++row;
    }
};

// The hashes of a pair of vectors' samples (draw_sampled_row's pair_points),
// all spp of them computed as the pair starts, in a loop of their own. Each
// sample then reads its hash where it computed mix32 (two multiplies that
// SSE2 emulates): computed in the sample loop, on the chain from the column
// table to the point and the early outs, the hash made the baseline's full
// rows at spp 9 about 11 % slower, with the same instructions but for a
// load and a store a sample (docs/bench.md). On: 16 KB of stack on the
// baseline path, 32 KB on AVX2's (max_spp hashes). Off (no pair hashes):
// empty.
template <class PairInts, bool on>
struct PairHashes {
    PROMYK_LANES_INLINE void fill(const SampleGrid&, int) {}
};
template <class PairInts>
struct PairHashes<PairInts, true> {
    PairInts h[max_spp];
    // Columns j .. of the table, read as sample_point_lanes reads them.
    PROMYK_LANES_INLINE void fill(const SampleGrid& grid, int j) {
        for (int s = 0; s < grid.spp; ++s) {
            PairInts column;
            std::memcpy(&column, grid.columns.hashes + static_cast<std::ptrdiff_t>(s) * grid.columns.stride + j,
                        sizeof column);
            h[s] = mix32_lanes(grid.i_hash ^ column);
        }
    }
};

// A sample's point E = (x, y, z_E) in each lane, and d, its offset's squared
// distance from the pixel's centre (in double, as sample_pixel compares it).
// InReal: the point was computed in float lanes (sample_point_lanes), its
// offset (u, v) is exact in them and d is their float u² + v², compared
// with a margin (take_result).
template <class Lane, bool InReal = false>
struct SamplePoint {
    Lane x, y;
    PointsOf<Lane> d[parts_of<Lane>];
};
template <class Lane>
struct SamplePoint<Lane, true> {
    Lane x, y, u, v, d;
};
// Such a point's offset (u, v), all that is computed a sample ahead
// (draw_sampled_row): the hash is the work, and x, y and d, a few
// operations from u and v, would hold three more registers a vector in
// flight (sixteen floats: GCC spilled registers every sample). Double
// lanes keep the whole point ahead: the same split there was slower on the
// baseline path (PROMYK_ISA=baseline bench effects --w 256 --spp 9, art.
// full 1.54-1.72 -> 1.75-1.83 a sample x spp 1, 2026-12-04).
template <class Lane>
struct OffsetLanes {
    Lane u, v;
};

// a / w, as sample_point divides by Real(w): where w is a power of two
// (grid.w_exact, the same every sample of a row), the multiply by 1/w,
// the same bits as Divisor's.
template <class Lane, class WDivisor>
PROMYK_LANES_INLINE Lane divided_by_w(const SampleGrid& grid, const WDivisor& by_w, Lane a) {
    if (grid.w_exact) return a * by_w.reciprocal;
    return by_w.divide(a);
}

// A sample's jitter in double lanes, the whole numbers U = 2^16 (s mod n)
// + h_u - grid.half_cell and V likewise (h_u, h_v: the hash's low and high
// 16 bits; half_cell is 0 where the grid is not whole), converted
// (widened). Below 2^31 in size: exact in double.
template <class Ints>
struct SampleJitter {
    Ints U, V;
};
template <class Ints, class U>
PROMYK_LANES_INLINE SampleJitter<Ints> sample_jitter(const SampleGrid& grid, const SampleCounter& c, U h) {
    const std::uint32_t half_cell = static_cast<std::uint32_t>(grid.half_cell);
    return {reinterpret_cast<Ints>((h & 0xffffU) + ((c.column << 16) - half_cell)),
            reinterpret_cast<Ints>((h >> 16) + ((c.row << 16) - half_cell))};
}

// The point of a sample in double lanes (Lane: doubles) from its jitter U,
// V converted to doubles, as sample_point computes it.
template <class Lane, class Intensity, class CellDivisor, class WDivisor>
PROMYK_LANES_INLINE SamplePoint<Lane> point_of_jitter(const SampleGrid& grid, const CellDivisor& by_cell,
                                                      const WDivisor& by_w, const SampledLanes<Lane, Intensity>& p,
                                                      Lane U, Lane V) {
    SamplePoint<Lane> E;
    // A whole grid, decided once a row (a branch taken the same way every
    // sample: one instantiation for w a power of two or not cost 0 to
    // 0.7 % a sample against two, 2026-12-05).
    if (grid.whole) {
        // n and w powers of two: u = U / (2^16 n), |U| <= 2^15 n <= 2^20,
        // and sample_point's steps are all exact (x0 + 2 u, dividing by w,
        // subtracting 1: at most 20 + log2 w bits), so x is the exact
        // (2 j + 1) / w - 1 + U 2^-15 / (n w): a product and a sum, both
        // exact, the same bits; y likewise. d is u² + v² scaled by
        // (2^16 n)², exact too (at most 41 bits), ordered the same.
        E.x = p.x_base[0] + U * grid.step;
        E.y = grid.y_base - V * grid.step;
        E.d[0] = U * U + V * V;
        return E;
    }
    // sample_point's steps scaled by 2 / s (SampleGrid::s, 1 or w, a power
    // of two either way): U is 2^16 (s mod n) + h_u, so by_cell's division
    // by 2^15 n s (draw_sampled_row) gives 2 q / s for sample_offset_on's q
    // = (s mod n + h_u 2^-16) / n (the same exact quotient, rounded once),
    // and subtracting 1 / s gives 2 u / s; x0 is (2 j + 1) / s, so x0 +
    // 2 u / s, rounded once, is sample_point's x0 + 2 u rounded and divided
    // by s. A power of two changes no rounding (nothing here comes near
    // underflow): the same bits, without the products by 2, and by 1 / w
    // where w is a power of two. d is u² + v² times 4 / s², ordered the
    // same. -(y0 + 2 v) is (-y0) - 2 v but for a zero's sign, which adding
    // 1 erases.
    const double half = grid.one_over_s;  // 1/2, scaled
    const Lane u = by_cell.divide(U) - half, v = by_cell.divide(V) - half;
    const Lane x = p.x0[0] + u, y = grid.minus_y0_s - v;
    E.d[0] = u * u + v * v;
    if (grid.w_exact) {  // divided by w already
        E.x = x - 1.0;
        E.y = y + 1.0;
    } else {
        E.x = by_w.divide(x) - 1.0;
        E.y = by_w.divide(y) + 1.0;
    }
    return E;
}

#if defined(__SSE2__) && !defined(__SSE4_1__)
// A pair of two-lane vectors' points on a whole grid (the baseline path's
// double lanes), from the hash h of their four pixels: the jitter's whole
// numbers U' = 2^16 (s mod n) + h_u and V' likewise (below 2^22; the half
// cell not subtracted) in the low 32 bits of magic's bits make the double
// magic + U' step (magic = 2^52 step, whose ulp is step): one unpack a
// vector where converting and scaling took three instructions. Then
// x = (magic + U' step) - (magic_half - x_base) = x_base + (U' - half_cell)
// step, point_of_jitter's exact x, rounded once to the same bits (+0 where
// it is 0, as there); y = y_magic - (magic + V' step) likewise. d (WithD):
// u² + v² with u = U step, exact (at most 41 bits, scaled by step²), so
// ordered as point_of_jitter's. On the article's scene at spp 4, 1.4 %
// fewer instructions a sample and 2.5 % less time (docs/bench.md).
inline constexpr bool magic_points = true;
template <bool WithD, class Pixels>
PROMYK_LANES_INLINE void magic_pair_points(const SampleGrid& grid, const SampleCounter& c, SampleInts<4>::U h,
                                           const Pixels& p0, const Pixels& p1, SamplePoint<Double2>& E0,
                                           SamplePoint<Double2>& E1) {
    const SampleInts<4>::U U = (h & 0xffffU) + (c.column << 16), V = (h >> 16) + (c.row << 16);
    const __m128i high = _mm_set1_epi32(static_cast<int>(grid.magic_high));
    const auto magic_plus = [&](SampleInts<4>::U x, int k) __attribute__((always_inline)) {
        const __m128i v = reinterpret_cast<__m128i>(x);
        return reinterpret_cast<Double2>(k == 0 ? _mm_unpacklo_epi32(v, high) : _mm_unpackhi_epi32(v, high));
    };
    const Double2 U0 = magic_plus(U, 0), U1 = magic_plus(U, 1), V0 = magic_plus(V, 0), V1 = magic_plus(V, 1);
    E0.x = U0 - p0.x_magic[0];
    E1.x = U1 - p1.x_magic[0];
    E0.y = grid.y_magic - V0;
    E1.y = grid.y_magic - V1;
    if constexpr (WithD) {
        const Double2 u0 = U0 - grid.magic_half, v0 = V0 - grid.magic_half;
        const Double2 u1 = U1 - grid.magic_half, v1 = V1 - grid.magic_half;
        E0.d[0] = u0 * u0 + v0 * v0;
        E1.d[0] = u1 * u1 + v1 * v1;
    }
}
#else
inline constexpr bool magic_points = false;
template <bool WithD, class... Arguments>
void magic_pair_points(const Arguments&...);  // only declared: its caller's branch is discarded
#endif

// Sample c.s's point for the vector's pixels, as sample_point computes it:
// in double, x's and y's numerators rounded to the kernel's Real before
// by_w divides them by Real(w). In float lanes with an exact cell, only
// its offset (OffsetLanes; point_at gives the point).
template <class Lane, class Intensity, class CellDivisor, class WDivisor>
PROMYK_LANES_INLINE auto sample_point_lanes(const SampleGrid& grid, const CellDivisor& by_cell,
                                                         const WDivisor& by_w, const SampleCounter& c,
                                                         const SampledLanes<Lane, Intensity>& p) {
    using Points = PointsOf<Lane>;
    using RealPart = typename PointLanes<Lane>::real;
    using Real = typename LaneTraits<Lane>::Real;
    using I = IntsOf<Lane>;
    constexpr int parts = parts_of<Lane>;
    // sample_offset_on: the hash's 16 bits of jitter along each axis. Its
    // (s mod n + jitter_u) / n is (2^16 (s mod n) + h_u) / (2^16 n), the same
    // exact quotient rounded once (the numerator, below 2^31, and 2^16 n are
    // exact in double), so one conversion and one division give its bits.
    UintsOf<Lane> column;  // mix32(j hash_j ^ mix32(s + hash_s)): the same in every row
    if (grid.columns.hashes)
        std::memcpy(&column, grid.columns.hashes + static_cast<std::ptrdiff_t>(c.s) * grid.columns.stride + p.j,
                    sizeof column);
    else
        column = mix32_lanes(p.j_hash ^ mix32_lanes(static_cast<std::uint32_t>(c.s) + hash_s));
    const auto h = mix32_lanes(grid.i_hash ^ column);
    if constexpr (parts == 1 && std::is_same_v<Real, double>) {
        // A whole grid, decided once a row (a branch taken the same way
        // every sample: one instantiation for w a power of two or not cost
        // 0 to 0.7 % a sample against two, 2026-12-05).
        if (grid.whole) {
            // n and w powers of two: u = U / (2^16 n) with the whole number
            // U = 2^16 (s mod n) + h_u - 2^15 n, |U| <= 2^15 n <= 2^20, and
            // sample_point's steps are all exact (x0 + 2 u, dividing by w,
            // subtracting 1: at most 20 + log2 w bits), so x is the exact
            // (2 j + 1) / w - 1 + U 2^-15 / (n w): a product and a sum, both
            // exact, the same bits; y likewise. d is u² + v² scaled by
            // (2^16 n)², exact too (at most 41 bits), ordered the same.
            const I U = reinterpret_cast<I>(h & 0xffffU) +
                        static_cast<std::int32_t>((c.column << 16) - static_cast<std::uint32_t>(grid.half_cell));
            const I V = reinterpret_cast<I>(h >> 16) +
                        static_cast<std::int32_t>((c.row << 16) - static_cast<std::uint32_t>(grid.half_cell));
            const Lane u = widened<Lane>(U), v = widened<Lane>(V);
            SamplePoint<Lane> E;
            E.x = p.x_base[0] + u * grid.step;
            E.y = grid.y_base - v * grid.step;
            E.d[0] = u * u + v * v;
            return E;
        }
    }
    const I h_u = reinterpret_cast<I>((h & 0xffffU) | (c.column << 16));
    const I h_v = reinterpret_cast<I>((h >> 16) | (c.row << 16));
    if constexpr (parts > 1 && CellDivisor::exact) {
        // Float lanes, n a power of two: u = (2^16 (s mod n) + h_u) / (2^16 n)
        // - 1/2 is exact in float as in double (a numerator below 2^21, a
        // power of two, and a multiple of 2^-21 below 1/2), and so are
        // x0 = 2 j + 1 and -y0 (below 2^23: draw_sampled_row checks w);
        // x0 + 2 u is exact in double (at most 53 bits from 2w down to
        // 2^-20), so float's x0 + 2 u, rounded once, is sample_point's
        // Real(x0 + 2 u): the point in float lanes, d in double from the
        // same exact u and v.
        // The point itself: point_at.
        const Real cell = static_cast<Real>(by_cell.reciprocal);  // 2^-16 / n, exact
        return OffsetLanes<Lane>{__builtin_convertvector(h_u, Lane) * cell - Real(0.5),
                                  __builtin_convertvector(h_v, Lane) * cell - Real(0.5)};
    } else {
        // sample_point's steps scaled by 2 / s (SampleGrid::s, 1 or w, a
        // power of two either way): by_cell divides by 2^15 n s
        // (draw_sampled_row), giving 2 q / s for its q, and subtracting 1 / s
        // gives 2 u / s; x0 is (2 j + 1) / s, so x0 + 2 u / s, rounded once,
        // is sample_point's x0 + 2 u rounded and divided by s. A power of
        // two changes no rounding (nothing here comes near underflow): the
        // same bits, without the products by 2, and by 1 / w where w is a
        // power of two. d is u² + v² times 4 / s², ordered the same.
        const double half = grid.one_over_s;  // 1/2, scaled
        SamplePoint<Lane> E;
        RealPart x[parts], y[parts];  // the numerators of sample_point's divisions, scaled
        for (int k = 0; k < parts; ++k) {
            const Points u = by_cell.divide(widened<Points>(part_of<IntsOf<Points>>(h_u, k))) - half;
            const Points v = by_cell.divide(widened<Points>(part_of<IntsOf<Points>>(h_v, k))) - half;
            // sample_point. -(y0 + 2 v) is (-y0) - 2 v but for a zero's sign,
            // which adding 1 erases (rounding to float is symmetric:
            // -Real(y0 + 2 v) is Real(-(y0 + 2 v)), the same bits).
            x[k] = __builtin_convertvector(p.x0[k] + u, RealPart);
            y[k] = __builtin_convertvector(grid.minus_y0_s - v, RealPart);
            E.d[k] = u * u + v * v;
        }
        if (grid.w_exact) {  // divided by w already
            E.x = joined<Lane>(x) - Real(1);
            E.y = joined<Lane>(y) + Real(1);
        } else {
            E.x = by_w.divide(joined<Lane>(x)) - Real(1);
            E.y = by_w.divide(joined<Lane>(y)) + Real(1);
        }
        return E;
    }
}

// The point of sample_point_lanes' offset in float lanes (above); any
// other point as it is.
template <class Lane, class Intensity, class WDivisor>
PROMYK_LANES_INLINE SamplePoint<Lane, true> point_at(const OffsetLanes<Lane>& o, const SampleGrid& grid,
                                                     const WDivisor& by_w, const SampledLanes<Lane, Intensity>& p) {
    using Real = typename LaneTraits<Lane>::Real;
    SamplePoint<Lane, true> E;
    E.u = o.u, E.v = o.v;
    E.x = divided_by_w(grid, by_w, p.x0_real + Real(2) * o.u) - Real(1);
    E.y = divided_by_w(grid, by_w, static_cast<Real>(grid.minus_y0) - Real(2) * o.v) + Real(1);
    E.d = o.u * o.u + o.v * o.v;
    return E;
}
template <class Lane, class Intensity, class WDivisor>
PROMYK_LANES_INLINE const SamplePoint<Lane>& point_at(const SamplePoint<Lane>& E, const SampleGrid&, const WDivisor&,
                                                      const SampledLanes<Lane, Intensity>&) {
    return E;
}

// Whether each lane's sample (u, v exact floats) is nearer its pixel's
// centre than the nearest yet, d = u² + v² < d_nearest exactly, as
// sample_pixel compares them in double (where both are exact). Float's
// d = fl(fl(u²) + fl(v²)) is within a relative 3·2^-24 of the exact one (u
// and v are multiples of 2^-21: no underflow), so a float d below
// d_nearest (1 - 2^-19) or above d_nearest (1 + 2^-19), the products
// rounded too, decides it; a lane between (a tie, or nearly) is compared in
// double: rare. The nearest's u, v and float d kept.
template <class Lane, class Intensity>
PROMYK_LANES_INLINE MaskOf<Lane> nearer_in_real(const SamplePoint<Lane, true>& E, SampledLanes<Lane, Intensity>& p) {
    using Real = typename LaneTraits<Lane>::Real;
    using Mask = MaskOf<Lane>;
    using Points = PointsOf<Lane>;
    using RealPart = typename PointLanes<Lane>::real;
    constexpr Real margin = Real(1) / Real(1 << 19);
    Mask nearer = E.d < p.nearest_real * (Real(1) - margin);
    const Mask decided = either(nearer, E.d > p.nearest_real * (Real(1) + margin));
    if (__builtin_expect(!all(decided), 0)) {  // rare (C++17: no [[unlikely]])
        UintsOf<Points> exact[parts_of<Lane>];
        for (int k = 0; k < parts_of<Lane>; ++k) {
            const auto wide = [&](Lane x) __attribute__((always_inline)) {
                return __builtin_convertvector(part_of<RealPart>(x, k), Points);
            };
            const Points u = wide(E.u), v = wide(E.v), u_n = wide(p.nearest_u), v_n = wide(p.nearest_v);
            exact[k] = __builtin_convertvector(u * u + v * v < u_n * u_n + v_n * v_n, UintsOf<Points>);
        }
        // Only the undecided lanes: a decided one may have no nearest yet
        // (its d infinite, its u and v not a sample's).
        nearer = either(both(decided, nearer), both(lane_not(decided), reinterpret_cast<Mask>(joined<CodeOf<Lane>>(exact))));
    }
    p.nearest_real = select(nearer, E.d, p.nearest_real);
    p.nearest_u = select(nearer, E.u, p.nearest_u);
    p.nearest_v = select(nearer, E.v, p.nearest_v);
    return nearer;
}

// What a shooter gives for a sample: its intensities and branch codes.
template <class Lane, class Intensity>
struct SampleResult {
    Intensity I_P;
    CodeOf<Lane> code;
};

// A sample's intensities at the vector's points E, and its branch codes,
// taken into the pixels' sums and counts. CountBranches false (render
// without --stats): the sums alone; the codes, the distance d and the
// nearest sample are then never computed (dead code once inlined).
template <bool CountBranches, class Lane, bool InReal, class Intensity>
PROMYK_LANES_INLINE void take_result(const SampleResult<Lane, Intensity>& result, const SamplePoint<Lane, InReal>& E,
                                     SampledLanes<Lane, Intensity>& p) {
    using Code = CodeOf<Lane>;
    const Code code = result.code;
    p.sum = plus(p.sum, result.I_P);
    if constexpr (!CountBranches) return;
    p.branches += code;
    // Whether the sample is the nearest yet to its pixel's centre; -1
    // (true) stays all ones in the code's width.
    using Points = PointsOf<Lane>;
    Code nearer{};
    if constexpr (InReal) {
        nearer = reinterpret_cast<Code>(nearer_in_real(E, p));
    } else {
        // Compared in double, part by part.
        UintsOf<Points> nearer_32[parts_of<Lane>];
        for (int k = 0; k < parts_of<Lane>; ++k) {
            const auto d_nearer = E.d[k] < p.nearest[k];
            p.nearest[k] = select(d_nearer, E.d[k], p.nearest[k]);
            if constexpr (parts_of<Lane> == 1) nearer = __builtin_convertvector(d_nearer, Code);
            else nearer_32[k] = __builtin_convertvector(d_nearer, UintsOf<Points>);
        }
        if constexpr (parts_of<Lane> > 1) nearer = joined<Code>(nearer_32);
    }
    p.centre = (code & nearer) | (p.centre & ~nearer);
}

// The article's samples (render/article_lanes.hpp) with the formula Root:
// each traced at its points E and taken into the pixels (a shooter of
// draw_sampled_row: the general tracer's are render/general_sample_lanes.hpp's).
// EarlyOuts (article_lanes) pay in float: its sixteen lanes are often all
// background or all dark (bench accuracy --real float --spp 4,16: 9.66 ->
// 8.05 and 33.66 -> 27.47 x base); in double's eight only where the row was
// not narrowed to its silhouette, whole vectors of background (bench
// effects --spp 4, art. full: 2.02 -> 1.47 a sample x spp 1).
template <template <class> class Root, class Real, bool EarlyOuts>
struct ArticleSamples {
    template <class Lane>
    using Intensity = Lane;
    // A copy, the row's own: through a reference GCC must assume the grey
    // levels' stores (a uint8_t* may alias anything) change the scene, and
    // it loaded and broadcast its every number again after each vector of
    // pixels (about 75 instructions a pair of vectors on the baseline path).
    const ArticleRow<Real> row;
    // A sample in two halves, as article_lanes is: where its ray meets the
    // sphere (hit), then its shading (shade). draw_sampled_row finds a
    // sample's hit a sample ahead, while the one before is shaded, as the
    // spp 1 rows do a vector ahead (render/article_row_lanes.hpp). Without
    // the early outs only (the columns near the silhouette): with them, a
    // hit ahead that may end early made whole rows much slower (AVX-512,
    // bench effects --w 256 --spp 4, art. full 8.42 -> 13.64 ns a pixel).
    static constexpr bool in_halves = !EarlyOuts;
    template <class Lane, bool InReal>
    struct Hit {
        SamplePoint<Lane, InReal> E;
        LaneHit<Lane> hit;
    };
    template <class Lane, bool InReal>
    PROMYK_LANES_INLINE Hit<Lane, InReal> hit(const SamplePoint<Lane, InReal>& E) const {
        return {E, article_hit<Root, EarlyOuts>(SampleRow<Lane>(row, E.y), E.x)};
    }
    template <class Lane, bool InReal>
    PROMYK_LANES_INLINE SampleResult<Lane, Lane> shade(const Hit<Lane, InReal>& h) const {
        const LanePixel<Lane> pixel = article_shade<EarlyOuts>(SampleRow<Lane>(row, h.E.y), h.hit);
        return {pixel.I_P, branch_code<CodeOf<Lane>>(pixel.miss, pixel.dark, pixel.non_finite)};
    }
    template <class Lane, bool InReal>
    PROMYK_LANES_INLINE SampleResult<Lane, Lane> operator()(const SamplePoint<Lane, InReal>& E, MaskOf<Lane>) {
        return shade(hit(E));
    }
    // The row's work beyond its branches: one test of the sphere a sample.
    static void count(RowCounts& counts, int pixels, int spp) {
        counts.sphere_tests = static_cast<long long>(pixels) * spp;
    }
};

// Whether a shooter gives the intensity of a sample that misses
// (background(): the general tracer's; BackgroundSum).
template <class Shooter, class = void>
inline constexpr bool has_background = false;
template <class Shooter>
inline constexpr bool has_background<Shooter, std::void_t<decltype(&Shooter::template background<Double2>)>> = true;

// Whether a shooter gives its samples in two halves (ArticleSamples).
template <class Shooter, class = void>
inline constexpr bool in_halves = false;
template <class Shooter>
inline constexpr bool in_halves<Shooter, std::void_t<decltype(Shooter::in_halves)>> = Shooter::in_halves;

// The row's pixels by branch, and those whose samples disagree, counted lane
// by lane (a mask is -1 where true) and summed once at the row's end.
template <class Vector>
struct RowTally {
    using Mask = MaskOf<Vector>;
    Mask miss{}, dark{}, non_finite{}, shadowed{}, disagreeing{};
    int first_non_finite_j = -1;
};

// The sum of a pixel whose every sample drew the background (missed), as
// most of the article's pane does, and the bytes of its mean, converted
// once a row: draw_sampled_row stores them for a vector of such sums, as
// the general tracer's spp 1 rows store the background's bytes for a
// vector that misses. It compares the sums, not how they came: a sum equal
// to this finite one has a finite mean with the same bytes (equal doubles
// are one number, or +0 and -0, whose bytes are both 0), however its
// samples were drawn. Without --stats only (CountBranches false): counting
// needs each pixel's branches, and I_P its mean. Off where the sum is not
// finite. The general tracer's rows only: the article's (which skip the
// background outside the silhouette) were slower with it on AVX2, where
// GCC then kept the pixels in memory (docs/bench.md).
template <class Lane, class Intensity>
struct BackgroundSum {
    static constexpr int channels = std::is_same_v<Intensity, Lane> ? 1 : 3;
    bool on = false;
    Intensity sum{};
    std::uint8_t bytes[LaneTraits<Lane>::width * channels]{};
    template <class Div>
    PROMYK_LANES_INLINE void set(const Intensity& background, int spp, const Div& by_spp) {
        sum = every_channel<Lane, channels == 3>(-0.0);  // in sample order, as take_result sums
        for (int s = 0; s < spp; ++s) sum = plus(sum, background);
        on = all(finite_channels(sum));
        put_intensities(divided(by_spp, sum), bytes, 0, LaneTraits<Lane>::width);
    }
};

// The vector's first n pixels (kept: their lanes), from column j: their grey
// levels (or r, g, b) into out, their branches into the tally (and, for the
// tests, I_P and branches). A pixel's branch is its centre sample's, or
// non-finite when its mean is; its samples agree when each branch took none
// or all of them. CountBranches false: only the non-finite pixels, those
// whose mean is not finite (a non-finite sample's intensity is NaN or
// infinite, so a non-finite centre sample makes the mean so too).
template <bool CountBranches, class Lane, class Intensity, class Div, class Out>
PROMYK_LANES_INLINE void put_sampled(const SampledLanes<Lane, Intensity>& p, int spp, const Div& by_spp, int j, int n,
                                     MaskOf<Lane> kept, std::uint8_t* out, RowTally<Lane>& tally, Out* I_P,
                                     std::uint8_t* branches) {
    using Mask = MaskOf<Lane>;
    using Code = CodeOf<Lane>;
    using Element = std::remove_reference_t<decltype(Code{}[0])>;
    constexpr int width = LaneTraits<Lane>::width;
    const Intensity mean = divided(by_spp, p.sum);  // sum / spp
    put_intensities(mean, out, j, n);
    if constexpr (!CountBranches) {
        const Mask non_finite = ~finite_channels(mean) & kept;
        tally.non_finite -= non_finite;
        if (tally.first_non_finite_j < 0 && any(non_finite))  // rare
            for (int k = width - 1; k >= 0; --k)
                if (non_finite[k]) tally.first_non_finite_j = j + k;
        return;
    }
    // The samples agree when all took one branch: their codes' sum is spp
    // times that branch's code (0 where all are lit).
    const Element all = static_cast<Element>(spp), one = 1;
    const Code sum = p.branches;
    const auto is = [](Code c, Element value) __attribute__((always_inline)) {
        return reinterpret_cast<Mask>(equal_codes(c, Code{} + value));
    };
    Mask agree = is(sum, 0) | is(sum, all << miss_field) | is(sum, all << dark_field) |
                 is(sum, all << non_finite_field);
    Mask centre_shadowed{};
    if constexpr (has_shadowed_field<Code>) {
        agree |= is(sum, all << shadowed_field);
        centre_shadowed = is(p.centre, one << shadowed_field);
    }
    tally.disagreeing -= ~agree & kept;
    const Mask centre_miss = is(p.centre, one << miss_field), centre_dark = is(p.centre, one << dark_field),
               centre_non_finite = is(p.centre, one << non_finite_field);
    const Mask finite = finite_channels(mean);  // finite_value
    const Mask non_finite = (~finite | centre_non_finite) & kept;
    tally.miss -= finite & centre_miss & kept;
    tally.dark -= finite & centre_dark & kept;
    if constexpr (has_shadowed_field<Code>) tally.shadowed -= finite & centre_shadowed & kept;
    tally.non_finite -= non_finite;
    if (tally.first_non_finite_j < 0 && any(non_finite))  // rare
        for (int k = width - 1; k >= 0; --k)
            if (non_finite[k]) tally.first_non_finite_j = j + k;
    if (I_P || branches) {
        for (int k = 0; k < n; ++k) {
            const Branch branch = non_finite[k]        ? Branch::non_finite
                                  : centre_miss[k]     ? Branch::miss
                                  : centre_dark[k]     ? Branch::dark
                                  : centre_shadowed[k] ? Branch::shadowed
                                                       : Branch::lit;
            if (I_P) {
                if constexpr (std::is_same_v<Intensity, Lane>)
                    I_P[j + k] = mean[k];
                else
                    I_P[j + k] = {mean.x[k], mean.y[k], mean.z[k]};
            }
            if (branches) branches[j + k] = static_cast<std::uint8_t>(branch);
        }
    }
}

// Columns [lo, hi) of row grid.i into out from grid.spp samples a pixel,
// each traced by `shoot` (ArticleSamples, or the general tracer's): two
// vectors of pixels in flight (two independent chains of square roots and
// divisions), then one for the rest. CountBranches false: only the
// non-finite pixels are counted (put_sampled), and I_P and branches must
// be null.
template <class Lane, bool ExactCell, bool CountBranches = true, class Shooter, class Out>
PROMYK_LANES_INLINE RowCounts draw_sampled_row(Shooter& shoot, const SampleGrid& row_grid, int lo, int hi,
                                               std::uint8_t* out, Out* I_P, std::uint8_t* branches) {
    // A copy, the loop's own (as ArticleSamples' row): through the
    // reference GCC loaded and broadcast the grid's numbers again for
    // every vector of every sample.
    const SampleGrid grid = row_grid;
    using Real = typename LaneTraits<Lane>::Real;
    using Points = PointsOf<Lane>;
    using Pixels = SampledLanes<Lane, typename Shooter::template Intensity<Lane>>;
    constexpr int width = LaneTraits<Lane>::width;
    using U = UintsOf<Lane>;
    using Mask = MaskOf<Lane>;
    // Float lanes with an exact cell compute their points in float
    // (sample_point_lanes) and read x0_real; the rest x0 and nearest, in double.
    constexpr bool points_in_real = ExactCell && Pixels::parts > 1;
    // by_cell: the jitter's denominator (sample_point_lanes), 2^16 n in
    // float lanes' points, else 2^15 n s (scaled); exact when n is a power
    // of two. by_w and by_cell divide bounded numerators, never -0:
    // WholeDivisor's fmas may stand for the division (in double); by_spp
    // divides any sum.
    const Divisor<Points, ExactCell, true> by_cell(points_in_real ? 65536.0 * grid.n : 32768.0 * grid.n * grid.s);
    const Divisor<Lane, false, true> by_w(grid.w);  // divided_by_w
    const MeanDivisor<Lane> by_spp(grid.spp);
    RowTally<Lane> tally;
    const int spp = grid.spp;
    U lane_numbers;  // 0, 1, .. width - 1
    for (int k = 0; k < width; ++k) lane_numbers[k] = static_cast<std::uint32_t>(k);
    // The baseline's double lanes: a pair's points on a whole grid by
    // magic_pair_points (pair_points below).
    constexpr bool magic_pair = magic_points && std::is_same_v<Lane, Double2>;
    const auto pixels = [&](int j) __attribute__((always_inline)) {
        Pixels p;
        const U j_lanes = static_cast<std::uint32_t>(j) + lane_numbers;
        if constexpr (points_in_real) {
            p.x0_real = Real(2) * __builtin_convertvector(j_lanes, Lane) + Real(1);
        } else {
            for (int k = 0; k < parts_of<Lane>; ++k) {
                // j as signed lanes (j < 2^31): SSE2 and AVX2 have no
                // unsigned conversion, and GCC converted each lane through
                // general registers (with j hash_j below, a sample at spp 4
                // on the baseline 5.31 -> 5.08 ns; docs/bench.md).
                const Points x0 =
                    2.0 * widened<Points>(reinterpret_cast<IntsOf<Points>>(part_of<UintsOf<Points>>(j_lanes, k))) + 1.0;
                p.x0[k] = x0 * grid.one_over_s;  // exact: s a power of two
                if (grid.whole) {
                    p.x_base[k] = p.x0[k] - 1.0;
                    if constexpr (magic_pair) p.x_magic[k] = grid.magic_half - p.x_base[k];
                }
                p.nearest[k] = splat<Points>(INFINITY);
            }
        }
        p.j = j;
        // Read only without the column table (sample_point_lanes). SSE2 has
        // no 32-bit lane multiply (GCC multiplies each lane in general
        // registers), so there it is made only where it is read; AVX2's is
        // one instruction, and leaving it out made AVX2's general sampled
        // rows slower (2.66 -> 2.88 ns a sample at spp 4; docs/bench.md).
#if defined(__SSE4_1__)
        p.j_hash = j_lanes * hash_j;
#else
        if (!grid.columns.hashes) p.j_hash = j_lanes * hash_j;
#endif
        return p;
    };
    const std::uint32_t n = static_cast<std::uint32_t>(grid.n);
    // A shooter in halves (ArticleSamples) in AVX-512's double lanes: the
    // hit too is found ahead (with the point), the shading in the sample's
    // own step. Only there: it needs registers for two vectors' hits ahead,
    // and AVX2's sixteen spilled (bench effects --w 256 --spp 4, the
    // article's row: 8.9 -> 13.5 ns a pixel; AVX-512 6.15 -> 5.6).
    constexpr bool halves = in_halves<Shooter> && std::is_same_v<Lane, Double8>;
    const auto points = [&](const SampleCounter& c, const Pixels& p) __attribute__((always_inline)) {
        if constexpr (halves)
            return shoot.hit(sample_point_lanes(grid, by_cell, by_w, c, p));
        else
            return sample_point_lanes(grid, by_cell, by_w, c, p);
    };
    // Sample c's points of a pair of vectors, p1's columns following p0's.
    // Where the column hashes are in the table, double lanes take both
    // vectors' hashes and jitters in one register (SSE2's four 32-bit
    // lanes, AVX2's eight; the hashes from PairHashes), then each point
    // (point_of_jitter): a hash of four lanes takes the baseline 24
    // instructions where two took 21.
    // Not AVX-512's (sixteen lanes): its full rows gained nothing, and its
    // rows near the silhouette, whose hits are found ahead (halves), were
    // slower whenever sample_point_lanes changed (docs/bench.md). The points
    // are assigned to E0 and E1: returned as a std::pair, GCC compiled
    // AVX-512's loop, which never takes this path, 25 % slower.
    constexpr int pair_width = 2 * width <= 16 ? 2 * width : width;  // SampleInts' widest is 16
    using PairInts = typename SampleInts<pair_width>::U;
    using PairSigned = typename SampleInts<pair_width>::I;
    constexpr bool pair_hashes = !halves && parts_of<Lane> == 1 && std::is_same_v<Real, double> &&
                                 pair_width == 2 * width && sizeof(PairInts) <= 32;
    static_assert(pair_hashes || !magic_pair);
    // Filled as each pair starts, where the table is there, and handed to
    // pair_points as an argument: a lambda that fills it, or pair_points
    // capturing it, changed AVX-512's object (its registers), which never
    // takes this path; written so, AVX-512's is the same as without it.
    PairHashes<PairInts, pair_hashes> pair_hashes_of;
    const auto pair_points = [&](const auto& hashes, const SampleCounter& c, const Pixels& p0, const Pixels& p1,
                                 auto& E0, auto& E1) __attribute__((always_inline)) {
        if constexpr (pair_hashes) {
            if (grid.columns.hashes) {
                if constexpr (magic_pair) {
                    if (grid.magic_fits) {
                        magic_pair_points<CountBranches>(grid, c, hashes.h[c.s], p0, p1, E0, E1);
                        return;
                    }
                }
                const auto jitter = sample_jitter<PairSigned>(grid, c, hashes.h[c.s]);
                E0 = point_of_jitter(grid, by_cell, by_w, p0, widened_half<Lane>(jitter.U, 0),
                                     widened_half<Lane>(jitter.V, 0));
                E1 = point_of_jitter(grid, by_cell, by_w, p1, widened_half<Lane>(jitter.U, 1),
                                     widened_half<Lane>(jitter.V, 1));
                return;
            }
        }
        E0 = points(c, p0);
        E1 = points(c, p1);
    };
    // Sample E's of the pixels p, traced and taken.
    const auto sample = [&](const auto& E_ahead, Pixels& p, Mask kept) __attribute__((always_inline)) {
        if constexpr (halves) {
            take_result<CountBranches>(shoot.shade(E_ahead), E_ahead.E, p);
        } else {
            const auto& E = point_at(E_ahead, grid, by_w, p);
            take_result<CountBranches>(shoot(E, kept), E, p);
        }
    };
    // Pixels whose samples all drew the background (BackgroundSum): the
    // general tracer's rows without --stats.
    constexpr bool background_sums = !CountBranches && has_background<Shooter>;
    BackgroundSum<Lane, typename Shooter::template Intensity<Lane>> background;
    if constexpr (background_sums) background.set(shoot.template background<Lane>(), spp, by_spp);
    const auto put = [&](const Pixels& p, int j, int lanes, Mask kept) __attribute__((always_inline)) {
        if constexpr (background_sums) {
            // Every lane the background's sum (past n too: the next
            // columns', or the last column's again, rarely different).
            if (background.on && all(equal_channels(p.sum, background.sum))) {
                std::memcpy(out + background.channels * j, background.bytes,
                            static_cast<std::size_t>(background.channels * lanes));
                return;
            }
        }
        put_sampled<CountBranches>(p, spp, by_spp, j, lanes, kept, out, tally, I_P, branches);
    };
    const Mask all_kept = ~Mask{};
    // Each sample's points (and, in halves, hits) are computed a sample
    // ahead, in the step before the sample they lead (the pair's last
    // sample computes the next pair's first): their hash and divisions then
    // run while the square roots before them wait, the loop being bound
    // by the latency of a sample's chain rather than by its work. The last
    // pair computes one unused.
    int j = lo;
    if (j + 2 * width <= hi) {
        Pixels p0 = pixels(j), p1 = pixels(j + width);
        decltype(points(SampleCounter{}, p0)) E0, E1;
        if constexpr (pair_hashes)
            if (grid.columns.hashes) pair_hashes_of.fill(grid, j);
        pair_points(pair_hashes_of, SampleCounter{}, p0, p1, E0, E1);
        for (; j + 2 * width <= hi; j += 2 * width) {
            SampleCounter c;
            for (; c.s + 1 < spp; ) {
                SampleCounter c_next = c;
                c_next.next(n);
                decltype(E0) next0, next1;
                pair_points(pair_hashes_of, c_next, p0, p1, next0, next1);
                sample(E0, p0, all_kept);
                sample(E1, p1, all_kept);
                c = c_next, E0 = next0, E1 = next1;
            }
            const Pixels q0 = pixels(j + 2 * width), q1 = pixels(j + 3 * width);
            decltype(E0) next0, next1;
            if constexpr (pair_hashes)
                if (grid.columns.hashes) pair_hashes_of.fill(grid, j + 2 * width);
            pair_points(pair_hashes_of, SampleCounter{}, q0, q1, next0, next1);
            sample(E0, p0, all_kept);
            sample(E1, p1, all_kept);
            put(p0, j, width, all_kept);
            put(p1, j + width, width, all_kept);
            p0 = q0, p1 = q1, E0 = next0, E1 = next1;
        }
    }
    for (; j < hi; j += width) {  // the last vector's lanes past hi are computed and dropped
        Pixels p = pixels(j);
        const int kept_lanes = hi - j < width ? hi - j : width;
        Mask kept{};
        for (int k = 0; k < kept_lanes; ++k) kept[k] = -1;
        SampleCounter c;
        for (; c.s < spp; c.next(n)) sample(points(c, p), p, kept);
        put(p, j, kept_lanes, kept);
    }
    RowCounts counts;
    int miss = 0, dark = 0, non_finite = 0, shadowed = 0;
    for (int k = 0; k < width; ++k) {
        miss += static_cast<int>(tally.miss[k]);
        dark += static_cast<int>(tally.dark[k]);
        non_finite += static_cast<int>(tally.non_finite[k]);
        shadowed += static_cast<int>(tally.shadowed[k]);
        counts.disagreeing += static_cast<int>(tally.disagreeing[k]);
    }
    counts.branches[static_cast<int>(Branch::miss)] = miss;
    counts.branches[static_cast<int>(Branch::dark)] = dark;
    counts.branches[static_cast<int>(Branch::non_finite)] = non_finite;
    counts.branches[static_cast<int>(Branch::shadowed)] = shadowed;
    if (CountBranches) counts.branches[static_cast<int>(Branch::lit)] = (hi - lo) - miss - dark - non_finite - shadowed;
    counts.first_non_finite_j = tally.first_non_finite_j;
    shoot.count(counts, hi - lo, spp);
    return counts;
}

// The numbers of row i's samples that do not change from sample to sample.
PROMYK_LANES_INLINE SampleGrid sample_grid(int w, int i, int spp) {
    SampleGrid grid;
    grid.i = i, grid.w = w, grid.spp = spp;
    grid.n = 1;
    while ((grid.n + 1) * (grid.n + 1) <= spp) ++grid.n;  // spp_side (not compiled here)
    grid.minus_y0 = -(2.0 * i + 1.0);
    grid.i_hash = static_cast<std::uint32_t>(i) * hash_i;
    grid.columns = sample_column_hashes(w, spp);
    grid.w_exact = power_of_two(w);
    grid.s = grid.w_exact ? w : 1;
    grid.one_over_s = 1.0 / grid.s;
    grid.minus_y0_s = grid.minus_y0 * grid.one_over_s;
    grid.whole = power_of_two(grid.n) && grid.w_exact;
    if (grid.whole) {
        grid.y_base = 1.0 - (2.0 * i + 1.0) / w;
        grid.step = 1.0 / 32768.0 / grid.n / w;
        grid.half_cell = 32768 * grid.n;
        grid.magic_fits = static_cast<double>(grid.n) * w <= 1073741824.0;
        grid.magic = 4503599627370496.0 * grid.step;
        grid.magic_half = grid.magic + 1.0 / w;
        grid.y_magic = (grid.y_base + 1.0 / w) + grid.magic;
        std::uint64_t bits;
        std::memcpy(&bits, &grid.magic, sizeof bits);
        grid.magic_high = static_cast<std::uint32_t>(bits >> 32);
    }
    return grid;
}

// Columns [lo, hi) of row i of a w-pixel pane, spp > 1 samples a pixel, the
// formula chosen at run time (once a row); Lane: doubles or floats.
// count_branches false (render without --stats): only the non-finite
// pixels are counted (11 to 17 % faster a sample: docs/bench.md).
template <class Lane, class Real = typename LaneTraits<Lane>::Real>
PROMYK_LANES_INLINE RowCounts draw_sampled_row(const ArticleRow<Real>& row, int w, int i, int spp, int lo, int hi,
                                               std::uint8_t* out, Real* I_P, std::uint8_t* branches,
                                               Formula formula, bool count_branches = true) {
    const SampleGrid grid = sample_grid(w, i, spp);
    // In float, an exact cell also takes the points in float lanes
    // (sample_point_lanes), which needs 2 w + 1 below 2^24.
    const bool cell_exact = power_of_two(grid.n) && (std::is_same_v<Real, double> || w <= (1 << 22));
    // Every branch counted for --stats and wherever a pixel's is asked for
    // (branches: maps and tests).
    const bool count = count_branches || I_P != nullptr || branches != nullptr;
    const auto draw_counting = [&](auto shoot, auto counting) __attribute__((always_inline)) {
        constexpr bool c = decltype(counting)::value;
        return cell_exact ? draw_sampled_row<Lane, true, c>(shoot, grid, lo, hi, out, I_P, branches)
                          : draw_sampled_row<Lane, false, c>(shoot, grid, lo, hi, out, I_P, branches);
    };
    const auto draw = [&](auto shoot) __attribute__((always_inline)) {
        return count ? draw_counting(shoot, std::true_type{}) : draw_counting(shoot, std::false_type{});
    };
    return with_root(formula, [&](auto root) {
        using R = decltype(root);
        if constexpr (std::is_same_v<Real, float>)
            return draw(ArticleSamples<R::template Root, Real, true>{row});
        else
            return lo == 0 && hi == w ? draw(ArticleSamples<R::template Root, Real, true>{row})
                                      : draw(ArticleSamples<R::template Root, Real, false>{row});
    });
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
