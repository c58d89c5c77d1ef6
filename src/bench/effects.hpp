// promyk bench effects: what each effect costs. Renders every example scene
// (lessons/scenes/, as built into the binary) in one run, on one thread,
// alternating the scenes round after round, and reports each scene's time per
// pixel as a ratio to the article's scene, next to the work the engine did
// (rays and intersection tests per pixel), so the cost can be read against
// its cause. With --spp N, at N samples a pixel, and each scene's cost of a
// sample against its own pixel at spp 1, timed in the same rounds.
#pragma once

namespace promyk::bench {

struct EffectsOptions {
    int w = 2048;         // pane side (runs shorter than 20 ms are repeated until they last long enough)
    int repetitions = 5;  // alternating rounds; medians are reported
    int spp = 1;          // samples per pixel; above 1 each scene is also timed at spp 1, beside
};

// Prints the table to stdout; returns 0.
int run_effects_bench(const EffectsOptions& options);

}  // namespace promyk::bench
