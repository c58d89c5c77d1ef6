// The article's program (Fig. 5 pseudocode) as a programmer would compile it
// from the page: one file, the pixel loop and `intensity` together (so the
// compiler inlines it and hoists what does not change), the scene in local
// variables, and the article's array t[i, j] of doubles as the result. It is
// the yardstick `promyk bench speed` times the engine against; it is
// deliberately not built from the engine's parts.
#pragma once

#include <vector>

namespace promyk::bench {

struct LiteralScene {
    double x_S, y_S, z_S, r;
    double x_L, y_L, z_L, I;
    double z_E;
    double background;  // the article's 1/2
};

// for i := 0 to w - 1, for j := 0 to w - 1: t[i, j] := intensity(x_E, y_E, z_E).
// t holds w * w doubles, t[i * w + j] being pixel (i, j).
void literal_render(const LiteralScene& scene, int w, std::vector<double>& t);

}  // namespace promyk::bench
