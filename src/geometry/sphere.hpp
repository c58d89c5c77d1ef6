// Intersecting a sphere when the eye may be anywhere: the article's near root
// first (sphere_article.hpp, unchanged), then, when it is not in front of the
// eye, the far root. Only a root with t > 0 is a hit (docs/conventions.md: the engine's
// conventions): a sphere behind the eye is not drawn, and an eye inside the
// sphere sees its inside.
#pragma once

#include <cmath>
#include <optional>

#include "geometry/sphere_article.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

template <class Real>
struct SphereRoot {
    Real t;       // the root taken, > 0, or NaN/inf when delta was not finite
    bool inside;  // the far root: the ray leaves the sphere there (the eye is inside)
};

// A discriminant that misses: <= 0 and finite below (a delta of -inf, like
// NaN, decides nothing and must not pass for a miss).
template <class Real>
bool discriminant_misses(Real delta) {
    return delta <= 0 && delta >= RealTraits<Real>::lowest();
}

// A formula's discriminant that misses, recorded as the article's miss is.
template <class Real, class Recorder>
bool records_miss(Real delta, Recorder& record) {
    if (!discriminant_misses(delta)) return false;
    if constexpr (Recorder::records) record(Key::found, "miss");
    return true;
}

// The coefficients the other formulas share, each recorded: EE = |E|^2,
// SS = |S|^2 and C = E.S computed as the article's, and c_0 = SS - r*r.
template <class Real>
struct SphereCoefficients {
    Real EE, SS, C, c_0;
};

template <class Real, class Recorder>
SphereCoefficients<Real> sphere_coefficients(const Vec3<Real>& E, const Vec3<Real>& S, Real r, Recorder& record) {
    SphereCoefficients<Real> k;
    k.EE = length_squared(E);
    record(Key::EE, k.EE);
    k.SS = length_squared(S);
    record(Key::SS, k.SS);
    k.C = dot(E, S);
    record(Key::C, k.C);
    record.lost_in_dot(Key::C, E, S, k.C);
    k.c_0 = k.SS - r * r;
    record(Key::c_0, k.c_0);
    if constexpr (Recorder::estimates) record.lost(Key::c_0, k.SS, r * r, k.c_0);
    return k;
}

// The engine's choice between a formula's two roots (either order): the
// nearer if it is > 0, else the farther if it is > 0 (the eye inside the
// sphere), else the sphere is behind the eye. A root that is NaN or infinite
// is returned as the near one, so the caller reports the pixel non-finite.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> nearest_root_ahead(Real t_a, Real t_b, Recorder& record) {
    const bool finite = t_a * Real(0) == Real(0) && t_b * Real(0) == Real(0);
    const Real near = !finite ? (t_a * Real(0) == Real(0) ? t_b : t_a) : t_a < t_b ? t_a : t_b;
    const Real far = t_a < t_b ? t_b : t_a;
    // (A root of -inf, too, decides nothing: it is not "behind the eye".)
    if (!finite || !(near <= 0)) {
        if constexpr (Recorder::records) record(Key::found, "near");
        return SphereRoot<Real>{near, false};
    }
    if (far > 0) {
        if constexpr (Recorder::records) record(Key::found, "far");
        return SphereRoot<Real>{far, true};
    }
    if constexpr (Recorder::records) record(Key::found, "behind");
    return std::nullopt;
}

// The article's formula, with the engine's choice of root.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> intersect_sphere(const Vec3<Real>& E, const Vec3<Real>& S, Real r,
                                                 Recorder& record) {
    const std::optional<Real> t = intersect_sphere_article(E, S, r, record);
    if (!t) {
        if constexpr (Recorder::records) record(Key::found, "miss");
        return std::nullopt;
    }
    // A NaN or infinite t (delta, or the division by |E|^2, not finite) passes
    // on, to be reported as non-finite.
    if (!(*t <= 0) || !finite_value(*t)) {
        if constexpr (Recorder::records) record(Key::found, "near");
        return SphereRoot<Real>{*t, false};
    }
    // The same EE, C and delta as the near root's (the compiler shares them).
    const Real EE = length_squared(E);
    const Real C = dot(E, S);
    const Real delta = C * C - EE * (length_squared(S) - r * r);
    const Real t_far = (C + square_root(delta)) / EE;
    record(Key::t_far, t_far);
    // Its numerator cancels when C < 0 (the sphere's centre behind the eye).
    if constexpr (Recorder::estimates) record.lost(Key::t_far, C, square_root(delta), C + square_root(delta));
    if (t_far > 0) {
        if constexpr (Recorder::records) record(Key::found, "far");
        return SphereRoot<Real>{t_far, true};
    }
    if constexpr (Recorder::records) record(Key::found, "behind");
    return std::nullopt;
}

}  // namespace promyk
