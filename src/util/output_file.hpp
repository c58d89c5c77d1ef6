// Where a command's output goes, and how it gets there (PRODUCT.md §3):
//
//   - a regular file, or a path that does not exist yet, is written
//     completely or not at all: a temporary beside the final file, renamed
//     onto it when everything went well. A symbolic link is followed first,
//     so the link stays a link and its target gets the new content;
//   - a device (/dev/null, a terminal), a FIFO, or `-` (standard output) is
//     written directly as the bytes are produced: it cannot be replaced, and
//     replacing /dev/null with a regular file (as root) would be a disaster;
//   - a directory is refused (OutputError) before anything is computed.
//
// A command inspects every output first (inspect_output, nothing created),
// refuses two outputs that are the same file (require_distinct_outputs),
// then opens them all before computing, and commits them together
// (commit_together) so that a failure leaves none of the new files.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/atomic_file.hpp"

namespace promyk {

enum class OutputKind {
    standard_output,  // "-": written directly to file descriptor 1
    file,             // a regular file or a new one: temporary, then rename
    stream,           // a device or a FIFO: opened and written directly
};

struct OutputTarget {
    std::string path;  // as given ("-" for standard output)
    OutputKind kind = OutputKind::file;
    // For OutputKind::file: the file the rename will replace, with every
    // symbolic link (the path's and its directories') resolved.
    std::string final_path;
    // Identity, when the destination exists (for `-`, what fd 1 is).
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    // The bytes end up in a regular file: a new or existing file, or
    // standard output redirected to one (for size guards: disks fill up).
    bool lands_in_regular_file = false;

    // "standard output" for `-`, else the path as given.
    std::string display_name() const;
};

// Looks at `path` without creating anything. OutputError (naming the path
// and the errno text) for a directory, a missing directory, a loop of
// symbolic links, a closed standard output.
OutputTarget inspect_output(const std::string& path);

// True if both name one file: the same inode (hard links, symbolic links,
// /proc/self/fd/1 and `-`), or the same resolved path for files that do not
// exist yet (x, ./x, a/../x, a dangling link to x).
bool same_destination(const OutputTarget& a, const OutputTarget& b);

// UsageError if two of the outputs are one file, naming both options:
// "--traces and -o name the same file (x.png)". Each entry is (option, target).
void require_distinct_outputs(const std::vector<std::pair<std::string, OutputTarget>>& outputs);

// UsageError if an output is one of the inputs, so that writing it would
// replace what is being read ("-o and --scene name the same file (s.json):
// the output would replace the input"). Inputs are (option, path), "-" for
// standard input; only an existing regular file can be replaced, and it is
// compared by identity (device and inode), so links and other paths count.
// Inputs that do not exist are left for their reader to report.
void require_outputs_not_inputs(const std::vector<std::pair<std::string, OutputTarget>>& outputs,
                                const std::vector<std::pair<std::string, std::string>>& inputs);

// The error a failed write deserves: BrokenPipe for EPIPE (the reader
// quit), else OutputError "cannot write PATH: <errno text>".
[[noreturn]] void throw_write_error(const std::string& display_name, int err);

class OutputFile {
public:
    // inspect_output(path), then open.
    explicit OutputFile(const std::string& path);
    // Opens the target: creates the temporary, or opens the device, FIFO or
    // standard output (a FIFO waits here for a reader). OutputError if that
    // fails. A directory was refused by inspect_output already.
    explicit OutputFile(OutputTarget target);
    // Removes the temporary unless committed. Output already sent to a
    // device, FIFO or standard output cannot be taken back.
    ~OutputFile() = default;

    OutputFile(OutputFile&&) noexcept = default;
    OutputFile& operator=(OutputFile&&) noexcept = default;

    // Appends bytes; OutputError, or BrokenPipe for EPIPE.
    void write(std::string_view bytes);
    // The same without exceptions, for C callbacks (libpng): 0 or the errno.
    int write_noexcept(const void* data, std::size_t size) noexcept;

    // Flushes; for a regular file also syncs and closes the temporary.
    // Errors as for write().
    void finish();
    // Renames a finished temporary onto the final file (nothing for direct
    // outputs). OutputError if the rename fails.
    void publish();
    // finish(), then publish().
    void commit();

    const OutputTarget& target() const noexcept { return target_; }
    const std::string& path() const noexcept { return target_.path; }
    std::string display_name() const { return target_.display_name(); }
    bool atomic() const noexcept { return target_.kind == OutputKind::file; }
    std::uint64_t bytes_written() const noexcept { return bytes_; }

private:
    std::FILE* stream() const;

    OutputTarget target_;
    std::optional<AtomicFile> atomic_;  // OutputKind::file
    struct Closer {
        void operator()(std::FILE* f) const noexcept { std::fclose(f); }
    };
    std::unique_ptr<std::FILE, Closer> direct_;  // device, FIFO, or a dup of fd 1
    std::uint64_t bytes_ = 0;
};

// Commits the files as one: finishes every one of them (flush, sync, close:
// where a full disk shows) and only then renames them. A failure before the
// renames leaves none of the new files; the destructors remove the
// temporaries. Null pointers are skipped.
void commit_together(std::initializer_list<OutputFile*> files);

}  // namespace promyk
