#include "bench/cpu_pinning.hpp"

#include <sched.h>

namespace promyk::bench {

namespace {

void set_cpus(const std::vector<int>& cpus) {
    cpu_set_t set;
    CPU_ZERO(&set);
    for (const int cpu : cpus) CPU_SET(cpu, &set);
    sched_setaffinity(0, sizeof set, &set);  // 0: the calling thread; failure only loses the pinning
}

}  // namespace

std::vector<int> allowed_cpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    std::vector<int> cpus;
    if (sched_getaffinity(0, sizeof set, &set) != 0) return cpus;
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
        if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
    return cpus;
}

PinnedToCpu::PinnedToCpu(int cpu) : previous_(allowed_cpus()) { set_cpus({cpu}); }

PinnedToCpu::~PinnedToCpu() {
    if (!previous_.empty()) set_cpus(previous_);
}

}  // namespace promyk::bench
