#include "app/cli_values.hpp"

#include <cerrno>
#include <cstdlib>

#include <fmt/format.h>

#include "scene/scene_json.hpp"
#include "util/errors.hpp"

namespace promyk::cli {

namespace {

// Splits "a,b,..." into exactly `count` whole numbers, or throws.
std::vector<int> parse_integers(const std::string& text, std::size_t count, const std::string& option,
                                const char* form) {
    std::vector<int> values;
    const char* p = text.c_str();
    while (true) {
        char* end = nullptr;
        errno = 0;
        const long value = std::strtol(p, &end, 10);
        const bool digits = end != p && (*p == '-' || *p == '+' || (*p >= '0' && *p <= '9'));
        if (!digits || errno == ERANGE || value < -1000000000L || value > 1000000000L)
            throw UsageError(fmt::format("{} expects {} (whole numbers), got '{}'", option, form, text));
        values.push_back(static_cast<int>(value));
        if (*end == '\0') break;
        if (*end != ',') throw UsageError(fmt::format("{} expects {} (whole numbers), got '{}'", option, form, text));
        p = end + 1;
    }
    if (values.size() != count) throw UsageError(fmt::format("{} expects {}, got '{}'", option, form, text));
    return values;
}

void check_inside(int i, int j, int w, const std::string& option) {
    if (i < 0 || i >= w || j < 0 || j >= w)
        throw UsageError(
            fmt::format("{} ({}, {}) is outside the {} x {} pane: i and j go from 0 to {}", option, i, j, w, w, w - 1));
}

}  // namespace

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

void check_w(int w) {
    if (w < 1 || w > max_w) throw UsageError(fmt::format("--w must be between 1 and {}, got {}", max_w, w));
}

void check_threads(int threads) {
    if (threads < 0 || threads > max_threads)
        throw UsageError(fmt::format("--threads must be between 0 (all cores) and {}, got {}", max_threads, threads));
}

Scene load_scene_option(const std::string& path) { return path.empty() ? article_scene() : load_scene_file(path); }

}  // namespace promyk::cli
