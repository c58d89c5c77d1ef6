// Shadow rays: does an object lie strictly between the hit point P and the
// light, on the segment P + sK with 0 < s < 1? The object that was hit is not
// tested here: shading/shadow.hpp decides it exactly (no shadow acne).
#pragma once

#include <cmath>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// What a segment test found: blocked, or not, or undecided (a value that
// decides it is NaN or infinite).
enum class Blocks { no, yes, undecided };

// A sphere blocks when the segment crosses its surface: a root of
// |P + sK - S|^2 = r^2 in (0, 1).
template <class Real, class Recorder>
Blocks sphere_blocks(const Vec3<Real>& P, const Vec3<Real>& K, Real KK, const Vec3<Real>& S, Real r,
                     Recorder& record) {
    const Vec3<Real> SP = S - P;
    const Real b_s = dot(K, SP);
    record(Key::b_s, b_s);
    record.lost_in_dot(Key::b_s, K, SP, b_s);
    const Real c_s = length_squared(SP) - r * r;
    record(Key::c_s, c_s);
    if constexpr (Recorder::estimates) record.lost(Key::c_s, length_squared(SP), r * r, c_s);
    const Real delta_s = b_s * b_s - KK * c_s;
    record(Key::delta_s, delta_s);
    if constexpr (Recorder::estimates) record.lost(Key::delta_s, b_s * b_s, KK * c_s, delta_s);
    if (!(delta_s * Real(0) == Real(0))) return Blocks::undecided;
    if (delta_s <= 0) return Blocks::no;
    const Real q = square_root(delta_s);
    const Real s_1 = (b_s - q) / KK;
    record(Key::s_1, s_1);
    if constexpr (Recorder::estimates) record.lost(Key::s_1, b_s, q, b_s - q);
    if constexpr (Recorder::records) {
        // Where the line enters the sphere, for a lesson to check by hand.
        const Vec3<Real> P_s1 = P + s_1 * K;
        record(Key::P_s1, P_s1);
        record(Key::d_s1, square_root(length_squared(P_s1 - S)));
    }
    const Real s_2 = (b_s + q) / KK;
    record(Key::s_2, s_2);
    if constexpr (Recorder::estimates) record.lost(Key::s_2, b_s, q, b_s + q);
    return (s_1 > 0 && s_1 < 1) || (s_2 > 0 && s_2 < 1) ? Blocks::yes : Blocks::no;
}

// A plane blocks when the segment crosses it: s = (NQ - n_hat.P) / n_hat.K
// in (0, 1). A segment parallel to the plane never crosses it.
template <class Real, class Recorder>
Blocks plane_blocks(const Vec3<Real>& P, const Vec3<Real>& K, const Vec3<Real>& n_hat, Real NQ, Recorder& record) {
    const Real NK = dot(n_hat, K);
    record(Key::NK, NK);
    record.lost_in_dot(Key::NK, n_hat, K, NK);
    if (NK == 0) return Blocks::no;
    const Real s = (NQ - dot(n_hat, P)) / NK;
    record(Key::s, s);
    // Digits lost by the numerator NQ - n_hat.P.
    if constexpr (Recorder::estimates) record.lost(Key::s, NQ, dot(n_hat, P), NQ - dot(n_hat, P));
    if (!(s * Real(0) == Real(0))) return Blocks::undecided;
    return s > 0 && s < 1 ? Blocks::yes : Blocks::no;
}

}  // namespace promyk
