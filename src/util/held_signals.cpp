#include "util/held_signals.hpp"

#include <poll.h>

#include <cerrno>
#include <ctime>
#include <system_error>

#include "util/interrupt.hpp"

namespace promyk {

namespace {

#ifdef __EMSCRIPTEN__
// The page's build: no signals and no FIFOs to wait on; a wait is a poll.
int wait(pollfd* file, int count, const timespec* limit, const sigset_t*) {
    return ::poll(file, static_cast<nfds_t>(count),
                  limit ? static_cast<int>(limit->tv_sec * 1000 + limit->tv_nsec / 1000000) : -1);
}
#else
int wait(pollfd* file, int count, const timespec* limit, const sigset_t* mask) {
    return ::ppoll(file, static_cast<nfds_t>(count), limit, mask);
}
#endif

void fail_unless_interrupted(int error) {
    if (error == EINTR) return;  // a signal: the flag says whose
    throw std::system_error(error, std::generic_category(), "ppoll");
}

}  // namespace

HeldSignals::HeldSignals() {
    sigset_t held;
    sigemptyset(&held);
    for (const int signal_number : interrupt_signals) sigaddset(&held, signal_number);
    pthread_sigmask(SIG_BLOCK, &held, &found_);
    // Inside a wait the three are open even where the caller had blocked
    // them (a test makes a signal pending that way).
    waiting_ = found_;
    for (const int signal_number : interrupt_signals) sigdelset(&waiting_, signal_number);
}

HeldSignals::~HeldSignals() { pthread_sigmask(SIG_SETMASK, &found_, nullptr); }

void HeldSignals::wait_readable(int fd) const {
    pollfd file{fd, POLLIN, 0};
    if (wait(&file, 1, nullptr, &waiting_) < 0) fail_unless_interrupted(errno);
    throw_if_interrupted();
}

void HeldSignals::pause(int milliseconds) const {
    const timespec limit{milliseconds / 1000, (milliseconds % 1000) * 1000000L};
    if (wait(nullptr, 0, &limit, &waiting_) < 0) fail_unless_interrupted(errno);
    throw_if_interrupted();
}

}  // namespace promyk
