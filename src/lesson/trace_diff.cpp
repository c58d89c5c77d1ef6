#include "lesson/trace_diff.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <unordered_set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/text.hpp"

namespace promyk {

namespace {

// A step as one side gives it: one number, or three (a point, a vector, a
// colour; a student may give some components only: P.x = 0,13).
struct SideStep {
    std::string path;
    std::vector<std::optional<DiffNumber>> slots;  // 1 or 3
    std::optional<std::string> non_finite;         // a trace's "nan", "[1, inf, 2]"
};

struct Side {
    std::vector<SideStep> steps;
    std::map<std::string, std::size_t> index;

    SideStep& step(const std::string& path) {
        const auto [it, added] = index.emplace(path, steps.size());
        if (added) steps.push_back({path, {}, std::nullopt});
        return steps[it->second];
    }
    const SideStep* find(const std::string& path) const {
        const auto it = index.find(path);
        return it == index.end() ? nullptr : &steps[it->second];
    }
};

std::optional<RealType> real_type_of(const std::string& name) {
    for (const RealType type : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
        if (real_type_name(type) == name) return type;
    return std::nullopt;
}

bool same_pixel(LessonPixel a, LessonPixel b) { return a.i == b.i && a.j == b.j; }

// The number `k` of an answer, as compared: a trace's value in its type, a student's as typed.
DiffNumber number_of(const Answer& answer, std::size_t k, const std::optional<TraceSummary>& trace) {
    DiffNumber number;
    const TypedNumber& typed = answer.numbers[k];
    number.text = typed_number_text(typed, Language::en);
    if (!trace) {
        number.exact = typed;
        number.scale = typed.scale;
        return number;
    }
    const std::optional<RealType> type = real_type_of(trace->real);
    const int bits = real_type_bits(trace->real).value_or(53);
    if (k < answer.real_text.size() && type) {
        if (const std::optional<TypedNumber> exact = exact_value_of(answer.real_text[k], *type)) {
            number.text = answer.real_text[k];
            number.exact = *exact;
            number.bits = bits;
            return number;
        }
    }
    // The double value (a double trace, or one without real_text): exact as a double.
    number.exact = exact_value_of(number.text, RealType::double_).value_or(typed);
    number.bits = std::min(bits, 53);
    return number;
}

// The steps of the chosen pixel, in the file's order.
Side side_of(const DiffInput& input, LessonPixel pixel) {
    Side side;
    const std::optional<TraceSummary>& trace = input.answers.trace;
    std::size_t read = 0;  // answers read so far (a trace's non-finite steps go between them)
    std::size_t next_non_finite = 0;
    const auto non_finite_until = [&](std::size_t count) {
        if (!trace) return;
        for (; next_non_finite < trace->non_finite.size() && trace->non_finite[next_non_finite].before <= count; ++next_non_finite)
            side.step(trace->non_finite[next_non_finite].path).non_finite = trace->non_finite[next_non_finite].text;
    };
    for (const PixelAnswers& section : input.answers.pixels) {
        if (!trace && !same_pixel(section.pixel, pixel) && !same_pixel(section.pixel, diff_first_pixel)) continue;
        for (const Answer& answer : section.answers) {
            if ((read & 4095) == 0) throw_if_interrupted();
            non_finite_until(read++);
            if (answer.numbers.empty()) continue;  // "key =": not given
            SideStep& step = side.step(answer.key);
            if (step.non_finite) continue;
            const std::size_t wanted = answer.component != 0 || answer.numbers.size() == 3 ? 3 : 1;
            if (step.slots.empty()) step.slots.resize(wanted);
            if (step.slots.size() != wanted) continue;  // P = 1 and P.x = 1: the first shape stands
            if (answer.component != 0) {
                auto& slot = step.slots[static_cast<std::size_t>(answer.component - 'x')];
                if (!slot) slot = number_of(answer, 0, trace);
            } else {
                for (std::size_t k = 0; k < answer.numbers.size(); ++k)
                    if (!step.slots[k]) step.slots[k] = number_of(answer, k, trace);
            }
        }
    }
    non_finite_until(std::numeric_limits<std::size_t>::max());
    return side;
}

// The order of the merged steps: the primary side's, each step of the other
// side that it lacks placed after the step that precedes it there.
std::vector<std::string> merged_order(const Side& primary, const Side& other) {
    std::vector<std::string> order;
    for (const SideStep& step : primary.steps) order.push_back(step.path);
    // Paths are unique on each side. A path of both is looked for after the
    // last match first: two traces of one scene match step after step, and a
    // search from the start each time was quadratic (hours for a trace of
    // thousands of objects and lights).
    const std::unordered_set<std::string> in_primary(order.begin(), order.end());
    std::size_t at = 0;
    std::size_t visited = 0;
    for (const SideStep& step : other.steps) {
        if ((visited++ & 4095) == 0) throw_if_interrupted();
        auto found = order.end();
        if (in_primary.count(step.path) > 0) {
            const auto from = order.begin() + static_cast<std::ptrdiff_t>(at);
            found = std::find(from, order.end(), step.path);
            if (found == order.end()) found = std::find(order.begin(), from, step.path);
        }
        if (found != order.end()) {
            at = static_cast<std::size_t>(found - order.begin()) + 1;
        } else {
            order.insert(order.begin() + static_cast<std::ptrdiff_t>(at), step.path);
            ++at;
        }
    }
    return order;
}

// The smallest k with 2·D ≤ 10^k, for the digits D of a positive integer.
int order_of_twice(const std::string& digits) {
    const std::string d = strip_zeros(digits);
    const bool five_and_zeros = d[0] == '5' && d.find_first_not_of('0', 1) == std::string::npos;
    const int length = static_cast<int>(d.size());
    return d[0] < '5' || five_and_zeros ? length : length + 1;
}

// The exponent of the leading digit of a non-zero number (3.14 -> 0, 0.01 -> -2).
int leading_exponent(const TypedNumber& number) { return static_cast<int>(strip_zeros(number.digits).size()) - 1 - number.scale; }

DiffComponent compare(char component, const DiffNumber& a, const DiffNumber& b, const DiffOptions& options) {
    DiffComponent out;
    out.component = component;
    out.a = a;
    out.b = b;
    out.difference = absolute_difference(a.exact, b.exact);
    const TypedNumber& larger = compare_magnitude(a.exact, b.exact) >= 0 ? a.exact : b.exact;
    const quad magnitude = quad_math::fabs(to_quad(larger));
    // Each side's tolerance, relative to the larger magnitude.
    const auto tolerance_of = [&](const DiffNumber& side) -> quad {
        if (side.bits > 0) return ldexpq(1, -side.bits);
        return magnitude == 0 ? 0 : quad(0.5) * powq(10, -side.scale) / magnitude;
    };
    out.tolerance = static_cast<double>(options.relative_tolerance ? quad(*options.relative_tolerance)
                                                                   : fmaxq(tolerance_of(a), tolerance_of(b)));
    if (is_zero(out.difference)) return out;
    out.digits = digits_agreeing(a.exact, b.exact);
    const quad difference = to_quad(out.difference);
    out.relative = static_cast<double>(difference / magnitude);
    if (options.relative_tolerance) {
        out.within = difference <= quad(*options.relative_tolerance) * magnitude;
        return out;
    }
    // Within either side's precision: a type's 2^-p relative, a typed number's
    // half unit in its last digit (exactly: 2·|a − b| ≤ 10^-scale).
    const int k = order_of_twice(out.difference.digits);
    const auto within_side = [&](const DiffNumber& side) {
        if (side.bits > 0) return difference <= ldexpq(1, -side.bits) * magnitude;
        return k <= out.difference.scale - side.scale;
    };
    out.within = within_side(a) || within_side(b);
    return out;
}

char component_name(std::size_t k, const std::string& path, const Vocabulary& vocabulary) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    const bool spatial = entry != nullptr && (entry->kind == "point" || entry->kind == "vector");
    return (spatial ? "xyz" : "rgb")[k];
}

std::vector<std::string> slot_texts(const SideStep* step) {
    std::vector<std::string> texts;
    if (step == nullptr) return texts;
    if (step->non_finite) return {*step->non_finite};
    for (const std::optional<DiffNumber>& slot : step->slots) texts.push_back(slot ? slot->text : "");
    return texts;
}

bool is_point(const std::string& path, const Vocabulary& vocabulary) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    return entry != nullptr && entry->kind == "point";
}

// "(0.1, 0.2, 3)", "[…]", or one number, the language's way; "?" for a component not given.
std::string written(const std::vector<std::string>& texts, bool point, Language language) {
    if (texts.size() == 1) return local_number_text(texts[0], language);
    std::string out = point ? "(" : "[";
    for (std::size_t k = 0; k < texts.size(); ++k)
        out += (k ? coordinate_separator(language) : "") + (texts[k].empty() ? "?" : local_number_text(texts[k], language));
    return out + (point ? ")" : "]");
}

const char* status_name(DiffStatus status) {
    switch (status) {
        case DiffStatus::agree:
            return "agree";
        case DiffStatus::differ:
            return "differ";
        case DiffStatus::shape:
            return "shape";
        case DiffStatus::non_finite:
            return "non-finite";
        case DiffStatus::only_a:
            return "only-a";
        case DiffStatus::only_b:
            return "only-b";
    }
    return "?";
}

// Two significant digits, the language's way: 7.2e-7 (7,2e−7), 0.25, 12.
std::string short_number(double value, Language language) {
    std::string text = fmt::format("{:.2g}", value);
    const std::size_t e = text.find('e');
    if (e != std::string::npos) {
        // 6e-08 -> 6.0e-8
        std::string mantissa = text.substr(0, e);
        if (mantissa.find('.') == std::string::npos) mantissa += ".0";
        text = mantissa + "e" + std::to_string(std::stoi(text.substr(e + 1)));
    }
    return local_number_text(text, language);
}

std::string symbol_text(const std::string& path, const Vocabulary& vocabulary, Language language) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    if (entry == nullptr) return path;
    const std::string symbol = optional_message(language, "symbol_" + entry->key).value_or(entry->symbol);
    return symbol == path_key(path) ? path : path + " (" + symbol + ")";
}

