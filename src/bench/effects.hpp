// promyk bench effects: what each effect costs. Renders every example scene
// (lessons/scenes/, as built into the binary) in one run, on one thread,
// alternating the scenes round after round, and reports each scene's time per
// pixel as a ratio to the article's scene, next to the work the engine did
// (rays and intersection tests per pixel), so the cost can be read against
// its cause.
#pragma once

namespace promyk::bench {

struct EffectsOptions {
    int w = 2048;         // pane side (runs shorter than 20 ms are repeated until they last long enough)
    int repetitions = 5;  // alternating rounds; medians are reported
};

// Prints the table to stdout; returns 0.
int run_effects_bench(const EffectsOptions& options);

}  // namespace promyk::bench
