#include "render/skipping.hpp"

#include <atomic>

namespace promyk {

namespace {
std::atomic<bool> skipping{true};
}

bool background_skipping() { return skipping.load(std::memory_order_relaxed); }
void set_background_skipping(bool on) { skipping.store(on, std::memory_order_relaxed); }

}  // namespace promyk
