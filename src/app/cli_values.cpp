#include "app/cli_values.hpp"

#include <cctype>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "scene/scene_json.hpp"
#include "util/errors.hpp"
#include "util/text.hpp"

namespace promyk::cli {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// What the user probably meant, written plainly: "010" -> "10",
// "0x10" -> "16", " 16" -> "16", "1e3" -> "1000"; empty when nothing fits.
std::string plain_form(const std::string& typed) {
    const std::string text = trim(typed);
    if (text.empty()) return "";
    const bool negative = text[0] == '-';
    const std::string body = text.substr(negative || text[0] == '+' ? 1 : 0);
    long long value = 0;
    if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
        char* end = nullptr;
        errno = 0;
        value = std::strtoll(body.c_str() + 2, &end, 16);
        if (*end != '\0' || errno != 0) return "";
    } else if (!body.empty() && std::all_of(body.begin(), body.end(), is_digit)) {
        const auto nonzero = body.find_first_not_of('0');
        const std::string digits = nonzero == std::string::npos ? "0" : body.substr(nonzero);
        if (digits.size() > 18) return "";
        value = std::stoll(digits);
    } else {
        char* end = nullptr;
        errno = 0;
        const double number = std::strtod(body.c_str(), &end);
        if (*end != '\0' || errno != 0 || !std::isfinite(number) || number != std::floor(number) ||
            std::fabs(number) > 1e18)
            return "";
        value = static_cast<long long>(number);
    }
    return fmt::format("{}{}", negative && value != 0 ? "-" : "", value);
}

// Splits "a,b,..." (optionally in parentheses, spaces allowed around each
// number) into exactly `count` plain whole numbers, or throws.
std::vector<int> parse_integers(const std::string& typed, std::size_t count, const std::string& option,
                                const char* form) {
    std::string text = trim(typed);
    if (text.size() >= 2 && text.front() == '(' && text.back() == ')') text = text.substr(1, text.size() - 2);
    std::vector<int> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string part = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (!is_plain_decimal(part) || part.size() > 10)
            throw UsageError(fmt::format("{} expects {} (whole numbers in plain decimal), got '{}'", option, form, typed));
        values.push_back(std::stoi(part));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (values.size() != count) throw UsageError(fmt::format("{} expects {}, got '{}'", option, form, typed));
    return values;
}

void check_inside(int i, int j, int w, const std::string& option) {
    if (i < 0 || i >= w || j < 0 || j >= w)
        throw UsageError(fmt::format("{} ({}, {}) is outside the {} × {} pane: i and j go from 0 to {}", option, i, j,
                                     w, w, w - 1));
}

}  // namespace

std::optional<std::string> whole_number_problem(const std::string& text, long min, long max) {
    const std::string range = fmt::format("a whole number from {} to {}", min, max);
    if (text.empty()) return fmt::format("needs a value: {}", range);
    if (!is_plain_decimal(text)) {
        const std::string plain = plain_form(text);
        return fmt::format("expects {} written in plain decimal, got '{}'{}", range, text,
                           plain.empty() ? "" : fmt::format("; write {}", plain));
    }
    if (text.size() > 12 || std::stol(text) < min || std::stol(text) > max)
        return fmt::format("expects {}, got {}", range, text);
    return std::nullopt;
}

int parse_whole_number(const std::string& text, const std::string& option, long min, long max) {
    if (const auto problem = whole_number_problem(text, min, max))
        throw UsageError(fmt::format("{} {}", option, *problem));
    return static_cast<int>(std::stol(text));
}

Pixel parse_pixel(const std::string& text, const std::string& option, int w) {
    const std::vector<int> v = parse_integers(text, 2, option, "I,J (row from the top, column from the left)");
    check_inside(v[0], v[1], w, option);
    return {v[0], v[1]};
}

PixelRegion parse_region(const std::string& text, const std::string& option, int w) {
    const std::vector<int> v = parse_integers(text, 4, option, "I0,J0,I1,J1 (top-left and bottom-right corners)");
    check_inside(v[0], v[1], w, option + " corner");
    check_inside(v[2], v[3], w, option + " corner");
    if (v[0] > v[2] || v[1] > v[3])
        throw UsageError(fmt::format("{} '{}': the first corner must be above and left of the second", option, text));
    return {v[0], v[1], v[2], v[3]};
}

Scene load_scene_option(const std::string& path) { return path.empty() ? article_scene() : load_scene_file(path); }

std::string read_input_file(const std::string& path, const std::string& reads) {
    std::ostringstream text;
    if (path == "-") {
        text << std::cin.rdbuf();
        return text.str();
    }
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw InputError(path, "", "is a folder; " + reads + " a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot read the file: " + std::generic_category().message(errno));
    text << in.rdbuf();
    return text.str();
}

}  // namespace promyk::cli
