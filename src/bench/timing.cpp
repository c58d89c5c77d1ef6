#include "bench/timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "trace/messages.hpp"
#include "util/interrupt.hpp"

namespace promyk::bench {

double steady_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TimedWork repeated(std::function<void()> unit) {
    return [unit = std::move(unit)](long count) {
        for (long k = 0; k < count; ++k) unit();
    };
}

double median_of(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

namespace {

double timed_run(const TimedWork& work, long count, const TimingClock& clock) {
    const double start = clock();
    work(count);
    const double seconds = clock() - start;
    throw_if_interrupted();
    return seconds;
}

std::string too_short(long count, const TimingPolicy& policy) {
    return ui_message("bench_untimed_short", {{"count", std::to_string(count)},
                                              {"ms", std::to_string(std::lround(policy.min_run_seconds * 1e3))}});
}

}  // namespace

Calibration calibrate(const TimedWork& work, const TimingPolicy& policy, std::vector<long>* counts_tried) {
    Calibration c;
    for (;;) {
        if (counts_tried) counts_tried->push_back(c.count);
        c.seconds = timed_run(work, c.count, policy.clock);
        if (c.seconds >= policy.min_run_seconds) {
            c.long_enough = true;
            return c;
        }
        if (c.count >= policy.max_count) return c;
        // Doubling: a short run says little about how long a unit takes (a
        // clock tick, a wait for a core), so it is not extrapolated from.
        c.count = std::min(c.count * 2, policy.max_count);
    }
}

std::vector<Timing> time_side_by_side(const std::vector<TimedWork>& jobs, const TimingPolicy& policy) {
    std::vector<Timing> timings(jobs.size());
    long done = 0;
    const long total = static_cast<long>(jobs.size()) * (policy.rounds + 1);
    auto progress = [&] {
        if (policy.progress) policy.progress(++done, total);
    };
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        const Calibration c = calibrate(jobs[k], policy);
        timings[k].count = c.count;
        if (!c.long_enough) timings[k].problem = too_short(c.count, policy);
        progress();
    }
    for (int round = 0; round < policy.rounds; ++round) {
        for (std::size_t n = 0; n < jobs.size(); ++n) {
            const std::size_t k = round % 2 ? jobs.size() - 1 - n : n;
            Timing& t = timings[k];
            if (!t.problem.empty()) {
                progress();
                continue;
            }
            double seconds = timed_run(jobs[k], t.count, policy.clock);
            // The machine got faster than at calibration (a busy neighbour
            // left): the run is too short to mean much, so it grows again.
            while (seconds < policy.min_run_seconds && t.count < policy.max_count) {
                t.count = std::min(t.count * 2, policy.max_count);
                seconds = timed_run(jobs[k], t.count, policy.clock);
            }
            if (seconds < policy.min_run_seconds) {
                t.problem = too_short(t.count, policy);
                progress();
                continue;
            }
            t.shortest_run_seconds = t.seconds_per_unit.empty() ? seconds : std::min(t.shortest_run_seconds, seconds);
            t.seconds_per_unit.push_back(seconds / static_cast<double>(t.count));
            progress();
        }
    }
    for (Timing& t : timings) {
        t.median_seconds_per_unit = median_of(t.seconds_per_unit);
        t.timed = t.problem.empty() && !t.seconds_per_unit.empty();
        if (t.problem.empty() && !t.timed) t.problem = ui_message("bench_untimed_no_rounds");
    }
    return timings;
}

}  // namespace promyk::bench
