// Scene files: the entry points that read them (a file, or its bytes).

#include "scene/scene_json.hpp"

#include <cerrno>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "scene/scene_parse.hpp"
#include "scene/scene_validate.hpp"
#include "trace/messages.hpp"
#include "util/held_signals.hpp"
#include "util/interrupt.hpp"

namespace promyk {

namespace {

// Closes a file descriptor when it goes out of scope.
struct Descriptor {
    int fd;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() { ::close(fd); }
};

std::string errno_text(int error) { return std::error_code(error, std::generic_category()).message(); }

}  // namespace

// A FIFO, a pipe or a slow device may give the file in pieces: read until the
// end of the file (read() returning 0), not until a short read. Opened
// without blocking (a FIFO with no writer yet opens at once), then every
// wait is HeldSignals' (util/held_signals.hpp): a signal at any moment, even
// just before a wait, ends it. promyk's interrupt (SIGINT, SIGTERM, SIGHUP)
// throws Interrupted (exit 128 + signal); another signal is harmless and
// the call is made again.
Scene load_scene_file(const std::string& path) {
    const HeldSignals held;
    int fd = -1;
    for (;;) {
        throw_if_interrupted();
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd >= 0) break;
        const int error = errno;
        if (error == EINTR) continue;
        throw SceneFileError(path, ui_message("scene_cannot_open", {{"reason", errno_text(error)}}), error);
    }
    const Descriptor file{fd};
    std::string text;
    char buffer[1 << 16];
    for (;;) {
        // A FIFO reports no end before a writer has come and gone (Linux's
        // pipe_poll), so this waits for the writer as open() did.
        held.wait_readable(file.fd);
        const ssize_t got = ::read(file.fd, buffer, sizeof buffer);
        if (got == 0) break;
        if (got < 0) {
            const int error = errno;
            if (error == EINTR || error == EAGAIN || error == EWOULDBLOCK) continue;  // waits again
            throw SceneFileError(path, ui_message("scene_cannot_read", {{"reason", errno_text(error)}}), error);
        }
        text.append(buffer, static_cast<std::size_t>(got));
        if (text.size() > max_scene_file_bytes)
            scene_detail::reject(path, "",
                                 ui_message("scene_file_too_large", {{"limit", std::to_string(max_scene_file_bytes)}}));
    }
    return load_scene_text(text, path);
}

Scene load_scene_text(std::string_view bytes, const std::string& name) {
    return scene_detail::validate_scene(scene_detail::parse_json(bytes, name), name);
}

Scene parse_scene(std::string_view text, const std::string& source) { return load_scene_text(text, source); }

}  // namespace promyk
