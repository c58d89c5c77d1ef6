#include "trace/digits_alarm.hpp"

#include <algorithm>
#include <cmath>

namespace promyk {

namespace {

// The grey level of an intensity: round(clamp(v, 0, 1) · 255), halves up.
int grey_level(double scaled) { return static_cast<int>(std::floor(std::clamp(scaled, 0.0, 255.0) + 0.5)); }

}  // namespace

double full_digits_of(std::string_view real) {
    constexpr double log10_2 = 0.30102999566398119521;
    if (real == "float") return 24 * log10_2;
    if (real == "double") return 53 * log10_2;
    if (real == "long-double") return 64 * log10_2;
    if (real == "quad") return 113 * log10_2;
    return 0;
}

bool digits_lost_alarm(double digits_lost, double full_digits, const std::vector<double>& intensities) {
    if (std::isnan(digits_lost) || full_digits <= 0) return false;
    if (digits_lost > full_digits / 2) return true;
    const double relative = std::pow(10.0, digits_lost - full_digits);
    for (const double I : intensities) {
        if (!std::isfinite(I)) continue;
        const double scaled = 255 * I, spread = std::fabs(scaled) * relative;
        if (grey_level(scaled - spread) != grey_level(scaled + spread)) return true;
    }
    return false;
}

}  // namespace promyk