std::string side_line(const DiffInput& input, const std::string& label, Language language) {
    MessageArgs args = {{"label", label}, {"file", input.file}};
    if (const std::optional<TraceSummary>& trace = input.answers.trace) {
        const LessonPixel pixel = input.answers.pixels.front().pixel;
        args.emplace_back("pixel", message(language, "pixel_label", {{"i", std::to_string(pixel.i)}, {"j", std::to_string(pixel.j)}}));
        args.emplace_back("real", trace->real);
        args.emplace_back("formula", trace->formula.empty() ? "?" : trace->formula);
        args.emplace_back("branch", trace->branch.empty() ? "?" : trace->branch + (trace->hit.empty() ? "" : " (" + trace->hit + ")"));
        return message(language, "diff_side_trace", args);
    }
    return message(language, "diff_side_typed", args);
}

}  // namespace

std::optional<int> real_type_bits(const std::string& real) {
    if (real == "float") return 24;
    if (real == "double") return 53;
    if (real == "long-double") return std::numeric_limits<long double>::digits;
    if (real == "quad") return 113;
    return std::nullopt;
}

std::optional<int> digits_agreeing(const TypedNumber& a, const TypedNumber& b) {
    const TypedNumber difference = absolute_difference(a, b);
    if (is_zero(difference)) return std::nullopt;
    const TypedNumber& larger = compare_magnitude(a, b) >= 0 ? a : b;
    // The largest n with 2·|a − b| ≤ 10^(e − n + 1), e the exponent of the
    // larger's leading digit: |a − b| = D·10^-s, 2·D ≤ 10^k, n = e + 1 + s − k.
    const int n = leading_exponent(larger) + 1 + difference.scale - order_of_twice(difference.digits);
    return std::max(n, 0);
}

