// Pinning the calling thread to one core, so single-thread timings can be
// taken on every core in turn: on virtual machines cores often differ in
// speed, and a single-thread figure depends on the core it ran on.
#pragma once

#include <vector>

namespace promyk::bench {

// The cores this process may run on.
std::vector<int> allowed_cpus();

// Pins the calling thread to `cpu` while alive; restores the previous set
// (threads started later inherit the calling thread's set).
class PinnedToCpu {
public:
    explicit PinnedToCpu(int cpu);
    ~PinnedToCpu();
    PinnedToCpu(const PinnedToCpu&) = delete;
    PinnedToCpu& operator=(const PinnedToCpu&) = delete;

private:
    std::vector<int> previous_;
};

}  // namespace promyk::bench
