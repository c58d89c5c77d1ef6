#include "util/standard_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/system_error_text.hpp"

namespace promyk {
namespace {

// EPIPE: BrokenPipe (exit 141, quietly); anything else: OutputError (exit 4).
[[noreturn]] void fail(int err) {
    if (err == 0) err = EIO;
    if (err == EPIPE) throw BrokenPipe("standard output");
    throw OutputError(ui_message("stdout_cannot_write", {{"reason", system_error_text(err)}}));
}

}  // namespace

void write_standard_output(std::string_view bytes) {
    // An earlier failure (set by a write that did not come through here)
    // is reported too: stdio would silently drop what follows.
    if (std::ferror(stdout)) fail(EIO);
    if (bytes.empty()) return;
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::ferror(stdout)) fail(errno);
}

void flush_standard_output() {
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) fail(errno);
}

void reserve_standard_descriptors() noexcept {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        const int opened = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
        if (opened >= 0 && opened != fd) {
            ::dup2(opened, fd);
            ::close(opened);
        }
    }
}

}  // namespace promyk
