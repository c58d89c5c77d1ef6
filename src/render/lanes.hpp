// Lanes: the types a kernel computes in, one pixel (a plain double or float)
// or several side by side (a GCC/clang vector extension, which em++ also
// compiles). Each operation on a vector acts on every lane alone and rounds
// as the one-lane operation does, so a lane's bits are the one pixel's bits.
// A comparison gives a mask (a bool, or a vector of all-ones / all-zeros
// integers), and a branch becomes a select between two computed values.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

// Everything a kernel calls on lanes is inlined into the loop: the kernel
// is too big for GCC to inline by itself, and a call costs the loop its
// registers.
#define PROMYK_LANES_INLINE inline __attribute__((always_inline))

// Each instruction set's build of these templates gets a namespace of its
// own (PROMYK_LANES_ISA, set per translation unit by src/CMakeLists.txt):
// an inline function the compiler did not inline is emitted in every
// translation unit that uses it, and the linker keeps one copy; were the
// AVX-512 copy kept, the baseline path would crash on older processors.
#ifndef PROMYK_LANES_ISA
#define PROMYK_LANES_ISA baseline
#endif

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// Two doubles and four floats: one SSE2 register, the baseline x86-64's
// vector (and wasm's simd128). Wider vectors pay only where the instruction
// set has them: without AVX, GCC splits a comparison of four doubles into
// scalar ones. The division and square root units, the kernel's
// bottleneck, then work on every lane at once.
typedef double Double2 __attribute__((vector_size(16)));
typedef float Float4 __attribute__((vector_size(16)));
// A comparison's result: 64- or 32-bit integers, -1 where true (GCC calls
// them long, clang long long: the type is the compiler's own).
using Mask2 = decltype(Double2{} < Double2{});
using Mask4 = decltype(Float4{} < Float4{});
// Four and eight doubles: AVX2's and AVX-512's registers, compiled only in
// those instruction sets' translation units (render/article_row_avx*.cpp).
typedef double Double4 __attribute__((vector_size(32)));
typedef double Double8 __attribute__((vector_size(64)));
using Mask4d = decltype(Double4{} < Double4{});
using Mask8d = decltype(Double8{} < Double8{});
// Eight and sixteen floats, the same registers for --real float.
typedef float Float8 __attribute__((vector_size(32)));
typedef float Float16 __attribute__((vector_size(64)));
using Mask8f = decltype(Float8{} < Float8{});
using Mask16f = decltype(Float16{} < Float16{});
// The widest vectors of a wider set's translation unit (PROMYK_LANES_BITS,
// set beside PROMYK_LANES_ISA by src/CMakeLists.txt): the lane types of
// render/*_wide.inc, the rows' body each wider set compiles.
#if defined(PROMYK_LANES_BITS) && PROMYK_LANES_BITS == 512
using WideDouble = Double8;
using WideFloat = Float16;
#elif defined(PROMYK_LANES_BITS) && PROMYK_LANES_BITS == 256
using WideDouble = Double4;
using WideFloat = Float8;
#endif

template <class Lane>
struct LaneTraits;

template <>
struct LaneTraits<double> {
    using Real = double;
    using Mask = bool;
    static constexpr int width = 1;
};
template <>
struct LaneTraits<float> {
    using Real = float;
    using Mask = bool;
    static constexpr int width = 1;
};
template <>
struct LaneTraits<Double2> {
    using Real = double;
    using Mask = Mask2;
    static constexpr int width = 2;
};
template <>
struct LaneTraits<Float4> {
    using Real = float;
    using Mask = Mask4;
    static constexpr int width = 4;
};

template <>
struct LaneTraits<Double4> {
    using Real = double;
    using Mask = Mask4d;
    static constexpr int width = 4;
};
template <>
struct LaneTraits<Double8> {
    using Real = double;
    using Mask = Mask8d;
    static constexpr int width = 8;
};
template <>
struct LaneTraits<Float8> {
    using Real = float;
    using Mask = Mask8f;
    static constexpr int width = 8;
};
template <>
struct LaneTraits<Float16> {
    using Real = float;
    using Mask = Mask16f;
    static constexpr int width = 16;
};

