// Phong's specular term for one light: k_s (R_hat.V_hat)^n, where R_hat is the
// direction to the light mirrored about the normal and V_hat points to the
// eye. Zero when RV <= 0 (the mirror direction turns away from the eye).
#pragma once

#include <cmath>

#include "math/power.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// N: the normal facing the eye, of length r; K = L - P, KK = |K|^2.
template <class Real, class Recorder>
Real phong_specular(const Vec3<Real>& N, Real r, const Vec3<Real>& K, Real KK, const Vec3<Real>& V_hat, Real I,
                    Real k_s, int n, Recorder& record) {
    const Vec3<Real> N_P = N / r;
    const Vec3<Real> K_P = K / square_root(KK);
    const Real cos_alpha = dot(N_P, K_P);
    // The lessons' section-4 quantities are recorded by Lambert's stage
    // already when a recorder asks; here they are needed for the value.
    const Vec3<Real> R_hat = (Real(2) * cos_alpha) * N_P - K_P;
    record(Key::R_hat, R_hat);
    if constexpr (Recorder::estimates) record.lost(Key::R_hat, (Real(2) * cos_alpha) * N_P, K_P, R_hat);
    const Real RV = dot(R_hat, V_hat);
    record(Key::RV, RV);
    record.lost_in_dot(Key::RV, R_hat, V_hat, RV);
    if (!(RV > 0)) return Real(0);
    if constexpr (Recorder::records) {
        // The squarings power() makes, RV^2, RV^4, ... while 2^k <= n: the
        // same products, so the same bits, for a lesson to show.
        Real square = RV;
        for (int k = 1; k <= squaring_count && (1 << k) <= n; ++k) {
            square = square * square;
            record(squaring_key(k), square);
        }
    }
    const Real RV_n = power(RV, n);
    record(Key::RV_n, RV_n);
    const Real specular = I * (k_s * RV_n);
    record(Key::specular, specular);
    return specular;
}

}  // namespace promyk
