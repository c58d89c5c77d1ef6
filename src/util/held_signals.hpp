// Waiting on a file (a FIFO with no writer yet, or no reader) without losing
// an interrupt. Checking the flag, then calling open() or read() leaves a
// window: a signal between the two only sets the flag, and the call then
// waits for a peer that may never come. While a HeldSignals lives, SIGINT,
// SIGTERM and SIGHUP stay pending (blocked) everywhere but inside its waits,
// which ppoll() makes: it unblocks them and waits in one step, so a signal
// that came earlier is delivered there and ends the wait.
#pragma once

#include <csignal>

namespace promyk {

class HeldSignals {
public:
    HeldSignals();   // blocks the three in this thread
    ~HeldSignals();  // restores the mask it found
    HeldSignals(const HeldSignals&) = delete;
    HeldSignals& operator=(const HeldSignals&) = delete;

    // Until fd can be read (data, or its writer gone): throws Interrupted
    // (util/errors.hpp) on promyk's interrupt; any other signal ends the
    // wait early, harmlessly (the caller tries again).
    void wait_readable(int fd) const;
    // Up to `milliseconds`, or less on a signal; throws Interrupted as above.
    void pause(int milliseconds) const;

private:
    sigset_t found_{}, waiting_{};  // the mask found; the mask inside the waits
};

}  // namespace promyk
