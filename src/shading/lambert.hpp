// Lambert shading with the article's program: I_P = I max(0, N.K / (|K| r)),
// computed as I D / (r sqrt(K)) with D = N.K and K = |L - P|^2.
#pragma once

#include <cmath>
#include <limits>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

template <class Real>
struct Shade {
    Real I_P;       // intensity reaching the eye
    Branch branch;  // dark, lit, or non_finite
};

template <class Real, class Recorder>
Shade<Real> shade_lambert(const Vec3<Real>& P, const Vec3<Real>& N, Real r, const Vec3<Real>& L, Real I,
                          Recorder& record) {
    // Compute the direction to the light, K = L - P, and its squared length.
    const Vec3<Real> K = L - P;
    record(Key::K, K);
    record.lost(Key::K, L, P, K);
    const Real KK = length_squared(K);  // the program's K = |K|^2
    record(Key::KK, KK);
    if constexpr (Recorder::records) {
        // |K| and the unit direction K_P = K / |K| of section 4, for the
        // lessons; undefined when the light sits on P (|K| = 0).
        const Real K_len = square_root(KK);
        record(Key::K_len, K_len);
        if (K_len > 0) record(Key::K_P, K / K_len);
    }
    // Compute D = N.K: |N||K| cos(alpha), negative on the dark side.
    const Real D = dot(N, K);
    record(Key::D, D);
    record.lost_in_dot(Key::D, N, K, D);
    if constexpr (Recorder::records) {
        // cos(alpha) = N_P.K_P, as formula (1) gives it for unit vectors.
        const Real K_len = square_root(KK);
        if (K_len > 0) record(Key::cos_alpha, dot(N / r, K / K_len));
    }
    // An overflow anywhere since E (in t, P, N or K) shows in |K|^2 or D,
    // each a sum of products of every earlier quantity; a NaN must not
    // decide dark or lit. x * 0 is 0 for a finite x and NaN for inf or NaN,
    // so one comparison checks both (a branch-free test, cheaper per pixel
    // than two isfinite).
    if (!(KK * Real(0) + D * Real(0) == Real(0))) return {RealTraits<Real>::quiet_nan(), Branch::non_finite};
    if (D <= 0) return {Real(0), Branch::dark};
    const Real I_P = I * D / (r * square_root(KK));
    // I D overflowing, or r sqrt(|K|^2) underflowing to 0: I_P is +inf or NaN.
    if (!(I_P <= RealTraits<Real>::max())) return {I_P, Branch::non_finite};
    return {I_P, Branch::lit};
}

}  // namespace promyk
