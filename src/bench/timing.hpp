// The one way the benches time things: a job is run again and again within
// a timed run until the run lasts long enough for the clock and the
// scheduler to be noise, then every job is timed round after round, side by
// side, and the median time per unit of work is reported. A job that cannot
// be timed says why instead of giving a number.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace promyk::bench {

// Seconds since some fixed moment (steady); tests pass a fake one.
using TimingClock = std::function<double()>;
double steady_seconds();

// Runs a job's unit of work `count` times in a row (so that per-run setup,
// such as pinning the thread to a core, is done once per timed run).
using TimedWork = std::function<void(long count)>;

// A job whose unit is `unit`, repeated.
TimedWork repeated(std::function<void()> unit);

struct TimingPolicy {
    double min_run_seconds = 0.020;  // a timed run shorter than this says more about the clock than the work
    long max_count = 1L << 24;       // the most units in one timed run: beyond it the job cannot be timed
    int rounds = 5;                  // alternating rounds; medians are reported
    TimingClock clock = steady_seconds;
    // Called after every timed run (calibration and rounds): runs done, and
    // an estimate of the total (it grows while calibration doubles counts).
    std::function<void(long done, long total)> progress;
};

// How many units make a timed run long enough: 1, 2, 4, ... until a run
// lasts at least min_run_seconds. `counts_tried`, when given, receives
// every count tried, in order (tests show the doubling with it).
struct Calibration {
    long count = 1;
    double seconds = 0;  // the last run's length (count units)
    bool long_enough = false;
};
Calibration calibrate(const TimedWork& work, const TimingPolicy& policy, std::vector<long>* counts_tried = nullptr);

struct Timing {
    long count = 0;                         // units in each timed run
    std::vector<double> seconds_per_unit;   // one a round
    double median_seconds_per_unit = 0;     // 0 when not timed
    bool timed = false;
    std::string problem;                    // why not timed, in the run's language: empty when timed
    double shortest_run_seconds = 0;        // the shortest timed run of the rounds
};

// Calibrates every job, then times them all `rounds` times, forwards and
// backwards in turn (so a drift of the machine's speed weighs on all alike).
// A round's run that comes out too short (the machine got faster since the
// calibration) is run again with twice the units, so every run that counts
// lasts at least min_run_seconds. A job is timed only when its runs reach
// that within max_count units. Throws Interrupted when a signal asks to stop
// (checked between runs); an exception from a job propagates.
std::vector<Timing> time_side_by_side(const std::vector<TimedWork>& jobs, const TimingPolicy& policy);

double median_of(std::vector<double> values);

}  // namespace promyk::bench
