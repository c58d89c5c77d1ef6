// The benches' timing helper (src/bench/timing.hpp) on a fake clock: the
// work advances the clock by a chosen cost per unit, so the tests know
// exactly how long every run "took" and what the helper must make of it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "bench/timing.hpp"
#include "trace/messages.hpp"

using namespace promyk;
using namespace promyk::bench;

namespace {

// A clock that moves only when the work says so.
struct FakeClock {
    double now = 0;
    TimingClock clock() {
        return [this] { return now; };
    }
    // A job whose unit costs `seconds_per_unit()` (asked anew for every unit).
    template <class Cost>
    TimedWork job(Cost cost) {
        return [this, cost](long count) {
            for (long k = 0; k < count; ++k) now += cost();
        };
    }
};

TimingPolicy policy_on(FakeClock& fake, int rounds = 3) {
    TimingPolicy policy;
    policy.clock = fake.clock();
    policy.rounds = rounds;
    policy.min_run_seconds = 0.020;
    return policy;
}

}  // namespace

TEST_CASE("calibration doubles the repetitions until a run lasts at least the minimum", "[bench][timing]") {
    FakeClock fake;
    std::vector<long> tried;
    const Calibration c = calibrate(fake.job([] { return 1e-3; }), policy_on(fake), &tried);
    CHECK(tried == std::vector<long>{1, 2, 4, 8, 16, 32});
    CHECK(c.count == 32);
    CHECK(c.seconds == Approx(0.032));
    CHECK(c.long_enough);

    // The property behind it, for costs from a microsecond to more than the
    // minimum: counts 1, 2, 4, ..., the last run long enough, the one before not.
    for (const double cost : {1e-6, 3.7e-5, 7e-3, 0.0199, 0.02, 0.5}) {
        CAPTURE(cost);
        FakeClock fresh;  // from 0, so that a run of one unit of 20 ms measures exactly 20 ms
        std::vector<long> counts;
        const Calibration k = calibrate(fresh.job([cost] { return cost; }), policy_on(fresh), &counts);
        for (std::size_t n = 0; n < counts.size(); ++n) CHECK(counts[n] == 1L << n);
        CHECK(k.long_enough);
        CHECK(static_cast<double>(k.count) * cost >= 0.020 * (1 - 1e-12));
        if (counts.size() > 1) CHECK(static_cast<double>(k.count / 2) * cost < 0.020);
    }
}

TEST_CASE("a too-short first run does not leave a ratio out: every job is timed, per unit", "[bench][timing]") {
    FakeClock fake;
    // Units of 0.1 ms and 0.3 ms: a single unit is far under 20 ms.
    const std::vector<TimedWork> jobs = {fake.job([] { return 1e-4; }), fake.job([] { return 3e-4; })};
    const std::vector<Timing> t = time_side_by_side(jobs, policy_on(fake));
    REQUIRE(t.size() == 2);
    for (const Timing& timing : t) {
        CHECK(timing.timed);
        CHECK(timing.problem.empty());
        CHECK(timing.seconds_per_unit.size() == 3);
        CHECK(timing.shortest_run_seconds >= 0.020);
    }
    CHECK(t[0].count == 256);  // 25.6 ms
    CHECK(t[1].count == 128);  // 38.4 ms
    CHECK(t[0].median_seconds_per_unit == Approx(1e-4));
    CHECK(t[1].median_seconds_per_unit == Approx(3e-4));
    CHECK(t[1].median_seconds_per_unit / t[0].median_seconds_per_unit == Approx(3));
}

TEST_CASE("a machine that gets faster after the calibration: the runs grow again, still no missing ratio",
          "[bench][timing]") {
    FakeClock fake;
    long units = 0;
    // Slow (1 ms a unit, a busy neighbour) for the calibration's 63 units, then 10 times faster.
    const TimedWork job = fake.job([&units] { return ++units <= 63 ? 1e-3 : 1e-4; });
    const std::vector<Timing> t = time_side_by_side({job}, policy_on(fake, 2));
    REQUIRE(t.size() == 1);
    CHECK(t[0].timed);
    CHECK(t[0].count == 256);  // 32 → 64 → 128 → 256: 25.6 ms
    CHECK(t[0].shortest_run_seconds >= 0.020);
    CHECK(t[0].median_seconds_per_unit == Approx(1e-4));
}

TEST_CASE("work that never lasts long enough is not timed, and says why", "[bench][timing]") {
    FakeClock fake;
    TimingPolicy policy = policy_on(fake);
    policy.max_count = 64;
    set_ui_language(Language::en);
    const std::vector<Timing> t =
        time_side_by_side({fake.job([] { return 0.0; }), fake.job([] { return 1e-3; })}, policy);
    CHECK_FALSE(t[0].timed);
    CHECK(t[0].problem == "64 repetitions still took under 20 ms");
    CHECK(t[0].seconds_per_unit.empty());
    CHECK(t[1].timed);  // the other job is unaffected
    CHECK(t[1].problem.empty());
}

TEST_CASE("rounds alternate forwards and backwards, and the progress counts every run", "[bench][timing]") {
    FakeClock fake;
    std::vector<int> order;
    auto job = [&](int id) {
        return [&, id](long count) {
            order.push_back(id);
            fake.now += static_cast<double>(count) * 0.025;
        };
    };
    TimingPolicy policy = policy_on(fake, 2);
    long last_done = 0, last_total = 0;
    policy.progress = [&](long done, long total) { last_done = done, last_total = total; };
    time_side_by_side({job(0), job(1), job(2)}, policy);
    CHECK(order == std::vector<int>{0, 1, 2, 0, 1, 2, 2, 1, 0});
    CHECK(last_done == 9);
    CHECK(last_total == 9);
}

TEST_CASE("median_of", "[bench][timing]") {
    CHECK(median_of({}) == 0);
    CHECK(median_of({3, 1, 2}) == 2);
    CHECK(median_of({4, 1, 3, 2}) == 2.5);
}