template <class Lane>
using MaskOf = typename LaneTraits<Lane>::Mask;

// One lane: the plain operations.
PROMYK_LANES_INLINE bool lane_not(bool m) { return !m; }
PROMYK_LANES_INLINE bool both(bool a, bool b) { return a && b; }
PROMYK_LANES_INLINE bool either(bool a, bool b) { return a || b; }
PROMYK_LANES_INLINE bool any(bool m) { return m; }
PROMYK_LANES_INLINE bool all(bool m) { return m; }
PROMYK_LANES_INLINE int count(bool m) { return m ? 1 : 0; }
PROMYK_LANES_INLINE bool lane_of(bool m, int) { return m; }
template <class Real>
PROMYK_LANES_INLINE Real select(bool m, Real a, Real b) {
    return m ? a : b;
}
PROMYK_LANES_INLINE double lane_sqrt(double x) { return std::sqrt(x); }
PROMYK_LANES_INLINE float lane_sqrt(float x) { return std::sqrt(x); }

// x in every lane, as one broadcast: the vector written out as {x, x, ...}
// (0 + x would turn a -0 into +0; filling the lanes one by one in a loop,
// GCC compiled a value read from memory to a masked load per lane).
template <class Lane, class Real, std::size_t... k>
PROMYK_LANES_INLINE Lane splat_lanes(Real x, std::index_sequence<k...>) {
    using Element = typename LaneTraits<Lane>::Real;
    return Lane{((void)k, static_cast<Element>(x))...};
}
template <class Lane, class Real>
PROMYK_LANES_INLINE Lane splat(Real x) {
    if constexpr (LaneTraits<Lane>::width == 1)
        return x;
    else
        return splat_lanes<Lane>(x, std::make_index_sequence<LaneTraits<Lane>::width>{});
}

