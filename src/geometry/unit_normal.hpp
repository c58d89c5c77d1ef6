// A plane's unit normal n̂ = n / |n|, |n| = √(n·n), each component divided,
// for every finite non-zero n. n is first scaled by a power of two so that its
// largest |component| lies in [1, 2): n·n then lies in [1, 12) and neither
// underflows (n = [0, 3e-162, 0] made n·n a subnormal, and n̂ came out
// [0, 0.954, 0]) nor overflows, in any Real type (float's range is far
// narrower than a scene's doubles). A power of two is exact and commutes with
// the correctly rounded √ and division, so a normal that needed no scaling
// keeps every bit of its old n̂.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/real.hpp"
#include "math/vec3.hpp"

namespace promyk {

template <class Real>
Vec3<Real> unit_normal(const Vec3d& n) {
    const double largest = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
    const int e = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
    const Vec3<Real> v{Real(std::scalbn(n.x, -e)), Real(std::scalbn(n.y, -e)), Real(std::scalbn(n.z, -e))};
    return v / square_root(length_squared(v));
}

}  // namespace promyk
