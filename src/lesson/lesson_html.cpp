#include "lesson/lesson_html.hpp"

#include <cctype>
#include <vector>

namespace promyk {

std::string html_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string html_math(std::string_view tex) { return "<span class=\"math\">" + html_escape(tex) + "</span>"; }

namespace {

bool word_character(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The article's symbols in prose, a letter and a capital subscript standing
// alone (x_E, z_S, I_P): typeset as a subscript, as the article prints them.
// Longer names (t_hit) and parts of words stay as they are.
bool symbol_subscript(std::string_view text, std::size_t k) {
    return k + 2 < text.size() && std::isalpha(static_cast<unsigned char>(text[k])) && text[k + 1] == '_' &&
           std::isupper(static_cast<unsigned char>(text[k + 2])) && (k == 0 || !word_character(text[k - 1])) &&
           (k + 3 == text.size() || !word_character(text[k + 3]));
}

}  // namespace

std::string html_inline(std::string_view text) {
    std::string out;
    bool strong = false, em = false;
    std::size_t k = 0;
    // A marker opens only when its twin follows (or closes what is open).
    const auto closes_later = [&](std::string_view marker, std::size_t from) {
        return text.find(marker, from) != std::string_view::npos;
    };
    while (k < text.size()) {
        const char c = text[k];
        if (c == '`' || c == '$') {
            const std::size_t end = text.find(c, k + 1);
            if (end != std::string_view::npos && end > k + 1) {
                const std::string_view inside = text.substr(k + 1, end - k - 1);
                out += c == '`' ? "<code>" + html_escape(inside) + "</code>" : html_math(inside);
                k = end + 1;
                continue;
            }
        } else if (text.compare(k, 2, "**") == 0 && (strong || closes_later("**", k + 2))) {
            out += strong ? "</strong>" : "<strong>";
            strong = !strong;
            k += 2;
            continue;
        } else if (c == '*' && text.compare(k, 2, "**") != 0 &&
                   (em || (k + 1 < text.size() && text[k + 1] != ' ' && closes_later("*", k + 1)))) {
            out += em ? "</em>" : "<em>";
            em = !em;
            ++k;
            continue;
        }
        if (symbol_subscript(text, k)) {  // x_E: x<sub>E</sub>
            out += text[k];
            out += "<sub>";
            out += text[k + 2];
            out += "</sub>";
            k += 3;
            continue;
        }
        out += html_escape(text.substr(k, 1));
        ++k;
    }
    // What is open at the line's end closes with it: the output stays well formed.
    if (em) out += "</em>";
    if (strong) out += "</strong>";
    return out;
}

namespace {

std::size_t list_marker(std::string_view line, bool& ordered) {
    ordered = false;
    if (line.rfind("- ", 0) == 0 || line.rfind("* ", 0) == 0) return 2;
    std::size_t k = 0;
    while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k]))) ++k;
    ordered = true;
    return k > 0 && line.compare(k, 2, ". ") == 0 ? k + 2 : 0;
}

bool table_row(std::string_view line) { return line.size() > 1 && line.front() == '|' && line.back() == '|'; }

std::vector<std::string_view> cells_of(std::string_view row) {
    std::vector<std::string_view> cells;
    row = row.substr(1, row.size() - 2);
    std::size_t start = 0;
    while (true) {
        const std::size_t bar = row.find('|', start);
        std::string_view cell = row.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start);
        while (!cell.empty() && cell.front() == ' ') cell.remove_prefix(1);
        while (!cell.empty() && cell.back() == ' ') cell.remove_suffix(1);
        cells.push_back(cell);
        if (bar == std::string_view::npos) break;
        start = bar + 1;
    }
    return cells;
}

bool separator_row(std::string_view row) {
    for (const char c : row)
        if (c != '|' && c != '-' && c != ':' && c != ' ') return false;
    return true;
}

}  // namespace

std::string html_prose(std::string_view text) {
    std::string out, paragraph;
    std::string list;  // "ul", "ol" or empty
    std::string item;  // the open list item's text
    std::vector<std::string_view> table, code;
    bool fenced = false;
    const auto flush_paragraph = [&] {
        if (!paragraph.empty()) out += "<p>" + html_inline(paragraph) + "</p>\n";
        paragraph.clear();
    };
    const auto flush_item = [&] {
        if (!item.empty()) out += "<li>" + html_inline(item) + "</li>\n";
        item.clear();
    };
    const auto close_list = [&] {
        flush_item();
        if (!list.empty()) out += "</" + list + ">\n";
        list.clear();
    };
    const auto flush_table = [&] {
        if (table.empty()) return;
        out += "<table>\n";
        bool head = table.size() > 1 && separator_row(table[1]);
        for (std::size_t r = 0; r < table.size(); ++r) {
            if (head && r == 1) continue;
            const char* cell = head && r == 0 ? "th" : "td";
            out += "<tr>";
            for (const std::string_view c : cells_of(table[r]))
                out += std::string("<") + cell + ">" + html_inline(c) + "</" + cell + ">";
            out += "</tr>\n";
        }
        out += "</table>\n";
        table.clear();
    };
    const auto flush_code = [&] {
        if (code.empty() && !fenced) return;
        out += "<pre><code>";
        for (const std::string_view line : code) out += html_escape(line) + "\n";
        out += "</code></pre>\n";
        code.clear();
    };
    const auto flush_all = [&] {
        flush_paragraph();
        close_list();
        flush_table();
    };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string_view line = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        start = end == std::string_view::npos ? text.size() + 1 : end + 1;
        if (line.rfind("```", 0) == 0) {
            if (fenced) {
                flush_code();
                fenced = false;
            } else {
                flush_all();
                if (!code.empty()) flush_code();
                fenced = true;
            }
            continue;
        }
        if (fenced) {
            code.push_back(line);
            continue;
        }
        const std::size_t first = line.find_first_not_of(' ');
        const bool indented_code = line.rfind("    ", 0) == 0 && paragraph.empty() && item.empty() && table.empty();
        if (!indented_code && !code.empty()) flush_code();
        if (first == std::string_view::npos) {
            flush_all();
            continue;
        }
        if (indented_code) {
            flush_all();
            code.push_back(line.substr(4));
            continue;
        }
        if (table_row(line)) {
            flush_paragraph();
            close_list();
            table.push_back(line);
            continue;
        }
        flush_table();
        bool ordered = false;
        if (const std::size_t marker = list_marker(line, ordered)) {
            flush_paragraph();
            const std::string kind = ordered ? "ol" : "ul";
            if (list != kind) {
                close_list();
                out += "<" + kind + ">\n";
                list = kind;
            }
            flush_item();
            item = std::string(line.substr(marker));
            continue;
        }
        if (!item.empty()) {
            item += " " + std::string(line.substr(first));
            continue;
        }
        std::size_t hashes = 0;
        while (hashes < line.size() && line[hashes] == '#') ++hashes;
        if (hashes > 0 && hashes <= 4 && line.size() > hashes && line[hashes] == ' ') {
            flush_all();
            const std::string tag = "h" + std::to_string(hashes + 2);  // under the step's h2
            out += "<" + tag + ">" + html_inline(line.substr(hashes + 1)) + "</" + tag + ">\n";
            continue;
        }
        paragraph += (paragraph.empty() ? "" : "\n") + std::string(line.substr(first));
    }
    if (fenced) flush_code();
    flush_code();
    flush_all();
    return out;
}

}  // namespace promyk
