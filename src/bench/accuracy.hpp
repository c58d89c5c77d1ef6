// promyk bench accuracy: what precision, formulas and samples cost in time
// against what they buy in accuracy (PRODUCT.md §8). For every real type ×
// formula × samples per pixel, on the article's scene and on a far sphere, in
// one run: the time per pixel (rendering the scene, all combinations side
// by side, round after round) as a ratio to double/article at spp 1, and the
// error of every pixel's intensity against a reference computed in the same
// run in quad with the geometric formula at the same spp (largest, median,
// pixels whose branch differs). Printed as a table; as JSON for a web page
// (src/bench/accuracy.schema.json).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/formula.hpp"
#include "math/real.hpp"
#include "render/kernel.hpp"
#include "scene/scene.hpp"
#include "trace/keys.hpp"

namespace promyk::bench {

// The far sphere: a unit sphere 10⁴ away on the axis, S = (0, 0, 10⁴), r = 1,
// with the pane at z_E = 8000 so that its disc (radius ≈ 0.8 on the pane)
// covers about half the pane, and the light L = (5000, 5000, 0), I = 1, 35°
// off the line of sight, so that about nine tenths of the visible sphere is
// lit. The article's formula in float loses a unit sphere from a distance of
// about 4097 on (every pixel misses), in double at about 10⁸; geometric keeps it.
Scene far_sphere_scene();

// Every pixel's intensity and branch on a w × w pane, row by row (i, then j),
// as Kernel::exact_intensity gives them (a grey scene: the first channel):
// exactly, in quad, and rounded to double.
struct PaneValues {
    int w = 0;
    std::vector<double> I;
    std::vector<quad> exact;  // the same values exactly; may be empty (then I is compared)
    std::vector<Branch> branch;
};

// Computes the pane's values with `threads` threads (0: all cores), rows
// handed out one at a time; throws Interrupted when a signal asks to stop.
PaneValues pane_values(const Kernel& kernel, int w, int threads);

// A run's intensities against the reference's, pixel by pixel.
struct ErrorStats {
    long long pixels = 0;           // w × w
    long long sphere_pixels = 0;    // pixels whose reference branch is not `miss`
    double max_error = 0;           // max |I − I_ref| over every pixel (infinity if a value is not finite)
    double median_error = 0;        // median |I − I_ref| over the sphere's pixels (0 when there are none)
    long long branch_differs = 0;   // pixels whose branch differs from the reference's
    long long non_finite = 0;       // pixels whose intensity (the run's or the reference's) is not finite
};

// The error of `run` against `reference` (same w): the absolute difference of
// the intensities, since I lies in [0, 1], taken in quad between the exact
// values (so a long double's errors, about 1e-20, show), then rounded to
// double. The median is taken over the
// pixels where the reference meets the sphere: a miss is exactly 1/2 in every
// type and formula, so over the whole pane the median would say more about
// the scene's framing than about the arithmetic.
ErrorStats compare_to_reference(const PaneValues& run, const PaneValues& reference);

struct AccuracyOptions {
    int w = 128;                         // pane side for the errors; the time of each timed run scales with w² too
    int threads = 0;                     // 0: all cores
    int repetitions = 5;                 // alternating timing rounds; medians are reported
    std::vector<int> spps = {1, 4, 16, 64};
    std::vector<RealType> reals = {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_};
    std::vector<Formula> formulas = {Formula::article, Formula::stable, Formula::fma, Formula::geometric};
    // Called as the work goes: the phase ("errors", "timing"), then work done
    // and total in the phase's own units (each phase starts again from 0).
    std::function<void(std::string_view phase, long done, long total)> progress;
};

// One scene of the run, with its timing baseline.
struct AccuracyScene {
    std::string name;   // "article", "far_sphere"
    Scene scene;
    double base_ns_per_pixel = 0;  // double/article at spp 1: every ratio's baseline on this scene
};

// One combination on one scene.
struct AccuracyRow {
    std::size_t scene = 0;  // index in AccuracyReport::scenes
    int spp = 1;
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    double ns_per_pixel = 0;   // wall-clock time per pixel rendering with the run's threads (median of the rounds)
    double ratio = 0;          // ns_per_pixel / the scene's base_ns_per_pixel
    std::string untimed;       // why there is no ratio (this job or the baseline could not be timed); empty: timed
    int timed_w = 0;           // each timed run renders the scene on a timed_w × timed_w pane
    ErrorStats errors;
};

struct AccuracyReport {
    int w = 0;
    int threads = 1;
    int rounds = 0;            // timing rounds (--repetitions)
    double target_ms = 0;      // the aimed-for length of each timed run
    double shortest_ms = 0;    // the shortest timed run (every run that counts lasts at least 20 ms)
    bool timeable = false;     // every combination was timed (runs of at least 20 ms): every ratio is given
    // Whether a timed kernel counted every pixel's branch (render --stats's
    // work); false: timed as promyk render runs without --stats, as bench
    // speed and bench effects time it.
    bool counted_branches = true;
    std::vector<AccuracyScene> scenes;
    std::vector<AccuracyRow> rows;  // scene, then spp, then real type, then formula
    double seconds = 0;        // the whole run's wall-clock time
};

// Runs the benchmark (nothing is printed).
AccuracyReport run_accuracy_bench(const AccuracyOptions& options);

// The table (standard output's product).
std::string accuracy_table(const AccuracyReport& report);

// The JSON form (src/bench/accuracy.schema.json), one object and a newline.
std::string accuracy_json(const AccuracyReport& report);

}  // namespace promyk::bench
