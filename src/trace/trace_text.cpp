#include "trace/trace_text.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include <fmt/format.h>

namespace promyk {

namespace {

// Terminal columns taken by UTF-8 text: one per code point (the vocabulary
// uses no wide or combining characters).
std::size_t display_width(const std::string& text) {
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string pad(const std::string& text, std::size_t width) {
    return text + std::string(width - std::min(width, display_width(text)), ' ');
}

// Points in parentheses, vectors in square brackets, as the article writes them.
std::string format_value(const StepValue& value, const std::string& kind) {
    if (const double* number = std::get_if<double>(&value)) return fmt::format("{}", *number);
    const Vec3d& v = std::get<Vec3d>(value);
    const char* open = kind == "vector" ? "[" : "(";
    const char* close = kind == "vector" ? "]" : ")";
    return fmt::format("{}{}, {}, {}{}", open, v.x, v.y, v.z, close);
}

}  // namespace

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary) {
    const TraceHeader& h = trace.header;
    struct Row {
        std::string step, key, symbol, formula, value;
    };
    std::vector<Row> rows = {{"step", "key", "symbol", "formula", "value"}};
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const Step& step = trace.steps[k];
        const std::string key(key_name(step.key));
        const VocabularyEntry* entry = vocabulary.find(key);
        rows.push_back({std::to_string(k + 1), key, entry ? entry->symbol : key, entry ? entry->formula : "",
                        format_value(step.value, entry ? entry->kind : "point")});
    }
    std::size_t widths[4] = {0, 0, 0, 0};
    for (const Row& row : rows) {
        widths[0] = std::max(widths[0], display_width(row.step));
        widths[1] = std::max(widths[1], display_width(row.key));
        widths[2] = std::max(widths[2], display_width(row.symbol));
        widths[3] = std::max(widths[3], display_width(row.formula));
    }

    std::string out = fmt::format("pixel (i, j) = ({}, {}) of a {} x {} pane; scene \"{}\", z_E = {}\n", h.i, h.j, h.w,
                                  h.w, h.scene_name, h.z_E);
    out += fmt::format("numbers: {}, formula: {}, samples per pixel: {}\n\n", h.real, h.formula, h.spp);
    for (const Row& row : rows) {
        out += fmt::format("{:>{}}  {}  {}  {}  {}\n", row.step, widths[0], pad(row.key, widths[1]),
                           pad(row.symbol, widths[2]), pad(row.formula, widths[3]), row.value);
    }
    const std::string branch(branch_name(trace.branch));
    const BranchEntry* about = vocabulary.find_branch(branch);
    out += fmt::format("\nbranch: {}{}\n", branch, about ? " — " + about->en : "");
    const VocabularyEntry* result = vocabulary.find("I_P");
    if (trace.branch == Branch::lit && result)
        out += fmt::format("result: {} = {} = {}\n", result->symbol, result->formula, trace.result);
    else
        out += fmt::format("result: {} = {}\n", result ? result->symbol : "I_P", trace.result);
    return out;
}

}  // namespace promyk
