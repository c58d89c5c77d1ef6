#include "render/pane_columns.hpp"

#include <cstddef>
#include <vector>

#include "render/pane.hpp"

namespace promyk {

namespace {

template <class Real>
const Real* x_E_of(int w) {
    thread_local std::vector<Real> x_E;
    if (static_cast<int>(x_E.size()) != w) {
        x_E.resize(static_cast<std::size_t>(w));
        for (int j = 0; j < w; ++j) x_E[static_cast<std::size_t>(j)] = pane_x<Real>(j, w);
    }
    return x_E.data();
}

}  // namespace

const double* pane_columns(int w) { return x_E_of<double>(w); }
const float* pane_columns_float(int w) { return x_E_of<float>(w); }

}  // namespace promyk
