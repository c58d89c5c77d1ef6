// Prose broken into lines that fit the terminal: 80 columns, the width every
// text output keeps (a projector, a narrow terminal).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "util/text.hpp"

namespace promyk {

inline constexpr std::size_t text_columns = 80;

// The widest bracketed group that is kept on one line: a pixel "(3, 4)", a
// point "(0,1323; 0,1323; 2,116)". A longer group breaks like prose.
inline constexpr std::size_t group_columns = 40;

// Operators that never start a wrapped line: the product dot of the
// article's formulas (and ×, ⊙ of the pane's size and of colours).
inline bool is_glued_operator(std::string_view word) { return word == "·" || word == "×" || word == "⊙"; }

// `text` with each of its lines broken at spaces so that none is wider than
// `columns` (display width); continuation lines start with `indent` spaces;
// `first_used` columns of the first line are taken already (a lead printed
// before it). A word longer than a line stays whole; so does a bracketed
// group of at most group_columns, moved whole to the next line when it does
// not fit (a longer one is not: a line never ends early before it). A lone
// "·", "×" or "⊙" stays at the end of the line before. A line's
// own leading spaces are kept (an indented example). No trailing newline.
inline std::string wrap_text(std::string_view text, std::size_t indent = 0, std::size_t columns = text_columns,
                             std::size_t first_used = 0) {
    // How many brackets a piece leaves open.
    const auto open = [](std::string_view piece) {
        long depth = 0;
        for (const char c : piece) depth += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
        return depth;
    };
    std::string out;
    std::size_t line_start = 0;
    std::size_t width = first_used;
    while (line_start <= text.size()) {
        const std::size_t line_end = std::min(text.find('\n', line_start), text.size());
        const std::string_view line = text.substr(line_start, line_end - line_start);
        std::size_t k = 0;
        bool first_word = true;
        while (k < line.size()) {
            std::size_t word_end = line.find(' ', first_word ? line.find_first_not_of(' ', k) : k);
            if (word_end == std::string_view::npos) word_end = line.size();
            // A word that opens a group: the group is one unit when it is
            // short; else the word stands alone.
            if (open(line.substr(k, word_end - k)) > 0) {
                std::size_t group_end = word_end;
                while (group_end < line.size() && open(line.substr(k, group_end - k)) > 0) {
                    const std::size_t next = line.find(' ', group_end + 1);
                    group_end = next == std::string_view::npos ? line.size() : next;
                }
                if (open(line.substr(k, group_end - k)) <= 0 &&
                    display_width(line.substr(k, group_end - k)) <= group_columns)
                    word_end = group_end;
            }
            // An operator standing alone ("RV⁴ · RV¹⁶") stays with the word
            // before it, so that no line starts with it: the break goes after it.
            while (word_end < line.size()) {
                std::size_t after = word_end + 1;
                while (after < line.size() && line[after] != ' ') ++after;
                if (!is_glued_operator(line.substr(word_end + 1, after - word_end - 1))) break;
                word_end = after;
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
        width = 0;
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
