// Describing a hit once t is known: the point P and the (unnormalised)
// normal N = P - S, as the article's program computes them.
#pragma once

#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

template <class Real>
struct Hit {
    Vec3<Real> P;  // hit point, P = O + tE
    Vec3<Real> N;  // P - S, of length r
};

template <class Real, class Recorder>
Hit<Real> describe_sphere_hit(Real t, const Vec3<Real>& E, const Vec3<Real>& S, Real r, Recorder& record) {
    // Compute the hit point P = tE (the eye is at O).
    const Vec3<Real> P = t * E;
    record(Key::P, P);
    // Compute N = P - S, the radius through P: perpendicular to the surface.
    const Vec3<Real> N = P - S;
    record(Key::N, N);
    // The unit normal N_P = N / r of section 4, for the lessons.
    if constexpr (Recorder::records) record(Key::N_P, N / r);
    return {P, N};
}

}  // namespace promyk
