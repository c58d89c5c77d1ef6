#include "app/cli_values.hpp"

#include <algorithm>
#include <cctype>
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
#include "trace/messages.hpp"
#include "util/edit_distance.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"
#include "util/read_input.hpp"
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
// number) into exactly `count` plain whole numbers, or throws. Numbers are
// at most max_w - 1 (a pixel of the largest pane): a longer text is refused
// with the range before it is converted, whatever its length.
std::vector<int> parse_integers(const std::string& typed, std::size_t count, const std::string& option,
                                const char* form_id) {
    const std::string form = ui_message(form_id);
    std::string text = trim(typed);
    if (text.size() >= 2 && text.front() == '(' && text.back() == ')') text = text.substr(1, text.size() - 2);
    std::vector<int> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string part = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (!is_plain_decimal(part))
            throw UsageError(ui_message("cli_pixel_form", {{"option", option}, {"form", form}, {"value", typed}}));
        if (part.size() > 7 || std::labs(std::stol(part)) >= max_w)
            throw UsageError(ui_message("cli_pixel_range", {{"option", option},
                                                           {"form", form},
                                                           {"max", std::to_string(max_w - 1)},
                                                           {"w", std::to_string(max_w)},
                                                           {"value", typed}}));
        values.push_back(std::stoi(part));  // a small negative one: check_inside says it is outside
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (values.size() != count)
        throw UsageError(ui_message("cli_pixel_count", {{"option", option}, {"form", form}, {"value", typed}}));
    return values;
}

void check_inside(int i, int j, int w, const std::string& option) {
    if (i >= 0 && i < w && j >= 0 && j < w) return;
    std::string text = ui_message("cli_pixel_outside", {{"option", option},
                                                        {"i", std::to_string(i)},
                                                        {"j", std::to_string(j)},
                                                        {"w", std::to_string(w)}});
    if (i < 0 || j < 0) {
        text += ui_message("cli_pixel_span", {{"last", std::to_string(w - 1)}});
    } else {
        const std::string need = std::to_string(smallest_w_containing(i, j));
        text += smallest_w_containing(i, j) <= render_default_w && w != render_default_w
                    ? ui_message("cli_pixel_fits_render", {{"need", need}, {"render", std::to_string(render_default_w)}})
                    : ui_message("cli_pixel_fits", {{"need", need}});
    }
    throw UsageError(text);
}

}  // namespace

std::string closest_name(const std::string& typed, const std::vector<std::string>& names) {
    std::string lower = typed;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const std::string& name : names)
        if (lower == name) return name;
    std::string best;
    std::size_t best_distance = 3;
    for (const std::string& name : names) {
        const std::size_t distance = edit_distance(lower, name);
        if (distance < best_distance && distance < std::max(lower.size(), name.size())) {
            best = name;
            best_distance = distance;
        }
    }
    return best;
}

std::string choice_problem(const std::string& typed, const std::string& option, const std::vector<std::string>& names) {
    if (std::find(names.begin(), names.end(), typed) != names.end()) return "";
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    const std::string suggestion = closest_name(typed, names);
    if (suggestion.empty())
        return ui_message("cli_unknown_value", {{"value", printable(typed)}, {"option", option}, {"names", list}});
    return ui_message("cli_unknown_value_suggest",
                      {{"value", printable(typed)}, {"option", option}, {"suggestion", suggestion}, {"names", list}});
}

std::optional<std::string> whole_number_problem(const std::string& text, long min, long max) {
    const MessageArgs range = {{"min", std::to_string(min)}, {"max", std::to_string(max)}, {"value", text}};
    if (text.empty()) return ui_message("cli_whole_needs_value", range);
    if (!is_plain_decimal(text)) {
        const std::string plain = plain_form(text);
        return ui_message("cli_whole_not_plain", range) +
               (plain.empty() ? "" : ui_message("cli_whole_write", {{"plain", plain}}));
    }
    if (text.size() > 12 || std::stol(text) < min || std::stol(text) > max) return ui_message("cli_whole_range", range);
    return std::nullopt;
}

int parse_whole_number(const std::string& text, const std::string& option, long min, long max) {
    if (const auto problem = whole_number_problem(text, min, max))
        throw UsageError(fmt::format("{} {}", option, *problem));
    return static_cast<int>(std::stol(text));
}

Pixel parse_pixel(const std::string& text, const std::string& option, int w) {
    const std::vector<int> v = parse_integers(text, 2, option, "cli_form_pixel");
    check_inside(v[0], v[1], w, option);
    return {v[0], v[1]};
}

PixelRegion parse_region(const std::string& text, const std::string& option, int w) {
    const std::vector<int> v = parse_integers(text, 4, option, "cli_form_region");
    const std::string corner = ui_message("cli_corner", {{"option", option}});
    check_inside(v[0], v[1], w, corner);
    check_inside(v[2], v[3], w, corner);
    if (v[0] > v[2] || v[1] > v[3])
        throw UsageError(ui_message("cli_region_order", {{"option", option}, {"value", text}}));
    return {v[0], v[1], v[2], v[3]};
}

Scene load_scene_option(const std::string& path) { return path.empty() ? article_scene() : load_scene_file(path); }

std::string read_input_file(const std::string& path, const std::string& reads, std::size_t max_bytes,
                            const std::string& who) {
    const std::string shown = path == "-" ? "(stdin)" : path;
    if (path != "-") {
        std::error_code error;
        if (std::filesystem::is_directory(path, error)) throw InputError(path, "", "is a folder; " + reads + " a file");
    }
    // util/read_input: the limit checked as the bytes come (one byte past it
    // is refusal), and a FIFO, pipe or terminal waited on interruptibly.
    WholeFile file = path == "-" ? read_whole_standard_input(max_bytes) : read_whole_file(path, max_bytes);
    switch (file.failure) {
        case WholeFile::Failure::none:
            break;
        case WholeFile::Failure::cannot_open:
        case WholeFile::Failure::cannot_read:
            throw InputError(shown, "", "cannot read the file: " + std::generic_category().message(file.error));
        case WholeFile::Failure::too_large:
            throw InputError(shown, "",
                             ui_message("input_too_large", {{"mib", std::to_string(max_bytes >> 20)}, {"who", who}}));
    }
    return std::move(file.bytes);
}

}  // namespace promyk::cli