// Vectors: masks are -1 (true) or 0 in every lane.
template <class Mask>
PROMYK_LANES_INLINE Mask lane_not(Mask m) {
    return ~m;
}
template <class Mask>
PROMYK_LANES_INLINE Mask both(Mask a, Mask b) {
    return a & b;
}
template <class Mask>
PROMYK_LANES_INLINE Mask either(Mask a, Mask b) {
    return a | b;
}
#if defined(__SSE2__) && !defined(__SSE4_1__)
// Two doubles' masks on the baseline path: GCC 12, without SSE4.1, takes
// the ~, & or | of comparisons' results lane by lane through general
// registers (each lane's bit 0 kept and negated: 12 instructions for a
// pand, and a select after it became cmovs). Through __m128i the result
// is no longer a comparison's, and the operation is one instruction.
PROMYK_LANES_INLINE __m128i as_m128i(Mask2 m) { return reinterpret_cast<__m128i>(m); }
PROMYK_LANES_INLINE Mask2 lane_not(Mask2 m) {
    return reinterpret_cast<Mask2>(_mm_xor_si128(as_m128i(m), _mm_set1_epi32(-1)));
}
PROMYK_LANES_INLINE Mask2 both(Mask2 a, Mask2 b) {
    return reinterpret_cast<Mask2>(_mm_and_si128(as_m128i(a), as_m128i(b)));
}
PROMYK_LANES_INLINE Mask2 either(Mask2 a, Mask2 b) {
    return reinterpret_cast<Mask2>(_mm_or_si128(as_m128i(a), as_m128i(b)));
}
#endif
// One bit a lane, set where the mask is: the lanes' sign bits in one
// instruction where the set has it (a loop over the lanes extracts each one).
template <class Mask>
PROMYK_LANES_INLINE unsigned lane_bits(Mask m) {
    constexpr int n = int(sizeof m / sizeof m[0]);
#if defined(__SSE2__)
    if constexpr (sizeof m == 16 && n == 2) return unsigned(_mm_movemask_pd(reinterpret_cast<__m128d>(m)));
    if constexpr (sizeof m == 16 && n == 4) return unsigned(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
#endif
#if defined(__AVX__)
    if constexpr (sizeof m == 32 && n == 4) return unsigned(_mm256_movemask_pd(reinterpret_cast<__m256d>(m)));
    if constexpr (sizeof m == 32 && n == 8) return unsigned(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
#endif
#if defined(__AVX512F__)
    if constexpr (sizeof m == 64 && n == 8) {
        const __m512i v = reinterpret_cast<__m512i>(m);
        return unsigned(_mm512_test_epi64_mask(v, v));
    }
    if constexpr (sizeof m == 64 && n == 16) {
        const __m512i v = reinterpret_cast<__m512i>(m);
        return unsigned(_mm512_test_epi32_mask(v, v));
    }
#endif
    unsigned bits = 0;
    for (int k = 0; k < n; ++k) bits |= m[k] ? 1u << k : 0u;
    return bits;
}
template <class Mask>
PROMYK_LANES_INLINE bool any(Mask m) {
    return lane_bits(m) != 0;
}
template <class Mask>
PROMYK_LANES_INLINE bool all(Mask m) {
    constexpr int n = int(sizeof m / sizeof m[0]);
    return lane_bits(m) == (1u << n) - 1;
}
template <class Mask>
PROMYK_LANES_INLINE int count(Mask m) {
    int n = 0;
    for (int k = 0; k < int(sizeof m / sizeof m[0]); ++k) n += m[k] != 0;
    return n;
}
template <class Mask>
PROMYK_LANES_INLINE bool lane_of(Mask m, int k) {
    return m[k] != 0;
}

// a where m, else b, bit for bit (a NaN's payload too): by the bits, so a
// NaN in the lane not taken changes nothing.
template <class Vector, class = std::enable_if_t<(LaneTraits<Vector>::width > 1)>>
PROMYK_LANES_INLINE Vector select(MaskOf<Vector> m, Vector a, Vector b) {
    using Mask = MaskOf<Vector>;
    return reinterpret_cast<Vector>((reinterpret_cast<Mask>(a) & m) | (reinterpret_cast<Mask>(b) & ~m));
}

// x with its sign flipped where m: select(m, -x, x) bit for bit (-x flips
// the sign bit, a NaN's too), as one xor with m's sign bits where the
// select took four instructions.
template <class Real>
PROMYK_LANES_INLINE Real negated_where(bool m, Real x) {
    return m ? -x : x;
}
template <class Vector, class = std::enable_if_t<(LaneTraits<Vector>::width > 1)>>
PROMYK_LANES_INLINE Vector negated_where(MaskOf<Vector> m, Vector x) {
    using Mask = MaskOf<Vector>;
    const Mask sign = both(m, reinterpret_cast<Mask>(splat<Vector>(-0.0)));
    return reinterpret_cast<Vector>(reinterpret_cast<Mask>(x) ^ sign);
}

// The square root lane by lane: with -fno-math-errno (the kernels' own
// translation unit) GCC makes this one sqrtpd/sqrtps; the result is the
// correctly rounded root in every lane either way.
template <class Vector, class = std::enable_if_t<(LaneTraits<Vector>::width > 1)>>
PROMYK_LANES_INLINE Vector lane_sqrt(Vector x) {
    Vector s = x;  // every lane replaced (GCC 12 took a bare s for uninitialized)
    for (int k = 0; k < LaneTraits<Vector>::width; ++k) s[k] = std::sqrt(x[k]);
    return s;
}

// a b + c rounded once, lane by lane: one vfmadd where the instruction set
// has it (__FP_FAST_FMA: AVX2's and AVX-512's translation units, both given
// -mfma: -mavx512f alone does not define it), else the
// C library's fma, exact too but a call a lane (render/whole_divisor.hpp
// then divides instead).
PROMYK_LANES_INLINE double lane_fma(double a, double b, double c) { return __builtin_fma(a, b, c); }
PROMYK_LANES_INLINE float lane_fma(float a, float b, float c) { return __builtin_fmaf(a, b, c); }
template <class Vector, class = std::enable_if_t<(LaneTraits<Vector>::width > 1)>>
PROMYK_LANES_INLINE Vector lane_fma(Vector a, Vector b, Vector c) {
    Vector s;
    for (int k = 0; k < LaneTraits<Vector>::width; ++k) s[k] = lane_fma(a[k], b[k], c[k]);
    return s;
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
