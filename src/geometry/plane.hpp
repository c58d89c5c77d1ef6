// Intersecting a plane through Q with unit normal n_hat: the points X with
// n_hat.X = NQ (NQ = n_hat.Q, computed once per scene). The ray tE meets it
// at t = NQ / (n_hat.E); a ray parallel to the plane (n_hat.E = 0) misses it
// without a division, so no infinity or NaN reaches the trace.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

template <class Real>
struct PlaneRoot {
    Real t;   // > 0 and finite; NaN when n_hat.Q or n_hat.E is not (nothing decided)
    Real NE;  // n_hat.E: > 0 when the eye sees the plane's back
};

template <class Real, class Recorder>
std::optional<PlaneRoot<Real>> intersect_plane(const Vec3<Real>& E, const Vec3<Real>& n_hat, Real NQ,
                                               Recorder& record) {
    if constexpr (Recorder::records) {
        // The plane's own numbers, the same for every ray, for the lessons.
        record(Key::n_hat, n_hat);
        record(Key::NQ, NQ);
    }
    const Real NE = dot(n_hat, E);
    record(Key::NE, NE);
    record.lost_in_dot(Key::NE, n_hat, E, NE);
    if (NE == 0) {
        if constexpr (Recorder::records) record(Key::found, "parallel");
        return std::nullopt;
    }
    const Real t = NQ / NE;
    // n_hat.Q or n_hat.E beyond the type's range decides nothing (a float
    // plane 1e39 away is not behind the eye): a NaN t, which the caller
    // reports as non-finite, as it does a sphere's.
    if (!(NQ * Real(0) + NE * Real(0) == Real(0))) return PlaneRoot<Real>{RealTraits<Real>::quiet_nan(), NE};
    // t may overflow for a ray all but parallel: the hit is beyond every
    // double, at the horizon, and is not drawn; no infinity reaches the trace.
    const bool finite = t * Real(0) == Real(0);
    if (finite) record(Key::t_plane, t);
    if (t > 0 && finite) {
        if constexpr (Recorder::records) record(Key::found, "near");
        return PlaneRoot<Real>{t, NE};
    }
    if constexpr (Recorder::records) record(Key::found, t > 0 ? "horizon" : "behind");
    return std::nullopt;
}

}  // namespace promyk
