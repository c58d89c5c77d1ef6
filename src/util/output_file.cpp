// Outputs: inspected before anything is computed, written atomically when
// they are regular files, directly when they are devices, FIFOs or `-`.
#include "util/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <memory>
#include <system_error>

#include <fmt/format.h>

#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/held_signals.hpp"
#include "util/interrupt.hpp"
#include "util/system_error_text.hpp"

namespace promyk {
namespace {

std::string directory_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string base_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string real_path(const std::string& path, const std::string& name) {
    char* resolved = ::realpath(path.c_str(), nullptr);
    if (resolved == nullptr) throw_cannot_write(name, errno);
    std::string result(resolved);
    std::free(resolved);
    return result;
}

// The file a path that does not exist yet will become: a dangling symbolic
// link is followed to where it points (as open(O_CREAT) would), and the
// directory is resolved, so that x, ./x and a/../x come out the same.
std::string final_path_of_new_file(const std::string& path) {
    std::string current = path;
    for (int hops = 0;; ++hops) {
        struct stat link {};
        if (::lstat(current.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) break;
        if (hops == 40) throw_cannot_write(path, ELOOP);
        std::string target(PATH_MAX, '\0');
        const ssize_t size = ::readlink(current.c_str(), target.data(), target.size());
        if (size < 0) throw_cannot_write(path, errno);
        target.resize(static_cast<std::size_t>(size));
        current = !target.empty() && target[0] == '/' ? target : directory_of(current) + "/" + target;
    }
    const std::string base = base_of(current);
    if (base.empty() || base == "." || base == "..") throw_cannot_write(path, EISDIR);
    const std::string directory = real_path(directory_of(current), path);
    return directory == "/" ? "/" + base : directory + "/" + base;
}

// A device, socket or FIFO, opened for writing. A FIFO with no reader:
// open(O_NONBLOCK) fails with ENXIO, and nothing tells when a reader comes,
// so it is tried again every 20 ms, paused by HeldSignals
// (util/held_signals.hpp): a signal at any moment ends the wait (a blocking
// open() would miss one that came just before it and wait for ever). Once
// open, its writes block again. -1 and errno on failure.
int open_stream(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0 && !S_ISFIFO(info.st_mode))
        return ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    const HeldSignals held;
    for (;;) {
        throw_if_interrupted();
        const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
        if (fd >= 0) {
            const int flags = ::fcntl(fd, F_GETFL);
            if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
                const int error = errno;
                ::close(fd);
                errno = error;
                return -1;
            }
            return fd;
        }
        if (errno == ENXIO)
            held.pause(20);  // no reader yet
        else if (errno != EINTR)
            return -1;
    }
}

}  // namespace

std::string OutputTarget::display_name() const { return kind == OutputKind::standard_output ? ui_message("output_standard_output") : path; }

OutputTarget inspect_output(const std::string& path) {
    OutputTarget target;
    target.path = path;
    struct stat info {};
    if (path == "-") {
        target.kind = OutputKind::standard_output;
        if (::fstat(STDOUT_FILENO, &info) != 0) throw_cannot_write(target.display_name(), errno);
    } else if (path.empty()) {
        throw_cannot_write("''", ENOENT);
    } else if (::stat(path.c_str(), &info) != 0) {
        if (errno != ENOENT) throw_cannot_write(path, errno);
        target.kind = OutputKind::file;
        target.final_path = final_path_of_new_file(path);
        target.lands_in_regular_file = true;
        return target;
    } else if (S_ISDIR(info.st_mode)) {
        throw_cannot_write(path, EISDIR);
    } else if (S_ISREG(info.st_mode)) {
        target.kind = OutputKind::file;
        target.final_path = real_path(path, path);
    } else {
        target.kind = OutputKind::stream;  // device, FIFO, socket (open will say)
    }
    target.exists = true;
    target.device = info.st_dev;
    target.inode = info.st_ino;
    target.lands_in_regular_file = S_ISREG(info.st_mode);
    return target;
}

bool same_destination(const OutputTarget& a, const OutputTarget& b) {
    if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
    if (a.exists || b.exists) return false;
    return a.final_path == b.final_path;
}

