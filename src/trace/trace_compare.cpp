#include "trace/trace_compare.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <quadmath.h>

#include "math/real.hpp"
#include "trace/messages.hpp"
#include "trace/trace_text.hpp"
#include "util/text.hpp"

namespace promyk {

namespace {

int significant_digits(const std::string& text) {
    const std::string mantissa = text.substr(0, text.find_first_of("eE"));
    std::string digits;
    for (char c : mantissa)
        if (c >= '0' && c <= '9') digits += c;
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return 1;
    return static_cast<int>(digits.find_last_not_of('0') - first + 1);
}

// The exact texts of a step: its real type's text, else the double's.
std::vector<std::string> exact_texts(const Step& step) {
    if (!step.real_text.empty()) return step.real_text;
    if (const double* v = std::get_if<double>(&step.value)) return {real_text(*v)};
    if (const Vec3d* v = std::get_if<Vec3d>(&step.value)) return {real_text(v->x), real_text(v->y), real_text(v->z)};
    return {std::get<std::string>(step.value)};
}

// A step's place: its group path and key, and which occurrence it is.
using Place = std::tuple<std::string, int>;

std::string path_of(const PixelTrace& trace, const Step& step) {
    std::string path;
    for (int g = step.group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent) {
        const TraceGroup& group = trace.groups[static_cast<std::size_t>(g)];
        path = group.kind + "[" + std::to_string(group.index) + "]." + path;
    }
    return path + std::string(key_name(step.key));
}

std::string pad(const std::string& text, std::size_t width) {
    const std::size_t shown = display_width(text);
    return shown >= width ? text : text + std::string(width - shown, ' ');
}

}  // namespace

namespace {

// The exact value of a real type's text, as a quad (every type's values are
// quads exactly: float, double and x87 long double fit in 113 bits).
quad exact_value(const std::string& text, const std::string& type) {
    if (type == "float") return std::strtof(text.c_str(), nullptr);
    if (type == "double") return std::strtod(text.c_str(), nullptr);
    if (type == "long-double") return std::strtold(text.c_str(), nullptr);
    return strtoflt128(text.c_str(), nullptr);
}

}  // namespace

int agreeing_digits(const std::string& value, const std::string& value_type, const std::string& reference,
                    const std::string& reference_type) {
    const quad a = exact_value(value, value_type);
    const quad b = exact_value(reference, reference_type);
    if (a == b) return -1;
    if (!(a * 0 == 0) || !(b * 0 == 0) || b == 0) return 0;
    const quad relative = fabsq((a - b) / b);
    return std::max(0, static_cast<int>(std::floor(-static_cast<double>(log10q(relative)))));
}

std::string mark_digits(const std::string& value, int digits) {
    if (digits >= significant_digits(value)) return value;
    std::string out;
    int seen = 0;
    bool started = false, marked = false;
    for (std::size_t k = 0; k < value.size(); ++k) {
        const char c = value[k];
        if (!marked && c >= '0' && c <= '9') {
            if (c != '0') started = true;
            if (started && seen == digits) {
                out += '|';
                marked = true;
            }
            if (started) ++seen;
        }
        if (!marked && (c == 'e' || c == 'E')) {
            out += '|';
            marked = true;
        }
        out += c;
    }
    return out;
}

std::string format_comparison(const std::vector<PixelTrace>& traces, const Vocabulary& vocabulary,
                              Language language) {
    if (traces.empty()) return "";
    const PixelTrace& reference = traces.back();
    // Rows in the reference's order, then the places only other types reach.
    std::vector<std::string> order;
    std::vector<std::map<std::string, const Step*>> places(traces.size());
    for (std::size_t c = 0; c < traces.size(); ++c) {
        std::map<std::string, int> seen;
        for (const Step& step : traces[c].steps) {
            std::string place = path_of(traces[c], step);
            const int n = seen[place]++;
            if (n > 0) place += "#" + std::to_string(n + 1);
            places[c][place] = &step;
            if (std::find(order.begin(), order.end(), place) == order.end()) {
                if (c + 1 == traces.size())
                    order.push_back(place);
            }
        }
    }
    for (std::size_t c = 0; c + 1 < traces.size(); ++c)
        for (const auto& [place, step] : places[c])
            if (std::find(order.begin(), order.end(), place) == order.end()) order.push_back(place);

    std::size_t name_width = 0;
    for (const PixelTrace& trace : traces) name_width = std::max(name_width, trace.header.real.size());
    std::string out = message(language, "compare_heading",
                              {{"i", std::to_string(reference.header.i)},
                               {"j", std::to_string(reference.header.j)},
                               {"w", std::to_string(reference.header.w)},
                               {"pane", pane_phrase(reference.header.w)},
                               {"scene", reference.header.scene_name},
                               {"reference", reference.header.real}}) +
                      "\n" + message(language, "compare_legend", {{"reference", reference.header.real}}) + "\n";
    for (const std::string& place : order) {
        const Step* ref = places.back().count(place) ? places.back().at(place) : nullptr;
        const std::string key = place.substr(place.rfind('.') == std::string::npos ? 0 : place.rfind('.') + 1);
        const std::string bare = key.substr(0, key.find('#'));
        const VocabularyEntry* entry = vocabulary.find(bare);
        out += fmt::format("\n{}  {}\n", place, entry ? entry->symbol : bare);
        for (std::size_t c = 0; c < traces.size(); ++c) {
            const auto it = places[c].find(place);
            std::string shown = "—";
            std::string agree;
            if (it != places[c].end()) {
                const std::vector<std::string> texts = exact_texts(*it->second);
                const std::vector<std::string> reference_texts = ref ? exact_texts(*ref) : std::vector<std::string>{};
                const bool word = std::holds_alternative<std::string>(it->second->value);
                shown.clear();
                int least = 1000;  // the fewest agreeing digits of the components; -1: all equal
                for (std::size_t k = 0; k < texts.size(); ++k) {
                    std::string text = texts[k];
                    if (!word && c + 1 < traces.size() && k < reference_texts.size()) {
                        const int digits = agreeing_digits(texts[k], traces[c].header.real, reference_texts[k],
                                                           reference.header.real);
                        least = std::min(least, digits);
                        if (digits >= 0) text = mark_digits(texts[k], digits);
                    }
                    if (word) text = word_text(language, text);
                    shown += (k ? ", " : "") + text;
                }
                if (texts.size() == 3) shown = "(" + shown + ")";
                if (!word && c + 1 < traces.size() && ref)
                    agree = least < 0 ? message(language, "compare_equal")
                                      : message(language, "compare_digits", {{"digits", std::to_string(least)}});
            }
            out += fmt::format("  {}  {}{}\n", pad(traces[c].header.real, name_width), shown,
                               agree.empty() ? "" : "   " + agree);
        }
    }
    out += "\n";
    for (const PixelTrace& trace : traces)
        out += fmt::format("{}  {}: {}\n", pad(trace.header.real, name_width), message(language, "trace_branch"),
                           std::string(branch_name(trace.branch)));
    return out;
}

}  // namespace promyk
