#include "bench/article_literal.hpp"

#include <cmath>

#include "render/quantize.hpp"

namespace promyk::bench {

double literal_intensity(double x_E, double y_E, double z_E, const LiteralScene& s) {
    const double E = x_E * x_E + y_E * y_E + z_E * z_E;
    const double S = s.x_S * s.x_S + s.y_S * s.y_S + s.z_S * s.z_S;
    const double C = x_E * s.x_S + y_E * s.y_S + z_E * s.z_S;
    const double Delta = C * C - E * (S - s.r * s.r);
    if (Delta <= 0) return 0.5;
    const double t = (C - std::sqrt(Delta)) / E;
    const double x_P = t * x_E, y_P = t * y_E, z_P = t * z_E;
    const double x_N = x_P - s.x_S, y_N = y_P - s.y_S, z_N = z_P - s.z_S;
    const double x_K = s.x_L - x_P, y_K = s.y_L - y_P, z_K = s.z_L - z_P;
    const double K = x_K * x_K + y_K * y_K + z_K * z_K;
    const double D = x_N * x_K + y_N * y_K + z_N * z_K;
    if (D <= 0) return 0;
    return s.I * D / (s.r * std::sqrt(K));
}

void literal_render(const LiteralScene& scene, int w, std::uint8_t* screen) {
    for (int i = 0; i <= w - 1; ++i) {
        for (int j = 0; j <= w - 1; ++j) {
            const double y_E = -(2.0 * i + 1) / w + 1;
            const double x_E = (2.0 * j + 1) / w - 1;
            screen[static_cast<long>(i) * w + j] = to_byte(literal_intensity(x_E, y_E, scene.z_E, scene));
        }
    }
}

}  // namespace promyk::bench
