// The article's roots with Kahan's discriminant (`--formula fma`): delta =
// C^2 - |E|^2 c_0 computed with fused multiply-adds so that, for the given
// C, |E|^2 and c_0, it has one rounding instead of cancelling two:
//
//   w = |E|^2 c_0 (rounded), e = fma(-|E|^2, c_0, w) = w - |E|^2 c_0 exactly,
//   delta = fma(C, C, -w) + e.
//
// Why it does not help here: it is exact for the numbers it is given, and
// those are already rounded. C = E.S carries a relative error of about one
// unit in the last place, so C^2 is off by about 2 eps C^2; c_0 = |S|^2 - r^2
// likewise by eps |S|^2. For a small sphere far away delta is tiny against
// C^2 (r^2 |E|^2 against |S|^2 |E|^2), and these input errors swamp it just as
// they swamp the article's delta: the sphere is lost at the same distance.
// Only when the coefficients happen to be exact (integers small enough)
// does Kahan's delta come out right. The cure is to compute delta from
// other quantities (geometry/sphere_geometric.hpp), not more exactly from
// the same ones.
#pragma once

#include <optional>

#include "geometry/sphere.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// Operation order: EE, SS, C as the article's; c_0 = SS - r*r; w = EE*c_0;
// e = fma(-EE, c_0, w); delta = fma(C, C, -w) + e; a miss when delta <= 0;
// then the article's roots t = (C - sqrt(delta)) / EE and
// t_far = (C + sqrt(delta)) / EE (both recorded).
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> intersect_sphere_fma(const Vec3<Real>& E, const Vec3<Real>& S, Real r,
                                                     Recorder& record) {
    const auto [EE, SS, C, c_0] = sphere_coefficients(E, S, r, record);
    const Real w = EE * c_0;
    record(Key::w_fma, w);
    const Real e = fused_multiply_add(-EE, c_0, w);
    record(Key::e_fma, e);
    const Real delta = fused_multiply_add(C, C, -w) + e;
    record(Key::delta_fma, delta);
    // Digits lost: C^2 against w = |E|^2 c_0, as in the article's delta. (e is
    // w - |E|^2 c_0 exactly, a rounding error made visible by design: it has
    // no estimate.)
    if constexpr (Recorder::estimates) record.lost(Key::delta_fma, C * C, w, delta);
    if (records_miss(delta, record)) return std::nullopt;
    const Real root = square_root(delta);
    const Real t = (C - root) / EE;
    record(Key::t, t);
    if constexpr (Recorder::estimates) record.lost(Key::t, C, root, C - root);
    const Real t_far = (C + root) / EE;
    record(Key::t_far, t_far);
    if constexpr (Recorder::estimates) record.lost(Key::t_far, C, root, C + root);
    return nearest_root_ahead(t, t_far, record);
}

}  // namespace promyk
