#pragma once
// Prose checked whatever its wrapping: the lesson and trace tests compare
// sentences, and the 80-column wrapper may break them anywhere.

#include <string>

// The text with every run of spaces and line ends made one space.
inline std::string flat(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const bool space = c == ' ' || c == '\n';
        if (space && !out.empty() && out.back() == ' ') continue;
        out += space ? ' ' : c;
    }
    return out;
}
