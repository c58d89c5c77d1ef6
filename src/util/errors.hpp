// The error kinds promyk reports, each mapped to its exit code in src/app.
// The core library throws them; only the application prints and exits.
#pragma once

#include <stdexcept>
#include <string>

namespace promyk {

// Bad command-line value (exit 2): a pixel outside the pane, w out of range.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Bad input file (exit 3). `where` is the file and, when known, the JSON
// pointer or line:column of the fault; the message says what is wrong.
struct InputError : std::runtime_error {
    InputError(std::string file_name, std::string location, const std::string& what)
        : std::runtime_error(what), file(std::move(file_name)), where(std::move(location)) {}
    std::string file;
    std::string where;
};

// An output file could not be written (exit 4).
struct OutputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The reader of standard output (or of a FIFO) went away: a write failed
// with EPIPE. Not an OutputError: main exits quietly with 141, as a process
// that SIGPIPE ended would (SIGPIPE itself is ignored so that unwinding can
// remove temporary files).
struct BrokenPipe : std::runtime_error {
    explicit BrokenPipe(const std::string& path) : std::runtime_error("broken pipe writing " + path) {}
};

// The user interrupted the work (SIGINT, SIGTERM, SIGHUP): exit 128 + signal.
struct Interrupted : std::runtime_error {
    explicit Interrupted(int signal) : std::runtime_error("interrupted"), signal_number(signal) {}
    int signal_number;
};

}  // namespace promyk
