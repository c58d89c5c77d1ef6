// Reading promyk's inputs (a file, standard input, a line typed in class)
// without losing an interrupt: a FIFO with no writer yet, a pipe or a
// terminal may keep promyk waiting, and every such wait is HeldSignals'
// (util/held_signals.hpp), so a signal at any moment, even just before a
// wait, ends it with Interrupted. One reader for scenes, lessons, answers,
// traces, bench files and lesson --step's Enter.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace promyk {

struct WholeFile {
    enum class Failure { none, cannot_open, cannot_read, too_large };
    std::string bytes;                // everything read (up to the limit and one piece past it)
    Failure failure = Failure::none;  // why reading stopped before the end, if it did
    int error = 0;                    // errno for cannot_open and cannot_read
};

// The file at `path` until its end (read() returning 0, not a short read:
// a FIFO gives its bytes in pieces). More than max_bytes is too_large, found
// as the bytes come, so an endless device ends. Throws Interrupted only.
WholeFile read_whole_file(const std::string& path, std::size_t max_bytes);
// Standard input, the same way.
WholeFile read_whole_standard_input(std::size_t max_bytes);

// One line of standard input, without its '\n', and only its first
// max_input_line_bytes (memory stays bounded whatever comes: lesson --step
// wants "q" or "b"); nothing at its end (or on an error: a closed input
// just goes on). Reads a byte at a time, so what follows the line stays
// unread. Throws Interrupted only.
inline constexpr std::size_t max_input_line_bytes = 4096;
std::optional<std::string> read_standard_input_line();

}  // namespace promyk
