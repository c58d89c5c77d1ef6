// SIGINT, SIGTERM and SIGHUP ask long work to stop cleanly: the handler only
// records the signal; loops poll it between rows and throw Interrupted, so
// that unwinding removes temporary files and main exits with 128 + signal.
// SIGPIPE is ignored: a write to a reader that quit fails with EPIPE, which
// becomes BrokenPipe (exit 141) after the same unwinding.
#pragma once

#include <csignal>

namespace promyk {

// Installed without SA_RESTART, so a blocking read or open (a FIFO with no
// writer) returns EINTR; main then reports the interruption, not the error.
void install_interrupt_handlers();

// The signals that ask promyk to stop (SIGHUP: the terminal closed during
// a long render): the handlers above, and util/held_signals.hpp's mask.
inline constexpr int interrupt_signals[] = {SIGINT, SIGTERM, SIGHUP};

// The signal received (SIGINT, SIGTERM or SIGHUP), or 0.
int interrupt_signal() noexcept;

// Throws Interrupted if a signal was received.
void throw_if_interrupted();

}  // namespace promyk
