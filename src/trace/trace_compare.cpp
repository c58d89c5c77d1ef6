#include "trace/trace_compare.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "math/decimal.hpp"
#include "math/portable_log10.hpp"
#include "math/real.hpp"
#include "trace/messages.hpp"
#include "util/interrupt.hpp"
#include "trace/trace_text.hpp"
#include "util/text.hpp"
#include "util/wrap.hpp"

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

// `lead` + `value` + "   " + `note` on one line when it fits 80 columns;
// else the value broken after its separators under the lead, and the note
// on a line of its own.
std::string fit_row(const std::string& lead, const std::string& value, const std::string& note, Language language,
                    std::string separator = "") {
    constexpr std::size_t columns = 80;
    const std::string tail = note.empty() ? "" : "   " + note;
    if (display_width(lead) + display_width(value) + display_width(tail) <= columns) return lead + value + tail + "\n";
    if (separator.empty()) separator = coordinate_separator(language);
    const std::string indent(display_width(lead), ' ');
    std::string out = lead;
    std::size_t width = display_width(lead), start = 0;
    while (start < value.size()) {
        // English values break after ", " as well as "; " (Polish numbers hold commas)
        std::size_t found = value.find(separator, start);
        std::size_t length = separator.size();
        if (language == Language::en && separator == "; ")
            if (const std::size_t comma = value.find(", ", start); comma < found) found = comma, length = 2;
        const std::size_t end = found == std::string::npos ? value.size() : found + length;
        std::string piece = value.substr(start, end - start);
        if (width > indent.size() && width + display_width(piece) > columns) {
            while (!out.empty() && out.back() == ' ') out.pop_back();
            out += "\n" + indent;
            width = indent.size();
        }
        out += piece;
        width += display_width(piece);
        start = end;
    }
    if (!note.empty()) out += "\n" + indent + note;
    return out + "\n";
}

}  // namespace

namespace {

// The exact value of a real type's text, as a quad (every type's values are
// quads exactly: float, double and x87 long double fit in 113 bits).
quad exact_value(const std::string& text, const std::string& type) {
    if (type == "float") return std::strtof(text.c_str(), nullptr);
    if (type == "double") return std::strtod(text.c_str(), nullptr);
#if PROMYK_HAS_X87_LONG_DOUBLE
    if (type == "long-double") return std::strtold(text.c_str(), nullptr);
#else
    if (type == "long-double") return x87_rounded(quad_math::from_text(text.c_str(), nullptr));
#endif
    return quad_math::from_text(text.c_str(), nullptr);
}

}  // namespace