DiffResult diff_inputs(const DiffInput& a, const DiffInput& b, const Vocabulary& vocabulary, const DiffOptions& options,
                       Language language) {
    DiffResult result;
    if (a.answers.trace)
        result.pixel = a.answers.pixels.front().pixel;
    else if (b.answers.trace)
        result.pixel = b.answers.pixels.front().pixel;
    else
        for (const DiffInput* input : {&a, &b}) {
            // Two students' files: each may head one pixel at most.
            std::vector<LessonPixel> headed;
            for (const PixelAnswers& section : input->answers.pixels)
                if (!same_pixel(section.pixel, diff_first_pixel)) headed.push_back(section.pixel);
            if (headed.size() > 1)
                throw InputError(input->file, "", message(language, "diff_error_pixels"));
        }
    const Side side_a = side_of(a, result.pixel), side_b = side_of(b, result.pixel);
    const bool b_leads = !a.answers.trace && b.answers.trace;
    std::size_t compared = 0;
    for (const std::string& path : b_leads ? merged_order(side_b, side_a) : merged_order(side_a, side_b)) {
        if ((compared++ & 4095) == 0) throw_if_interrupted();
        const SideStep* in_a = side_a.find(path);
        const SideStep* in_b = side_b.find(path);
        DiffStep step;
        step.path = path;
        step.a_text = in_a ? written(slot_texts(in_a), is_point(path, vocabulary), Language::en) : "";
        step.b_text = in_b ? written(slot_texts(in_b), is_point(path, vocabulary), Language::en) : "";
        if (!in_a || !in_b) {
            step.status = in_a ? DiffStatus::only_a : DiffStatus::only_b;
        } else if (in_a->non_finite || in_b->non_finite) {
            ++result.common;
            step.status = in_a->non_finite == in_b->non_finite ? DiffStatus::agree : DiffStatus::non_finite;
        } else if (in_a->slots.size() != in_b->slots.size()) {
            ++result.common;
            step.status = DiffStatus::shape;
        } else {
            ++result.common;
            for (std::size_t k = 0; k < in_a->slots.size(); ++k) {
                if (!in_a->slots[k] || !in_b->slots[k]) continue;
                const char component = in_a->slots.size() == 3 ? component_name(k, path, vocabulary) : 0;
                step.components.push_back(compare(component, *in_a->slots[k], *in_b->slots[k], options));
            }
            const bool within = std::all_of(step.components.begin(), step.components.end(),
                                            [](const DiffComponent& c) { return c.within; });
            step.status = within ? DiffStatus::agree : DiffStatus::differ;
        }
        const bool differs = step.status == DiffStatus::differ || step.status == DiffStatus::shape ||
                             step.status == DiffStatus::non_finite;
        if (differs && !result.first) result.first = result.steps.size();
        result.steps.push_back(std::move(step));
    }
    return result;
}

