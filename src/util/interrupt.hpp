// SIGINT and SIGTERM ask long work to stop cleanly: the handler only records
// the signal; loops poll it between rows and throw Interrupted, so that
// unwinding removes temporary files and main exits with 128 + signal.
#pragma once

namespace promyk {

void install_interrupt_handlers();

// The signal received (SIGINT or SIGTERM), or 0.
int interrupt_signal() noexcept;

// Throws Interrupted if a signal was received.
void throw_if_interrupted();

}  // namespace promyk
