#include "trace/trace_text.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include <fmt/format.h>

namespace promyk {

namespace {

constexpr std::size_t columns = 80;

// Terminal columns taken by UTF-8 text: one per code point (the vocabulary
// uses no wide or combining characters).
std::size_t display_width(const std::string& text) {
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string pad(const std::string& text, std::size_t width) {
    return text + std::string(width - std::min(width, display_width(text)), ' ');
}

// The shortest text that reads back to the same double; "nan", "inf" and
// "-inf" as the JSON trace spells them (a NaN's sign means nothing).
std::string number_text(double value) {
    if (value != value) return "nan";
    return fmt::format("{}", value);
}

// Points in parentheses, vectors in square brackets, as the article writes them.
std::string format_value(const StepValue& value, const std::string& kind) {
    if (const double* number = std::get_if<double>(&value)) return number_text(*number);
    const Vec3d& v = std::get<Vec3d>(value);
    const char* open = kind == "vector" ? "[" : "(";
    const char* close = kind == "vector" ? "]" : ")";
    return fmt::format("{}{}, {}, {}{}", open, number_text(v.x), number_text(v.y), number_text(v.z), close);
}

// `first` + `text`, broken after a separator (a space, or ", " to keep
// "name = value" pairs whole) so that no line is wider than the terminal;
// continuation lines start with `indent` spaces.
std::string wrap(const std::string& first, const std::string& text, std::size_t indent,
                 const std::string& separator = " ") {
    std::string out = first;
    std::size_t width = display_width(first);
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t found = text.find(separator, start);
        const std::size_t end = found == std::string::npos ? text.size() : found + separator.size();
        const std::string piece = text.substr(start, end - start);
        if (width > indent && width + display_width(piece) > columns) {
            while (!out.empty() && out.back() == ' ') out.pop_back();
            out += '\n' + std::string(indent, ' ');
            width = indent;
        }
        out += piece;
        width += display_width(piece);
        start = end;
    }
    return out + '\n';
}

std::string symbol_of(const Vocabulary& vocabulary, const std::string& key) {
    const VocabularyEntry* entry = vocabulary.find(key);
    return entry ? entry->symbol : key;
}

std::string kind_of(const Vocabulary& vocabulary, const std::string& key) {
    const VocabularyEntry* entry = vocabulary.find(key);
    return entry ? entry->kind : "point";
}

std::string header_text(const PixelTrace& trace, const Vocabulary& vocabulary) {
    const TraceHeader& h = trace.header;
    std::string out = fmt::format("pixel (i, j) = ({}, {}) of {}; scene \"{}\" ({})\n", h.i, h.j, pane_phrase(h.w),
                                  h.scene_name, h.scene_file);
    out += fmt::format("numbers: {}, formula: {}, samples per pixel: {}\n", h.real, h.formula, h.spp);
    std::string given;
    for (const GivenValue& value : h.given) {
        given += fmt::format("{}{} = {}", given.empty() ? "" : ", ", symbol_of(vocabulary, value.key),
                             format_value(value.value, kind_of(vocabulary, value.key)));
    }
    if (!given.empty()) out += wrap("given: ", given, 7, ", ");
    return out + '\n';
}

std::string narrow_steps(const PixelTrace& trace, const Vocabulary& vocabulary) {
    std::size_t key_width = 0;
    for (const Step& step : trace.steps) key_width = std::max(key_width, key_name(step.key).size());
    const std::size_t number_width = std::to_string(trace.steps.size()).size();
    const std::size_t indent = number_width + 2 + key_width + 2;
    std::string out;
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const Step& step = trace.steps[k];
        const std::string key(key_name(step.key));
        const VocabularyEntry* entry = vocabulary.find(key);
        const std::string symbol = entry ? entry->symbol : key;
        const std::string lead = fmt::format("{:>{}}  {}", k + 1, number_width, pad(key, key_width + 2));
        out += wrap(lead, entry && !entry->formula.empty() ? symbol + " = " + entry->formula : symbol, indent);
        out += wrap(std::string(indent, ' ') + "= ", format_value(step.value, entry ? entry->kind : "point"),
                    indent + 2);
    }
    return out;
}

std::string wide_steps(const PixelTrace& trace, const Vocabulary& vocabulary) {
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
    std::string out;
    for (const Row& row : rows) {
        out += fmt::format("{:>{}}  {}  {}  {}  {}\n", row.step, widths[0], pad(row.key, widths[1]),
                           pad(row.symbol, widths[2]), pad(row.formula, widths[3]), row.value);
    }
    return out;
}

std::string footer_text(const PixelTrace& trace, const Vocabulary& vocabulary) {
    const std::string branch(branch_name(trace.branch));
    const BranchEntry* about = vocabulary.find_branch(branch);
    std::string out = wrap("\nbranch: ", branch + (about ? " — " + about->en : ""), 8);
    const VocabularyEntry* result = vocabulary.find("I_P");
    const std::string I_P = result ? result->symbol : "I_P";
    if (trace.branch == Branch::lit && result)
        out += fmt::format("result: {} = {} = {}\n", I_P, result->formula, number_text(trace.result));
    else
        out += fmt::format("result: {} = {}\n", I_P, number_text(trace.result));
    if (trace.first_non_finite && *trace.first_non_finite < trace.steps.size()) {
        const std::size_t k = *trace.first_non_finite;
        const std::string key(key_name(trace.steps[k].key));
        const bool decides = trace.branch == Branch::non_finite;
        out += wrap("first non-finite value: ",
                    fmt::format("step {}, {} = {}: the numbers left the range of a double (about ±1.8e308){}", k + 1,
                                symbol_of(vocabulary, key), format_value(trace.steps[k].value, kind_of(vocabulary, key)),
                                decides ? ", so no comparison from here on can be trusted"
                                        : "; only the lessons compute it, the program's own numbers stayed finite"),
                    2);
    }
    out += wrap("grey level: ", fmt::format("{} of 255 = round(255 · {}), {} clamped to [0, 1], halves up{}",
                                            trace.grey, I_P, I_P, trace.result != trace.result ? "; NaN gives 0" : ""),
                2);
    out +=
        "\n(…) is a point, […] a vector. Each number is the shortest decimal that reads\n"
        "back as the same double. Most decimals have no exact binary form: 3.2 is\n"
        "stored as 3.2000000000000001776…, so 3.2² gives 10.240000000000002, not 10.24.\n";
    return out;
}

}  // namespace

std::string pane_phrase(int w) {
    const std::string digits = std::to_string(w);
    // Spoken "eight…", "eleven…", "eighteen…" take "an".
    const bool vowel = digits[0] == '8' || w == 11 || w == 18 || (w >= 11000 && w < 12000) ||
                       (w >= 18000 && w < 19000);
    return fmt::format("{} {} × {} pane", vowel ? "an" : "a", w, w);
}

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary, TraceLayout layout) {
    std::string out = header_text(trace, vocabulary);
    out += layout == TraceLayout::wide ? wide_steps(trace, vocabulary) : narrow_steps(trace, vocabulary);
    return out + footer_text(trace, vocabulary);
}

}  // namespace promyk