void require_distinct_outputs(const std::vector<std::pair<std::string, OutputTarget>>& outputs) {
    for (std::size_t a = 0; a < outputs.size(); ++a) {
        for (std::size_t b = a + 1; b < outputs.size(); ++b) {
            if (!same_destination(outputs[a].second, outputs[b].second)) continue;
            const OutputTarget& first = outputs[a].second;
            const OutputTarget& second = outputs[b].second;
            const std::string names = first.path == second.path
                                          ? first.display_name()
                                          : ui_message("output_two_names", {{"a", first.display_name()},
                                                                            {"b", second.display_name()}});
            throw UsageError(ui_message("output_same_file",
                                        {{"a", outputs[a].first}, {"b", outputs[b].first}, {"names", names}}));
        }
    }
}

void require_outputs_not_inputs(const std::vector<std::pair<std::string, OutputTarget>>& outputs,
                                const std::vector<std::pair<std::string, std::string>>& inputs) {
    for (const auto& [input_option, input_path] : inputs) {
        if (input_path.empty()) continue;  // not given: a built-in one
        struct stat info {};
        const int read = input_path == "-" ? ::fstat(STDIN_FILENO, &info) : ::stat(input_path.c_str(), &info);
        if (read != 0 || !S_ISREG(info.st_mode)) continue;
        for (const auto& [output_option, target] : outputs) {
            if (!target.exists || target.device != info.st_dev || target.inode != info.st_ino) continue;
            const std::string input_name = input_path == "-" ? ui_message("input_standard_input") : input_path;
            const std::string names = target.path == input_path
                                          ? input_name
                                          : ui_message("output_two_names", {{"a", target.display_name()}, {"b", input_name}});
            throw UsageError(ui_message("output_is_input", {{"output", output_option}, {"input", input_option}, {"names", names}}));
        }
    }
}

void throw_write_error(const std::string& display_name, int err) {
    if (err == EPIPE) throw BrokenPipe(display_name);
    throw_cannot_write(display_name, err);
}

OutputFile::OutputFile(const std::string& path) : OutputFile(inspect_output(path)) {}

OutputFile::OutputFile(OutputTarget target) : target_(std::move(target)) {
    int fd = -1;
    switch (target_.kind) {
        case OutputKind::file:
            // The temporary goes beside the resolved file; errors name the
            // path the user typed.
            atomic_.emplace(target_.final_path, target_.path);
            return;
        case OutputKind::standard_output:
            fd = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 0);
            break;
        case OutputKind::stream:
            // No O_CREAT, no O_TRUNC: the device or FIFO exists and is written
            // as it is. A FIFO waits here until a reader opens it.
            fd = open_stream(target_.path);
            break;
    }
    if (fd < 0) throw_cannot_write(display_name(), errno);
    std::FILE* stream = ::fdopen(fd, "wb");
    if (stream == nullptr) {
        const int err = errno;
        ::close(fd);
        throw_cannot_write(display_name(), err);
    }
    direct_.reset(stream);
}

std::FILE* OutputFile::stream() const {
    std::FILE* stream = atomic_ ? atomic_->stream() : direct_.get();
    if (stream == nullptr) throw std::logic_error("OutputFile used after finish()");
    return stream;
}

void OutputFile::write(std::string_view bytes) {
    stream();  // std::logic_error after finish()
    if (const int err = write_noexcept(bytes.data(), bytes.size())) throw_write_error(display_name(), err);
}

int OutputFile::write_noexcept(const void* data, std::size_t size) noexcept {
    std::FILE* stream = atomic_ ? atomic_->stream() : direct_.get();
    if (stream == nullptr) return EBADF;
    if (size == 0) return 0;
    errno = 0;
    const std::size_t written = std::fwrite(data, 1, size, stream);
    bytes_ += written;
    return written == size ? 0 : errno_or_eio();
}

void OutputFile::finish() {
    if (atomic_) {
        atomic_->finish();
        return;
    }
    std::FILE* stream = this->stream();
    errno = 0;
    if (std::fflush(stream) != 0 || std::ferror(stream)) throw_write_error(display_name(), errno_or_eio());
    errno = 0;
    const int closed = std::fclose(direct_.release());
    if (closed != 0) throw_write_error(display_name(), errno_or_eio());
}

void OutputFile::publish() {
    if (atomic_) atomic_->publish();
}

void OutputFile::commit() {
    finish();
    publish();
}

void commit_together(std::initializer_list<OutputFile*> files) {
    for (OutputFile* file : files) {
        if (file != nullptr) file->finish();
    }
    // Every file is complete on disk; only renames remain, which fail only if
    // the directory changed under us. Between two renames there is a tiny
    // window (a crash, SIGKILL, a power cut) in which the first file is new
    // and the second still old: POSIX has no rename of two files at once.
    for (OutputFile* file : files) {
        if (file != nullptr) file->publish();
    }
}

}  // namespace promyk
