// The pane: pixel (i, j) of a w x w pane at z = z_E maps to the centre of its
// square, E = (x_E, y_E, z_E). i is the row from the top, j the column from
// the left. E is not normalised.
#pragma once

#include "math/vec3.hpp"

namespace promyk {

// y_E := -(2i + 1)/w + 1, as in the article: the same for a whole row.
template <class Real>
Real pane_y(int i, int w) {
    return -Real(2 * i + 1) / Real(w) + Real(1);
}

// x_E := (2j + 1)/w - 1, as in the article.
template <class Real>
Real pane_x(int j, int w) {
    return Real(2 * j + 1) / Real(w) - Real(1);
}

template <class Real>
Vec3<Real> pane_point(int i, int j, int w, Real z_E) {
    return {pane_x<Real>(j, w), pane_y<Real>(i, w), z_E};
}

}  // namespace promyk
