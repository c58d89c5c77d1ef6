// Intensity to an 8-bit grey level: round(clamp(v, 0, 1) * 255), halves
// rounded up. A NaN (never produced by a valid scene) maps to 0.
#pragma once

#include <cstdint>

namespace promyk {

inline std::uint8_t to_byte(double v) {
    const double clamped = v > 0 ? (v < 1 ? v : 1) : 0;
    const double y = clamped * 255;
    int q = static_cast<int>(y);  // truncation; y - q is then exact
    if (y - q >= 0.5) ++q;
    return static_cast<std::uint8_t>(q);
}

}  // namespace promyk
