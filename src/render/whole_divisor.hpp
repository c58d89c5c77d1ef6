// Division by a whole number b, 1 <= b <= 2^21, known before the loop,
// without the division unit (a sample's x_E, y_E and jitter divide by w and
// 2^16 n or 2^15 n w; a division costs a quarter of the kernel's share of
// that unit):
//
//   q0 = A y   (y = 1/b rounded),   r = A - b q0   (fma),   q = q0 + r y   (fma)
//
// gives the bits of A / b for every A the samples divide: finite, not -0
// (-0 would give +0), 0 or at least 2^-900 in size, below 2^900. Why:
// 1. y is 1/b within a relative 2^-53, so q0 is within 2 ulp(q0) of A / b.
// 2. A and b q0 are whole multiples of ulp(q0) / 2 and differ by at most
//    2 b ulp(q0) <= 2^22 ulp(q0): r is representable, and the fma is exact.
// 3. q0 + r y = A / b + e (A / b - q0) with |e| <= 2^-53, within
//    2^-52 ulp(q0) of A / b, and the second fma rounds it once.
// 4. A / b is never that close to a midpoint m between two doubles, of
//    spacing s there: with b = 2^t c, c odd, A / 2^t is a multiple of s
//    (b = 1 aside, where q0 = A exactly) and c m an odd multiple of s / 2,
//    so |A / b - m| = |A / 2^t - c m| / c >= s / (2 c) >= s / 2^22. Rounded
//    once, A / b and q0 + r y fall on the same side of every midpoint: the
//    same double. No ties either.
// b may also be such a number times a power of two 2^k (the scaled cell's
// 2^15 n w): y, q0, r y and q are then those of b / 2^k scaled by 2^-k, r
// is the same, and scaling by a power of two rounds nothing (the samples'
// quotients are far from underflow).
// tests/whole_divisor_test.cpp checks it against the division on every
// divisor the panes use and numerators next to every midpoint.
#pragma once

#include "render/lanes.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// Whether this translation unit's instruction set fuses a multiply-add in
// one instruction: without it the fma is a slow library call, and the
// division is cheaper.
#if defined(__FP_FAST_FMA)  // GCC and clang: an fma instruction (-mfma)
inline constexpr bool fused_multiply_add = true;
#else
inline constexpr bool fused_multiply_add = false;
#endif

// Lanes divided by b: A / b, or its bits by the two fmas above (Fused).
template <class Lane, bool Fused = fused_multiply_add>
struct WholeDivisor {
    double b, y;
    explicit WholeDivisor(double whole) : b(whole), y(1.0 / whole) {}
    PROMYK_LANES_INLINE Lane divide(Lane A) const {
        if constexpr (Fused) {
            const Lane q0 = A * y;
            const Lane r = lane_fma(-q0, splat<Lane>(b), A);
            return lane_fma(r, splat<Lane>(y), q0);
        } else {
            return A / b;
        }
    }
};

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
