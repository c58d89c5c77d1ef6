// A file that is written completely or not at all (PRODUCT.md §3): the bytes
// go to a temporary file beside the final one, and only commit() renames the
// finished file onto the final path. Until then an existing file keeps its
// old content, and a failure, an exception or an interruption (which unwinds)
// leaves neither a truncated file nor the temporary behind.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace promyk {

// The output error for a file that cannot be written: it names the file the
// user asked for (never a temporary) and the system's reason.
[[noreturn]] void throw_cannot_write(const std::string& file, int err);

class AtomicFile {
public:
    // Creates the temporary `.<basename>.promyk-XXXXXX` in the final path's
    // directory (same file system, so the rename is atomic). OutputError if
    // it cannot be created, e.g. the directory does not exist.
    // Errors name `name_in_errors` if given (the path the user typed, when
    // final_path is that path with its symbolic links resolved).
    explicit AtomicFile(std::string final_path, std::string name_in_errors = "");
    // Removes the temporary unless commit() succeeded.
    ~AtomicFile();

    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&& other) noexcept;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // The open temporary, for code that writes through stdio (libpng);
    // nullptr once committed. Errors on it are caught by commit().
    std::FILE* stream() const noexcept { return stream_; }

    // Appends bytes; OutputError on failure.
    void write(std::string_view bytes);

    // finish(), then publish().
    void commit();

    // Flushes, syncs and closes the temporary and gives it the mode a new
    // file would get (0666 & ~umask; mkstemp makes 0600). OutputError on any
    // failure; the temporary is then removed by the destructor. Split from
    // publish() so that several files can all be finished before any of
    // them is renamed.
    void finish();

    // Renames the finished temporary onto the final path. OutputError if
    // that fails; std::logic_error unless finish() succeeded first.
    void publish();

    const std::string& path() const noexcept { return final_path_; }
    // The temporary's path while it exists (empty after commit or a move).
    const std::string& temporary_path() const noexcept { return temp_path_; }

private:
    void require_open() const;
    void discard() noexcept;

    std::string final_path_;
    std::string name_;       // for error messages
    std::string temp_path_;  // non-empty while a temporary exists
    std::FILE* stream_ = nullptr;
    bool finished_ = false;  // closed by finish(), not yet renamed
};

}  // namespace promyk
