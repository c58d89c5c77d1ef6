// Describing a hit once t is known: the point P and the (unnormalised)
// normal N = P - S, as the article's program computes them. Two functions
// returning a vector each, not one returning a {P, N} struct: GCC kept such
// a struct in memory on the render path (about 1 ns a pixel in 6).
#pragma once

#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// Compute the hit point P = O + tE (the eye is at O).
template <class Real, class Recorder>
Vec3<Real> hit_point(Real t, const Vec3<Real>& E, Recorder& record) {
    const Vec3<Real> P = t * E;
    record(Key::P, P);
    return P;
}

// Compute N = P - S, the radius through P: perpendicular to the surface.
template <class Real, class Recorder>
Vec3<Real> sphere_normal(const Vec3<Real>& P, const Vec3<Real>& S, Real r, Recorder& record) {
    const Vec3<Real> N = P - S;
    record(Key::N, N);
    record.lost(Key::N, P, S, N);
    // The unit normal N_P = N / r of section 4, for the lessons.
    if constexpr (Recorder::records) record(Key::N_P, N / r);
    return N;
}

}  // namespace promyk
