// Prose broken into lines that fit the terminal: 80 columns, the width every
// text output keeps (a projector, a narrow terminal).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "util/text.hpp"

namespace promyk {

inline constexpr std::size_t text_columns = 80;

// `text` with each of its lines broken at spaces so that none is wider than
// `columns` (display width); continuation lines start with `indent` spaces.
// A word longer than a line stays whole. No trailing newline is added.
inline std::string wrap_text(std::string_view text, std::size_t indent = 0, std::size_t columns = text_columns) {
    std::string out;
    std::size_t line_start = 0;
    while (line_start <= text.size()) {
        const std::size_t line_end = std::min(text.find('\n', line_start), text.size());
        const std::string_view line = text.substr(line_start, line_end - line_start);
        std::size_t width = 0, k = 0;
        bool first_word = true;
        while (k < line.size()) {
            // keep the line's own leading spaces (an indented example)
            std::size_t word_end = line.find(' ', first_word ? line.find_first_not_of(' ', k) : k);
            if (word_end == std::string_view::npos) word_end = line.size();
            const std::string_view word = line.substr(k, word_end - k);
            if (!first_word && width + 1 + display_width(word) > columns) {
                out += '\n' + std::string(indent, ' ');
                width = indent;
            } else if (!first_word) {
                out += ' ';
                ++width;
            }
            out += word;
            width += display_width(word);
            first_word = false;
            k = word_end + 1;
        }
        if (line_end >= text.size()) break;
        out += '\n';
        line_start = line_end + 1;
    }
    return out;
}

}  // namespace promyk
