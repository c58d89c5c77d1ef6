// promyk bench speed: the engine against the article's literal program,
// threads against one thread, and the cost of writing traces, measured
// side by side in one run and reported as ratios.
#pragma once

#include <string>

namespace promyk::bench {

struct SpeedOptions {
    int w = 4096;         // pane side for the image timings (runs under 20 ms are repeated)
    int repetitions = 7;  // alternating rounds; medians are reported
    int threads = 0;      // 0: all cores
    int trace_w = 512;    // pane side for the traces' throughput
};

// Runs the benchmark, printing the table to stdout. Returns 0, or 1 when the
// engine's image differs from the literal program's (it must not).
int run_speed_bench(const SpeedOptions& options);

}  // namespace promyk::bench
