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
            // A short group in brackets, a pixel "(3, 4)", is never broken.
            const auto open = [](std::string_view w) {
                long depth = 0;
                for (const char c : w) depth += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
                return depth;
            };
            while (word_end < line.size() && open(line.substr(k, word_end - k)) > 0) {
                std::size_t next = line.find(' ', word_end + 1);
                if (next == std::string_view::npos) next = line.size();
                if (display_width(line.substr(k, next - k)) > 24) break;
                word_end = next;
            }
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

// Every line of `text` that is wider than `columns` wrapped at spaces, its
// continuation lines indented by 4 (or 2 more than a line indented deeper),
// so they stand apart from the report's own indented lines (diff's, the
// answer check's).
inline std::string wrap_lines(std::string_view text, std::size_t columns = text_columns) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        const bool last = end == std::string_view::npos;
        if (last) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        if (display_width(line) <= columns) {
            out += line;
        } else {
            const std::size_t indent = std::min<std::size_t>(line.find_first_not_of(' ') == std::string_view::npos
                                                                  ? 0
                                                                  : line.find_first_not_of(' '),
                                                              20);
            out += wrap_text(line, indent < 4 ? 4 : indent + 2, columns);
        }
        if (!last) out += '\n';
        start = end + 1;
    }
    return out;
}

}  // namespace promyk
