// Writing a file completely or not at all: temporary file, then rename.
#include "util/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/system_error_text.hpp"

namespace promyk {

void throw_cannot_write(const std::string& file, int err) {
    throw OutputError(ui_message("output_cannot_write", {{"file", file}, {"reason", system_error_text(err)}}));
}

namespace {

// The process's umask, read without changing it: umask(2) can only be read by
// setting it, which would race with files that other threads create.
mode_t current_umask() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.compare(0, 6, "Umask:") == 0) {
            char* end = nullptr;
            const unsigned long mask = std::strtoul(line.c_str() + 6, &end, 8);
            if (end != line.c_str() + 6) return static_cast<mode_t>(mask & 0777);
        }
    }
    const mode_t mask = ::umask(0);  // kernels before 4.7 lack the Umask line
    ::umask(mask);
    return mask;
}

// "dir/name.png" -> "dir/.name.png.promyk-XXXXXX": hidden, and recognisably
// ours should a crash (SIGKILL) ever leave one behind.
std::string temporary_template(const std::string& final_path) {
    const auto slash = final_path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : final_path.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? final_path : final_path.substr(slash + 1);
    base.resize(std::min<std::size_t>(base.size(), 200));  // stay under NAME_MAX (255)
    return dir + "." + base + ".promyk-XXXXXX";
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path, std::string name_in_errors)
    : final_path_(std::move(final_path)), name_(name_in_errors.empty() ? final_path_ : std::move(name_in_errors)) {
    if (final_path_.empty()) throw_cannot_write(name_, ENOENT);
    std::string name = temporary_template(final_path_);
    const int fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0) throw_cannot_write(name_, errno);
    std::FILE* stream = ::fdopen(fd, "wb");
    if (stream == nullptr) {
        const int err = errno;
        ::close(fd);
        ::unlink(name.c_str());
        throw_cannot_write(name_, err);
    }
    temp_path_ = std::move(name);
    stream_ = stream;
}

AtomicFile::~AtomicFile() { discard(); }

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : final_path_(std::move(other.final_path_)),
      name_(std::move(other.name_)),
      temp_path_(std::exchange(other.temp_path_, std::string())),
      stream_(std::exchange(other.stream_, nullptr)),
      finished_(std::exchange(other.finished_, false)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
    if (this != &other) {
        discard();
        final_path_ = std::move(other.final_path_);
        name_ = std::move(other.name_);
        temp_path_ = std::exchange(other.temp_path_, std::string());
        stream_ = std::exchange(other.stream_, nullptr);
        finished_ = std::exchange(other.finished_, false);
    }
    return *this;
}

void AtomicFile::write(std::string_view bytes) {
    require_open();
    if (bytes.empty()) return;
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), stream_) != bytes.size()) throw_cannot_write(name_, errno_or_eio());
}

void AtomicFile::commit() {
    finish();
    publish();
}

void AtomicFile::finish() {
    require_open();
    // A full disk often shows only here, when the last buffer is written;
    // ferror catches failures of writes made through stream() and unchecked.
    errno = 0;
    if (std::fflush(stream_) != 0 || std::ferror(stream_)) throw_cannot_write(name_, errno_or_eio());
    const int fd = ::fileno(stream_);
    if (::fchmod(fd, 0666 & ~current_umask()) != 0) throw_cannot_write(name_, errno);
    // The data must be on disk before the rename makes it the file: otherwise
    // a crash could leave the new name pointing at an empty file.
    if (::fsync(fd) != 0) throw_cannot_write(name_, errno);
    errno = 0;
    if (std::fclose(std::exchange(stream_, nullptr)) != 0) throw_cannot_write(name_, errno_or_eio());
    finished_ = true;
}

void AtomicFile::publish() {
    if (!finished_ || temp_path_.empty()) throw std::logic_error("AtomicFile published before finish()");
    if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0) throw_cannot_write(name_, errno);
    temp_path_.clear();
    finished_ = false;
}

void AtomicFile::require_open() const {
    if (stream_ == nullptr) throw std::logic_error("AtomicFile used after commit, a failed commit or a move");
}

void AtomicFile::discard() noexcept {
    if (stream_ != nullptr) std::fclose(std::exchange(stream_, nullptr));
    if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
    temp_path_.clear();
    finished_ = false;
}

}  // namespace promyk
