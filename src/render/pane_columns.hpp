// x_E of every column of a w-pixel pane (render/pane.hpp's pane_x): the
// same for every row, so the row kernels read them instead of dividing
// once a pixel.
#pragma once

namespace promyk {

// pane_x(j, w) for j = 0 .. w - 1, computed once per thread and pane; valid
// until this thread asks for another w.
const double* pane_columns(int w);
// The same in float, each computed in float (pane_x<float>), for --real float.
const float* pane_columns_float(int w);

}  // namespace promyk