int agreeing_digits(const std::string& value, const std::string& value_type, const std::string& reference,
                    const std::string& reference_type) {
    const quad a = exact_value(value, value_type);
    const quad b = exact_value(reference, reference_type);
    if (a == b) return -1;
    if (!(a * 0 == 0) || !(b * 0 == 0) || b == 0) return 0;
    const quad relative = quad_math::fabs((a - b) / b);
    return std::max(0, static_cast<int>(std::floor(-log10_magnitude(relative))));
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
    // (A set beside the order: a search of the order for each step was
    // quadratic, hours for a trace of thousands of objects and lights.)
    std::vector<std::string> order;
    std::set<std::string> ordered;
    std::vector<std::map<std::string, const Step*>> places(traces.size());
    std::size_t visited = 0;
    for (std::size_t c = 0; c < traces.size(); ++c) {
        std::map<std::string, int> seen;
        for (const Step& step : traces[c].steps) {
            if ((visited++ & 4095) == 0) throw_if_interrupted();
            std::string place = path_of(traces[c], step);
            const int n = seen[place]++;
            if (n > 0) place += "#" + std::to_string(n + 1);
            places[c][place] = &step;
            if (c + 1 == traces.size() && ordered.insert(place).second) order.push_back(place);
        }
    }
    for (std::size_t c = 0; c + 1 < traces.size(); ++c)
        for (const auto& [place, step] : places[c])
            if (ordered.insert(place).second) order.push_back(place);

    std::size_t name_width = 0;
    for (const PixelTrace& trace : traces) name_width = std::max(name_width, trace.header.real.size());
    std::string out = wrap_text(message(language, "compare_heading",
                              {{"i", std::to_string(reference.header.i)},
                               {"j", std::to_string(reference.header.j)},
                               {"w", std::to_string(reference.header.w)},
                               {"pane", pane_phrase(reference.header.w)},
                               {"scene", reference.header.scene_name},
                               {"reference", reference.header.real}})) +
                      "\n" + wrap_text(message(language, "compare_legend", {{"reference", reference.header.real}})) + "\n";
    for (const std::string& place : order) {
        if ((visited++ & 4095) == 0) throw_if_interrupted();
        const Step* ref = places.back().count(place) ? places.back().at(place) : nullptr;
        const std::string key = place.substr(place.rfind('.') == std::string::npos ? 0 : place.rfind('.') + 1);
        const std::string bare = key.substr(0, key.find('#'));
        const VocabularyEntry* entry = vocabulary.find(bare);
        const bool vector = entry && (entry->kind == "vector" || entry->kind == "colour");
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
                // A vector agrees as far as its worst component: a component
                // equal to the reference's agrees in every digit, and the
                // vector is "exactly equal" only when every component is.
                bool all_equal = true;
                int least = 1000;
                for (std::size_t k = 0; k < texts.size(); ++k) {
                    std::string text = texts[k];
                    if (!word && c + 1 < traces.size() && k < reference_texts.size()) {
                        const int digits = agreeing_digits(texts[k], traces[c].header.real, reference_texts[k],
                                                           reference.header.real);
                        if (digits >= 0) {
                            all_equal = false;
                            least = std::min(least, digits);
                            text = mark_digits(texts[k], digits);
                        }
                    }
                    text = word ? word_text(language, text) : local_number_text(text, language);
                    shown += (k ? coordinate_separator(language) : "") + text;
                }
                if (texts.size() == 3) shown = (vector ? "[" : "(") + shown + (vector ? "]" : ")");
                if (!word && c + 1 < traces.size() && ref)
                    agree = all_equal ? message(language, "compare_equal")
                                      : message(language, "compare_digits", {{"digits", std::to_string(least)}});
            }
            out += fit_row("  " + pad(traces[c].header.real, name_width) + "  ", shown, agree, language);
        }
    }
    // How each type ends: its branch, its intensity and its grey level
    // (or colour), so that a difference in the result shows at a glance.
    out += "\n";
    for (const PixelTrace& trace : traces) {
        const std::string lead = pad(trace.header.real, name_width) + "  ";
        std::string result = trace.result_real_text.empty() ? real_text(trace.result) : trace.result_real_text.front();
        if (trace.result_rgb) {
            const std::vector<std::string> texts =
                trace.result_real_text.size() == 3
                    ? trace.result_real_text
                    : std::vector<std::string>{real_text(trace.result_rgb->x), real_text(trace.result_rgb->y),
                                               real_text(trace.result_rgb->z)};
            const char* separator = coordinate_separator(language);
            result = "[" + local_number_text(texts[0], language) + separator + local_number_text(texts[1], language) +
                     separator + local_number_text(texts[2], language) + "]";
        } else {
            result = local_number_text(result, language);
        }
        const std::string levels = trace.result_rgb
                                       ? fmt::format("[{}, {}, {}]", trace.rgb[0], trace.rgb[1], trace.rgb[2])
                                       : std::to_string(trace.grey);
        out += fit_row(lead, message(language, "compare_result",
                                     {{"branch", message(language, "branch_name_" + std::string(branch_name(trace.branch)))},
                                      {"I_P", result},
                                      {"grey", levels}}),
                       "", language, "; ");
    }
    return out;
}

}  // namespace promyk
