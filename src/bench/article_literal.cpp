#include "bench/article_literal.hpp"

#include <cmath>

namespace promyk::bench {

namespace {

// function intensity(x_E, y_E, z_E), line by line. The scene comes by value,
// as the pseudocode's global constants would: nothing is reloaded per pixel.
inline double intensity(double x_E, double y_E, double z_E, double x_S, double y_S, double z_S, double r,
                        double x_L, double y_L, double z_L, double I, double background) {
    const double E = x_E * x_E + y_E * y_E + z_E * z_E;
    const double S = x_S * x_S + y_S * y_S + z_S * z_S;
    const double C = x_E * x_S + y_E * y_S + z_E * z_S;
    const double Delta = C * C - E * (S - r * r);
    if (Delta <= 0) return background;
    const double t = (C - std::sqrt(Delta)) / E;
    const double x_P = t * x_E, y_P = t * y_E, z_P = t * z_E;
    const double x_N = x_P - x_S, y_N = y_P - y_S, z_N = z_P - z_S;
    const double x_K = x_L - x_P, y_K = y_L - y_P, z_K = z_L - z_P;
    const double K = x_K * x_K + y_K * y_K + z_K * z_K;
    const double D = x_N * x_K + y_N * y_K + z_N * z_K;
    if (D <= 0) return 0;
    return I * D / (r * std::sqrt(K));
}

}  // namespace

void literal_render(const LiteralScene& scene, int w, std::vector<double>& t) {
    const double x_S = scene.x_S, y_S = scene.y_S, z_S = scene.z_S, r = scene.r;
    const double x_L = scene.x_L, y_L = scene.y_L, z_L = scene.z_L, I = scene.I;
    const double z_E = scene.z_E, background = scene.background;
    t.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(w));
    double* out = t.data();
    for (int i = 0; i <= w - 1; ++i) {
        for (int j = 0; j <= w - 1; ++j) {
            const double y_E = -(2.0 * i + 1) / w + 1;
            const double x_E = (2.0 * j + 1) / w - 1;
            out[static_cast<std::size_t>(i) * w + j] =
                intensity(x_E, y_E, z_E, x_S, y_S, z_S, r, x_L, y_L, z_L, I, background);
        }
    }
}

}  // namespace promyk::bench
