// Intensity to an 8-bit grey level: round(clamp(v, 0, 1) * 255), halves
// rounded up. A NaN (a non-finite pixel) maps to 0.
#pragma once

#include <cstdint>

namespace promyk {

// Branch-free: an `if` on the fraction is mispredicted all along a smooth
// gradient, which once cost as much as the pixel's own arithmetic.
inline std::uint8_t to_byte(double v) {
    double clamped = v > 0 ? v : 0;          // maxsd; also NaN -> 0
    clamped = clamped < 1 ? clamped : 1;     // minsd
    const double y = clamped * 255;
    const int q = static_cast<int>(y);       // truncation; y - q is then exact
    return static_cast<std::uint8_t>(q + (y - q >= 0.5));
}

}  // namespace promyk
