// What every fuzz target shares: the input as text, the run's language from
// the input's length (so every seed is read in both languages as it mutates),
// and a property failure that libFuzzer reports as a crash with its input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "trace/messages.hpp"

namespace promyk::fuzz {

inline std::string_view bytes_of(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

inline Language language_of(std::size_t size) { return size % 2 == 0 ? Language::en : Language::pl; }

// A property the parser promises does not hold: abort, so libFuzzer keeps the input.
[[noreturn]] inline void broken(const char* what) {
    std::fprintf(stderr, "fuzz property broken: %s\n", what);
    std::abort();
}

}  // namespace promyk::fuzz
