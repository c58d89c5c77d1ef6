// x^n for a whole n >= 1 by repeated squaring from the lowest bit of n, so
// that every build (and the browser's) gives the same bits, which std::pow
// does not promise.
#pragma once

namespace promyk {

template <class Real>
Real power(Real x, int n) {
    Real y = Real(1);
    for (; n > 0; n >>= 1) {
        if (n & 1) y = y * x;
        x = x * x;
    }
    return y;
}

}  // namespace promyk
