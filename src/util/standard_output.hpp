// Standard output carries the product (a trace, a table, a scene): every byte
// of it goes through here, so that no failed write is lost. stdio keeps a
// write error only as a flag, and fputs of a long string writes past the
// buffer directly: an unchecked write that fails leaves nothing for the final
// fflush to see, and a full disk or a closed standard output ended in exit 0.
#pragma once

#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace promyk {

// Writes the bytes to standard output. BrokenPipe if its reader quit (EPIPE),
// OutputError "cannot write standard output: <reason>" for any other failure
// (a full disk, a closed descriptor), this one or an earlier one.
void write_standard_output(std::string_view bytes);

// fmt::print to standard output, checked.
template <typename... Args>
void print_standard_output(fmt::format_string<Args...> format, Args&&... args) {
    write_standard_output(fmt::format(format, std::forward<Args>(args)...));
}

// Flushes standard output and checks its error flag; the same errors. main
// calls it before exit 0; step-by-step output calls it after each step.
void flush_standard_output();

// If descriptor 0, 1 or 2 is closed, fills it with /dev/null opened the
// wrong way round (1 and 2 read-only, 0 write-only): a file promyk opens
// later cannot take the number and receive the product, and a write to a
// closed standard output still fails (EBADF) rather than vanishing.
void reserve_standard_descriptors() noexcept;

}  // namespace promyk
