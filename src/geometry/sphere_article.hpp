// Intersecting the sphere with the article's literal quadratic (formula (2)
// with the program's letters). Solving for t is this step; describing the hit
// (P, N) is the next one (geometry/hit.hpp), as in pbrt-v4's shapes.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// Returns the nearer root t of t^2|E|^2 - 2t E.S + |S|^2 - r^2 = 0, or no
// value when the ray misses. Like the article, a tangent ray (delta = 0)
// misses and t is not checked to be positive.
//
// When delta is not finite (the coefficients overflowed), nothing can be
// decided: the returned t is then NaN or infinite, and so are the hit's
// quantities, which shading reports as non-finite. A delta of -inf must not
// pass for a miss.
template <class Real, class Recorder>
std::optional<Real> intersect_sphere_article(const Vec3<Real>& E, const Vec3<Real>& S, Real r, Recorder& record) {
    // Compute the quadratic's coefficients, named as in the program.
    const Real EE = length_squared(E);  // the program's E = |E|^2
    record(Key::EE, EE);
    const Real SS = length_squared(S);  // the program's S = |S|^2
    record(Key::SS, SS);
    const Real C = dot(E, S);
    record(Key::C, C);
    record.lost_in_dot(Key::C, E, S, C);

    // Compute the program's delta: a quarter of formula (2)'s discriminant.
    const Real delta = C * C - EE * (SS - r * r);
    record(Key::delta, delta);
    // Digits lost: C^2 against |E|^2 (|S|^2 - r^2), the outer subtraction.
    if constexpr (Recorder::estimates) record.lost(Key::delta, C * C, EE * (SS - r * r), delta);
    if constexpr (Recorder::records) {
        // Formula (2)'s own discriminant, for the lessons: Delta = 4 delta, and
        // sqrt(Delta) = 2 sqrt(delta) (both exact: 4 and 2 are powers of two).
        record(Key::Delta, Real(4) * delta);
        if (delta > 0) record(Key::sqrt_Delta, square_root(Real(4) * delta));
    }
    if (delta <= 0 && delta >= RealTraits<Real>::lowest()) return std::nullopt;

    // Compute the nearer root: the minus sign, since |E|^2 > 0.
    const Real t = (C - square_root(delta)) / EE;
    record(Key::t, t);
    // Digits lost by the numerator C - sqrt(delta) (the division loses none).
    if constexpr (Recorder::estimates) record.lost(Key::t, C, square_root(delta), C - square_root(delta));
    return t;
}

}  // namespace promyk
