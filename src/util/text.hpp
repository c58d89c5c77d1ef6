// Small text helpers shared by the command line, the trace table and the
// lessons: one definition each.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace promyk {

// The text without the spaces, tabs and line ends around it.
inline std::string trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return "";
    const auto last = text.find_last_not_of(" \t\r\n");
    return std::string(text.substr(first, last - first + 1));
}

// Terminal columns taken by UTF-8 text: one per code point (promyk's texts
// use no wide or combining characters).
inline std::size_t display_width(std::string_view text) {
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The text and spaces after it, to `width` terminal columns (never cut).
inline std::string pad(const std::string& text, std::size_t width) {
    return text + std::string(width - std::min(width, display_width(text)), ' ');
}

// Items as a person lists them: "a, b, c".
inline std::string joined(const std::vector<std::string_view>& items) {
    std::string out;
    for (const std::string_view item : items) out += (out.empty() ? "" : ", ") + std::string(item);
    return out;
}

// -?(0|[1-9][0-9]*): what a person means by a whole number, and nothing a C
// library would read otherwise (strtol's base 0 takes 010 as eight).
inline bool is_plain_decimal(std::string_view text) {
    std::size_t k = !text.empty() && text[0] == '-' ? 1 : 0;
    if (k == text.size()) return false;
    if (text[k] == '0') return k + 1 == text.size();
    for (; k < text.size(); ++k)
        if (text[k] < '0' || text[k] > '9') return false;
    return true;
}

}  // namespace promyk