std::string diff_report(const DiffResult& result, const DiffInput& a, const DiffInput& b, const DiffOptions& options,
                        const Vocabulary& vocabulary, Language language) {
    std::string out = side_line(a, "A", language) + "\n" + side_line(b, "B", language) + "\n";
    const std::optional<TraceSummary>&ta = a.answers.trace, &tb = b.answers.trace;
    if (ta && tb) {
        const LessonPixel pa = a.answers.pixels.front().pixel, pb = b.answers.pixels.front().pixel;
        if (!same_pixel(pa, pb)) out += message(language, "diff_other_pixels") + "\n";
        // Said before the branches: two scenes' (or panes') steps need not agree at all.
        if (!ta->scene_hash.empty() && !tb->scene_hash.empty() && ta->scene_hash != tb->scene_hash) {
            const bool same_name = ta->scene == tb->scene;
            const auto named = [same_name](const TraceSummary& t) {
                return "\"" + t.scene + "\"" + (same_name ? " (" + t.scene_hash.substr(0, 12) + ")" : "");
            };
            out += message(language, "diff_other_scene", {{"a", named(*ta)}, {"b", named(*tb)}}) + "\n";
        }
        if (ta->w > 0 && tb->w > 0 && ta->w != tb->w)
            out += message(language, "diff_other_w", {{"a", std::to_string(ta->w)}, {"b", std::to_string(tb->w)}}) + "\n";
        if (ta->branch != tb->branch || ta->hit != tb->hit)
            out += message(language, "diff_branches",
                           {{"a", ta->branch + (ta->hit.empty() ? "" : " (" + ta->hit + ")")},
                            {"b", tb->branch + (tb->hit.empty() ? "" : " (" + tb->hit + ")")}}) + "\n";
    }
    if (options.relative_tolerance) {
        out += message(language, "diff_tolerance_relative", {{"tol", short_number(*options.relative_tolerance, language)}}) + "\n";
    } else {
        // The less precise trace's type, and whether a side is typed.
        std::optional<std::pair<int, std::string>> coarsest;
        bool typed = false;
        for (const DiffInput* input : {&a, &b}) {
            if (!input->answers.trace) {
                typed = true;
                continue;
            }
            const std::string& real = input->answers.trace->real;
            const int bits = real_type_bits(real).value_or(53);
            if (!coarsest || bits < coarsest->first) coarsest.emplace(bits, real);
        }
        MessageArgs args;
        if (coarsest)
            args = {{"type", coarsest->second},
                    {"bits", std::to_string(coarsest->first)},
                    {"value", short_number(std::ldexp(1.0, -coarsest->first), language)}};
        out += message(language, !coarsest ? "diff_tolerance_typed" : typed ? "diff_tolerance_mixed" : "diff_tolerance_type", args) + "\n";
    }

    std::size_t width = 0;
    for (const DiffStep& step : result.steps) width = std::max(width, display_width(symbol_text(step.path, vocabulary, language)));
    out += "\n" + message(language, "diff_heading") + "\n";
    const std::string all = message(language, "diff_all");
    for (std::size_t s = 0; s < result.steps.size(); ++s) {
        const DiffStep& step = result.steps[s];
        if (step.status == DiffStatus::only_a || step.status == DiffStatus::only_b) {
            // Consecutive steps of one side only, on one line.
            std::string paths;
            const DiffStatus status = step.status;
            for (; s < result.steps.size() && result.steps[s].status == status; ++s)
                paths += (paths.empty() ? "" : ", ") + result.steps[s].path;
            --s;
            out += "  " + message(language, "diff_only", {{"label", status == DiffStatus::only_a ? "A" : "B"},
                                                           {"file", status == DiffStatus::only_a ? a.file : b.file},
                                                           {"steps", paths}}) + "\n";
            continue;
        }
        std::string what;
        const bool point = is_point(step.path, vocabulary);
        if (step.status == DiffStatus::shape || step.status == DiffStatus::non_finite) {
            what = message(language, step.status == DiffStatus::shape ? "diff_shape" : "diff_non_finite",
                           {{"a", written({step.a_text}, point, language)}, {"b", written({step.b_text}, point, language)}});
        } else if (!step.components.empty() || step.status == DiffStatus::agree) {
            for (const DiffComponent& c : step.components) {
                const std::string digits = c.digits ? std::to_string(*c.digits) : all;
                what += (what.empty() ? "" : ", ") + (c.component ? std::string(1, c.component) + " " : "") + digits;
            }
            if (step.components.empty()) what = all;  // the same NaN or infinity
        }
        const std::string name = symbol_text(step.path, vocabulary, language);
        const std::string mark = step.status == DiffStatus::agree ? "  " : "✗ ";
        out += fmt::format("{}{}{}  {}\n", mark, name, std::string(width - std::min(width, display_width(name)), ' '), what);
    }
    out += "\n";
    if (!result.first) {
        out += message(language, result.common == 0 ? "diff_nothing_common" : "diff_agree",
                       {{"count", std::to_string(result.common)}}) + "\n";
        return out;
    }
    const DiffStep& first = result.steps[*result.first];
    const std::string name = symbol_text(first.path, vocabulary, language);
    const bool point = is_point(first.path, vocabulary);
    if (first.status != DiffStatus::differ) {
        out += message(language, "diff_first_other",
                       {{"step", name}, {"a", written({first.a_text}, point, language)}, {"b", written({first.b_text}, point, language)}}) + "\n";
        return out;
    }
    for (const DiffComponent& c : first.components) {
        if (c.within) continue;
        out += message(language, "diff_first",
                       {{"step", name + (c.component ? std::string(".") + c.component : "")},
                        {"a", local_number_text(c.a.text, language)},
                        {"b", local_number_text(c.b.text, language)},
                        {"abs", short_number(static_cast<double>(to_quad(c.difference)), language)},
                        {"rel", short_number(c.relative, language)},
                        {"digits", c.digits ? std::to_string(*c.digits) : all},
                        {"tol", short_number(c.tolerance, language)}}) + "\n";
        break;
    }
    return out;
}

