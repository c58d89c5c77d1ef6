// The pane: pixel (i, j) of a w x w pane at z = z_E maps to the centre of its
// square, E = (x_E, y_E, z_E). i is the row from the top, j the column from
// the left. E is not normalised.
#pragma once

#include "math/vec3.hpp"

namespace promyk {

template <class Real>
Vec3<Real> pane_point(int i, int j, int w, Real z_E) {
    // y_E := -(2i + 1)/w + 1 and x_E := (2j + 1)/w - 1, as in the article.
    const Real y_E = -Real(2 * i + 1) / Real(w) + Real(1);
    const Real x_E = Real(2 * j + 1) / Real(w) - Real(1);
    return {x_E, y_E, z_E};
}

}  // namespace promyk
