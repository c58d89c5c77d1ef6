#pragma once
// Tests of promyk's interrupt run in a child process each: once a signal
// has set the flag it stays set (util/interrupt.hpp), and the next test
// must not find it.

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <functional>

#include "util/errors.hpp"

namespace promyk::testing {

// Runs `body` in a child (fork) and returns waitpid's status; body's
// result is the child's exit code (it must not throw).
inline int child_status(const std::function<int()>& body) {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) _exit(body());
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    return status;
}

// An exit code for a child whose `work` should end with Interrupted by
// `signal`: 0 when it did, 101 when work returned, 102 for another
// signal, 103 for another exception.
inline int interrupted_code(int signal, const std::function<void()>& work) {
    try {
        work();
        return 101;
    } catch (const Interrupted& interrupted) {
        return interrupted.signal_number == signal ? 0 : 102;
    } catch (...) {
        return 103;
    }
}

}  // namespace promyk::testing
