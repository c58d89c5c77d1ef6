#include "util/read_input.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

#include "util/held_signals.hpp"
#include "util/interrupt.hpp"

namespace promyk {

namespace {

// Closes a file descriptor when it goes out of scope (also on Interrupted).
struct Descriptor {
    int fd;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() { ::close(fd); }
};

// Reads fd to its end, waiting (for data, or a FIFO's writer) only in
// HeldSignals. Linux reports no end on a FIFO before a writer has come and
// gone (pipe_poll), so a FIFO opened without blocking is waited for as a
// blocking open() would, but interruptibly.
WholeFile read_to_end(int fd, std::size_t max_bytes, const HeldSignals& held) {
    WholeFile file;
    char buffer[1 << 16];
    for (;;) {
        held.wait_readable(fd);
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got == 0) return file;
        if (got < 0) {
            const int error = errno;
            if (error == EINTR || error == EAGAIN || error == EWOULDBLOCK) continue;  // waits again
            file.failure = WholeFile::Failure::cannot_read;
            file.error = error;
            return file;
        }
        file.bytes.append(buffer, static_cast<std::size_t>(got));
        if (file.bytes.size() > max_bytes) {
            file.failure = WholeFile::Failure::too_large;
            return file;
        }
    }
}

}  // namespace

WholeFile read_whole_file(const std::string& path, std::size_t max_bytes) {
    const HeldSignals held;
    int fd = -1;
    for (;;) {
        throw_if_interrupted();
        // Without blocking: a FIFO with no writer yet opens at once.
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd >= 0) break;
        if (errno == EINTR) continue;
        WholeFile failed;
        failed.failure = WholeFile::Failure::cannot_open;
        failed.error = errno;
        return failed;
    }
    const Descriptor opened{fd};
    return read_to_end(opened.fd, max_bytes, held);
}

WholeFile read_whole_standard_input(std::size_t max_bytes) {
    const HeldSignals held;
    return read_to_end(STDIN_FILENO, max_bytes, held);
}

std::optional<std::string> read_standard_input_line() {
    const HeldSignals held;
    std::string line;
    for (;;) {
        held.wait_readable(STDIN_FILENO);
        char byte = 0;
        const ssize_t got = ::read(STDIN_FILENO, &byte, 1);
        if (got < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;  // waits again
        if (got <= 0) return line.empty() ? std::nullopt : std::optional<std::string>(line);
        if (byte == '\n') return line;
        if (line.size() < max_input_line_bytes) line += byte;  // the rest of a longer line is read and dropped
    }
}

}  // namespace promyk
