#include "util/interrupt.hpp"

#include <atomic>
#include <csignal>

#include "util/errors.hpp"

namespace promyk {

namespace {

std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");

extern "C" void on_signal(int signal_number) { received_signal.store(signal_number, std::memory_order_relaxed); }

}  // namespace

void install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (const int signal_number : interrupt_signals) sigaction(signal_number, &action, nullptr);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, nullptr);
}

int interrupt_signal() noexcept { return received_signal.load(std::memory_order_relaxed); }

void throw_if_interrupted() {
    if (const int s = interrupt_signal()) throw Interrupted(s);
}

}  // namespace promyk
