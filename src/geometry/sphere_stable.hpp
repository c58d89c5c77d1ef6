// The sphere's roots without cancellation (`--formula stable`). The article's
// near root (C - sqrt(delta)) / |E|^2 subtracts two nearly equal numbers when
// sqrt(delta) is close to C, that is when |E|^2 (|S|^2 - r^2) is small against
// C^2: the eye close to the surface of a sphere that is large or near. Here
// the two roots are taken from q = C + sign(C) sqrt(delta), a sum of two
// numbers of one sign, as q / |E|^2 and, by Vieta (t_1 t_2 = c_0 / |E|^2),
// c_0 / q. Neither subtracts. delta itself is the program's, with its own
// cancellation (C^2 against |E|^2 c_0) untouched: a small sphere far away is
// lost as the article loses it (geometry/sphere_geometric.hpp keeps it).
#pragma once

#include <optional>

#include "geometry/sphere.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// The roots q / |E|^2 and c_0 / q of t^2 |E|^2 - 2tC + c_0 = 0, from
// root_term = sqrt(delta) >= 0, with q = C + sign(C) root_term and
// sign(0) = +1; then the engine's choice between them. Shared by the stable
// and geometric formulas, which differ in how they compute root_term.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> cancellation_free_roots(Real C, Real root_term, Real c_0, Real EE, Recorder& record) {
    const Real q = C >= 0 ? C + root_term : C - root_term;
    record(Key::q, q);
    // Two numbers of one sign: never cancels (its estimate is 0, shown for that).
    record.lost(Key::q, C, root_term, q);
    const Real t_q = q / EE;
    record(Key::t_q, t_q);
    const Real t_c = c_0 / q;
    record(Key::t_c, t_c);
    return nearest_root_ahead(t_q, t_c, record);
}

// Operation order (each one rounding): EE = |E|^2, SS = |S|^2, C = E.S as the
// article's; c_0 = SS - r*r; delta = C*C - EE*c_0 (the program's delta, the
// same operations); a miss when delta <= 0; q = C +- sqrt(delta); q / EE;
// c_0 / q.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> intersect_sphere_stable(const Vec3<Real>& E, const Vec3<Real>& S, Real r,
                                                        Recorder& record) {
    const auto [EE, SS, C, c_0] = sphere_coefficients(E, S, r, record);
    const Real delta = C * C - EE * c_0;
    record(Key::delta, delta);
    if constexpr (Recorder::estimates) record.lost(Key::delta, C * C, EE * c_0, delta);
    if (records_miss(delta, record)) return std::nullopt;
    return cancellation_free_roots(C, square_root(delta), c_0, EE, record);
}

}  // namespace promyk
