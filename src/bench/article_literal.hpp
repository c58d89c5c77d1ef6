// The article's program (Fig. 5 pseudocode), compiled literally into the
// binary so that `promyk bench speed` can time the engine against it side
// by side. It is deliberately not built from the engine's parts.
#pragma once

#include <cstdint>

namespace promyk::bench {

struct LiteralScene {
    double x_S, y_S, z_S, r;
    double x_L, y_L, z_L, I;
    double z_E;
};

// function intensity(x_E, y_E, z_E), line by line.
double literal_intensity(double x_E, double y_E, double z_E, const LiteralScene& scene);

// The article's pixel loop, with the screen in place of the array t:
// screen[i * w + j] is pixel (i, j) as an 8-bit grey level.
void literal_render(const LiteralScene& scene, int w, std::uint8_t* screen);

}  // namespace promyk::bench