std::string diff_json(const DiffResult& result, const DiffInput& a, const DiffInput& b, const DiffOptions& options) {
    using OrderedJson = nlohmann::ordered_json;
    const auto side = [](const DiffInput& input) {
        OrderedJson out = {{"file", input.file}, {"kind", input.answers.trace ? "trace" : "typed"}};
        if (const std::optional<TraceSummary>& trace = input.answers.trace) {
            const LessonPixel pixel = input.answers.pixels.front().pixel;
            out["pixel"] = {{"i", pixel.i}, {"j", pixel.j}};
            out["real"] = trace->real;
            out["formula"] = trace->formula;
            out["branch"] = trace->branch;
            if (!trace->hit.empty()) out["hit"] = trace->hit;
        }
        return out;
    };
    const auto text_of = [](const TypedNumber& number) { return is_zero(number) ? std::string("0") : typed_number_text(number, Language::en); };
    OrderedJson steps = OrderedJson::array();
    for (const DiffStep& step : result.steps) {
        OrderedJson item = {{"path", step.path}, {"status", status_name(step.status)}};
        if (!step.a_text.empty()) item["a"] = step.a_text;
        if (!step.b_text.empty()) item["b"] = step.b_text;
        if (step.status == DiffStatus::agree || step.status == DiffStatus::differ) {
            OrderedJson components = OrderedJson::array();
            for (const DiffComponent& c : step.components) {
                OrderedJson component;
                if (c.component) component["component"] = std::string(1, c.component);
                component["a"] = c.a.text;
                component["b"] = c.b.text;
                component["digits"] = c.digits ? OrderedJson(*c.digits) : OrderedJson(nullptr);
                component["difference"] = text_of(c.difference);
                component["relative"] = c.relative;
                component["tolerance"] = c.tolerance;
                component["within"] = c.within;
                components.push_back(component);
            }
            item["components"] = components;
        }
        steps.push_back(item);
    }
    OrderedJson out = {{"diff", 1}, {"a", side(a)}, {"b", side(b)}};
    out["tolerance"] = options.relative_tolerance ? OrderedJson({{"relative", *options.relative_tolerance}})
                                                  : OrderedJson({{"precision", "less precise side"}});
    out["steps"] = steps;
    out["common"] = result.common;
    out["first_divergence"] = result.first ? OrderedJson(result.steps[*result.first].path) : OrderedJson(nullptr);
    out["agree"] = !result.first.has_value();
    return out.dump() + "\n";
}

}  // namespace promyk
