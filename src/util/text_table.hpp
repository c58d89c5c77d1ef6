// A table of text for the terminal: columns as wide as their widest cell or
// heading (display width, so "× base" and "ł" count one column a character),
// headings of several lines aligned at the bottom. The bench's tables use it,
// so a translated heading never breaks the alignment.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "util/text.hpp"

namespace promyk {

struct TextColumn {
    std::string heading;  // lines separated by '\n'
    bool left = false;    // text to the left (names); numbers to the right
};

class TextTable {
public:
    explicit TextTable(std::vector<TextColumn> columns, std::size_t indent = 2, std::size_t gap = 2)
        : columns_(std::move(columns)), indent_(indent), gap_(gap) {}

    void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
    // An empty line between groups of rows.
    void add_break() { rows_.emplace_back(); }

    std::string text() const {
        std::vector<std::vector<std::string>> headings;
        std::size_t heading_lines = 0;
        std::vector<std::size_t> widths(columns_.size(), 0);
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            headings.push_back(lines_of(columns_[c].heading));
            heading_lines = std::max(heading_lines, headings.back().size());
            for (const std::string& line : headings.back()) widths[c] = std::max(widths[c], display_width(line));
        }
        for (const auto& row : rows_)
            for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c)
                widths[c] = std::max(widths[c], display_width(row[c]));
        std::string out;
        for (std::size_t line = 0; line < heading_lines; ++line) {
            std::vector<std::string> cells;
            for (const auto& heading : headings) {
                const std::size_t blank = heading_lines - heading.size();  // bottom-aligned
                cells.push_back(line < blank ? std::string() : heading[line - blank]);
            }
            out += line_of(cells, widths);
        }
        for (const auto& row : rows_) out += row.empty() ? "\n" : line_of(row, widths);
        return out;
    }

private:
    static std::vector<std::string> lines_of(const std::string& text) {
        std::vector<std::string> lines;
        std::size_t start = 0;
        for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
            lines.push_back(text.substr(start, end - start));
        lines.push_back(text.substr(start));
        return lines;
    }

    std::string line_of(const std::vector<std::string>& cells, const std::vector<std::size_t>& widths) const {
        std::string out(indent_, ' ');
        for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c) {
            const std::size_t pad = widths[c] - std::min(widths[c], display_width(cells[c]));
            if (c > 0) out.append(gap_, ' ');
            if (columns_[c].left) {
                out += cells[c];
                if (c + 1 < cells.size()) out.append(pad, ' ');
            } else {
                out.append(pad, ' ');
                out += cells[c];
            }
        }
        while (!out.empty() && out.back() == ' ') out.pop_back();
        return out + '\n';
    }

    std::vector<TextColumn> columns_;
    std::size_t indent_, gap_;
    std::vector<std::vector<std::string>> rows_;
};

}  // namespace promyk
