// Each formula as a type, so a kernel takes it as a template parameter and
// the choice is made once, at compile time, never per pixel. Each policy's
// intersect returns the engine's root: the nearest with t > 0 and whether it
// is the far one (the eye inside), or no hit; a NaN or infinite root is
// returned so the caller reports the pixel non-finite.
#pragma once

#include <optional>

#include "geometry/formula.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_fma.hpp"
#include "geometry/sphere_geometric.hpp"
#include "geometry/sphere_stable.hpp"

namespace promyk {

template <Formula F>
struct SphereFormula {
    static constexpr Formula id = F;
    template <class Real, class Recorder>
    static std::optional<SphereRoot<Real>> intersect(const Vec3<Real>& E, const Vec3<Real>& S, Real r,
                                                     Recorder& record) {
        if constexpr (F == Formula::stable)
            return intersect_sphere_stable(E, S, r, record);
        else if constexpr (F == Formula::fma)
            return intersect_sphere_fma(E, S, r, record);
        else if constexpr (F == Formula::geometric)
            return intersect_sphere_geometric(E, S, r, record);
        else
            return intersect_sphere(E, S, r, record);
    }
};

// The engine's root by the formula chosen at run time: for tests and tools
// that look at one ray, never for a pixel loop.
template <class Real, class Recorder>
std::optional<SphereRoot<Real>> intersect_sphere_with(Formula formula, const Vec3<Real>& E, const Vec3<Real>& S,
                                                      Real r, Recorder& record) {
    switch (formula) {
        case Formula::stable:
            return SphereFormula<Formula::stable>::intersect(E, S, r, record);
        case Formula::fma:
            return SphereFormula<Formula::fma>::intersect(E, S, r, record);
        case Formula::geometric:
            return SphereFormula<Formula::geometric>::intersect(E, S, r, record);
        case Formula::article:
            break;
    }
    return SphereFormula<Formula::article>::intersect(E, S, r, record);
}

}  // namespace promyk
