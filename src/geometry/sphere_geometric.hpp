// The geometric formula (`--formula geometric`) of Haines, Guenther and
// Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection"
// (Ray Tracing Gems, 2019, chapter 7), in the engine's parametrisation: the
// ray is tE, t in units of E, not normalised.
//
// The article's delta = C^2 - |E|^2 c_0 subtracts two numbers of the size
// |E|^2 |S|^2 to get one of the size |E|^2 r^2: for a small sphere far away
// every digit cancels. The same discriminant is |E|^2 (r^2 - |l|^2), where l
// is the vector from the centre S to the ray's point closest to it,
// t_mid E with t_mid = C / |E|^2 (the paper's f + b'd with f = -S and d the
// direction). l's components carry absolute errors of about eps |S|, so
// delta_g = r^2 - |l|^2 is off by about eps |S| r, not eps |S|^2: the sphere
// stays visible |S| / r times farther away. The roots then come the
// cancellation-free way (geometry/sphere_stable.hpp) from
// q = C + sign(C) sqrt(|E|^2 delta_g): the paper's t_0 = c / q and t_1 = q, in
// units of E (the paper divides distances by |d| = 1; here by |E|^2 once).
#pragma once

#include <optional>

#include "geometry/sphere.hpp"
#include "geometry/sphere_stable.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

// Operation order (each one rounding): EE, SS, C as the article's;
// c_0 = SS - r*r; t_mid = C / EE; l = t_mid*E - S (per component: a
// product, then a difference); ll = |l|^2 (l.x*l.x + l.y*l.y, + l.z*l.z);
// delta_g = r*r - ll; a miss when delta_g <= 0; q = C +- sqrt(EE*delta_g);
// q / EE; c_0 / q.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> intersect_sphere_geometric(const Vec3<Real>& E, const Vec3<Real>& S, Real r,
                                                           Recorder& record) {
    const auto [EE, SS, C, c_0] = sphere_coefficients(E, S, r, record);
    const Real t_mid = C / EE;
    record(Key::t_mid, t_mid);
    const Vec3<Real> l = t_mid * E - S;
    record(Key::l, l);
    if constexpr (Recorder::estimates) record.lost(Key::l, t_mid * E, S, l);
    const Real ll = length_squared(l);
    record(Key::ll, ll);
    const Real delta_g = r * r - ll;
    record(Key::delta_g, delta_g);
    if constexpr (Recorder::estimates) record.lost(Key::delta_g, r * r, ll, delta_g);
    if (records_miss(delta_g, record)) return std::nullopt;
    return cancellation_free_roots(C, square_root(EE * delta_g), c_0, EE, record);
}

}  // namespace promyk
