#include "lesson/answers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"
#include "util/text.hpp"

namespace promyk {

namespace {

// --- exact decimals (math/decimal.hpp) ---------------------------------

std::string plus_one(std::string digits) {
    for (std::size_t k = digits.size(); k-- > 0;) {
        if (digits[k] != '9') {
            ++digits[k];
            return digits;
        }
        digits[k] = '0';
    }
    return "1" + digits;
}

struct Rounded {
    TypedNumber nearest;               // halves away from zero
    std::optional<TypedNumber> other;  // the other neighbour, when the value is not exact at this scale
};

Rounded round_to(const TypedNumber& exact, int scale) {
    std::string digits = exact.digits;
    const int exact_scale = exact.scale;
    Rounded out;
    out.nearest.negative = exact.negative;
    out.nearest.scale = scale;
    if (scale >= exact_scale) {
        out.nearest.digits = digits + std::string(static_cast<std::size_t>(scale - exact_scale), '0');
        return out;
    }
    const std::size_t drop = static_cast<std::size_t>(exact_scale - scale);
    if (digits.size() < drop + 1) digits.insert(0, drop + 1 - digits.size(), '0');
    const std::string kept = digits.substr(0, digits.size() - drop);
    const std::string rest = digits.substr(digits.size() - drop);
    const bool up = rest[0] >= '5';
    out.nearest.digits = up ? plus_one(kept) : kept;
    if (rest.find_first_not_of('0') != std::string::npos) {
        out.other = out.nearest;
        out.other->digits = up ? kept : plus_one(kept);
    }
    return out;
}

bool same_number(const TypedNumber& a, const TypedNumber& b) {
    const std::string x = strip_zeros(a.digits), y = strip_zeros(b.digits);
    return x == y && (x == "0" || a.negative == b.negative);
}

std::string symbol_of(const Vocabulary& vocabulary, const Answer& answer, Language language) {
    const VocabularyEntry* entry = vocabulary.find(path_key(answer.key));
    const auto [path, settings] = split_settings(answer.key);
    std::string symbol = entry ? optional_message(language, "symbol_" + entry->key).value_or(entry->symbol) : path;
    if (answer.component != 0) symbol += std::string(".") + answer.component;
    const std::string key = qualified_path(path, answer.component, settings);
    return symbol == key ? symbol : symbol + " (" + key + ")";
}

// As the value is written: a point, a vector, a colour (three numbers where
// one is meant: I_P and a light's contribution in a coloured scene) or one number.
std::string kind_of(const Vocabulary& vocabulary, const Answer& answer, const std::optional<StepValue>& value) {
    if (answer.component != 0) return "scalar";
    const VocabularyEntry* entry = vocabulary.find(path_key(answer.key));
    const std::string kind = entry ? entry->kind : "scalar";
    if (value && std::holds_alternative<Vec3d>(*value) && kind != "point" && kind != "vector") return "colour";
    return kind;
}

std::string numbers_text(const std::vector<TypedNumber>& numbers, const std::string& kind, Language language) {
    if (numbers.size() == 1) return typed_number_text(numbers[0], language);
    std::string out = kind == "point" ? "(" : "[";
    for (std::size_t k = 0; k < numbers.size(); ++k)
        out += (k ? (language == Language::pl ? "; " : ", ") : "") + typed_number_text(numbers[k], language);
    return out + (kind == "point" ? ")" : "]");
}

// Each pixel's trace, looked up once a check rather than searched for.
class TraceIndex {
public:
    explicit TraceIndex(const std::vector<PixelTrace>& traces) {
        for (const PixelTrace& trace : traces) index_.emplace(std::make_pair(trace.header.i, trace.header.j), &trace);
    }
    const PixelTrace* operator()(LessonPixel pixel) const {
        const auto it = index_.find({pixel.i, pixel.j});
        return it == index_.end() ? nullptr : it->second;
    }

private:
    std::map<std::pair<int, int>, const PixelTrace*> index_;
};

}  // namespace

TypedNumber round_exactly(double value, int scale) { return round_to(exact_decimal(value), scale).nearest; }

std::string typed_number_text(const TypedNumber& number, Language language) {
    std::string digits = strip_zeros(number.digits);
    std::string text;
    if (number.scale <= 0) {
        text = digits == "0" ? digits : digits + std::string(static_cast<std::size_t>(-number.scale), '0');
    } else {
        const std::size_t scale = static_cast<std::size_t>(number.scale);
        if (digits.size() < scale + 1) digits.insert(0, scale + 1 - digits.size(), '0');
        text = digits.substr(0, digits.size() - scale) + (language == Language::pl ? "," : ".") + digits.substr(digits.size() - scale);
    }
    if (number.negative && strip_zeros(number.digits) != "0") text = (language == Language::pl ? "\u2212" : "-") + text;
    return text;
}

Verdict compare_number(double reference, const TypedNumber& typed, TypedNumber& expected) {
    if (!std::isfinite(reference)) {
        expected = TypedNumber{};
        return Verdict::wrong;
    }
    return compare_number(exact_decimal(reference), typed, expected);
}

Verdict compare_number(const TypedNumber& reference, const TypedNumber& typed, TypedNumber& expected) {
    const Rounded rounded = round_to(reference, typed.scale);
    expected = rounded.nearest;
    if (same_number(typed, rounded.nearest)) return Verdict::right;
    if (rounded.other && same_number(typed, *rounded.other)) return Verdict::wrong_way;
    return Verdict::wrong;
}

std::vector<AnswerCheck> check_answers(const std::vector<PixelAnswers>& answers, const std::vector<PixelTrace>& traces,
                                       const std::vector<PixelTrace>& others) {
    const Vocabulary& vocabulary = builtin_vocabulary();
    std::vector<AnswerCheck> checks;
    const TraceIndex trace_of(traces);
    for (const PixelAnswers& pixel : answers) {
        const PixelTrace* trace = trace_of(pixel.pixel);
        if (trace == nullptr) throw std::logic_error("check_answers: no trace for an answered pixel");
        std::vector<std::pair<std::size_t, const Answer*>> sorted;
        for (const Answer& answer : pixel.answers) sorted.emplace_back(derivation_rank(*trace, vocabulary, answer.key), &answer);
        std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [rank, answer_of] : sorted) {
            const Answer& answer = *answer_of;
            AnswerCheck check{pixel.pixel, answer, Verdict::right, {}};
            const std::optional<LessonNumber> number = lesson_number(*trace, answer.key, others);
            const std::optional<StepValue> value = number ? std::optional<StepValue>(number->value) : std::nullopt;
            // Three numbers for a point, a vector or a colour; one for a number or a component.
            const bool vector_key = value && std::holds_alternative<Vec3d>(*value);
            const std::size_t wanted = vector_key && answer.component == 0 ? 3 : 1;
            if (answer.numbers.empty()) {
                check.verdict = Verdict::blank;
            } else if (!value || std::holds_alternative<std::string>(*value)) {
                check.verdict = Verdict::not_reached;
            } else if (answer.numbers.size() != wanted || (answer.component != 0 && !vector_key)) {
                check.verdict = Verdict::wrong_shape;
            } else {
                // Each number's exact value in the trace's own type: a double's
                // binary value, or a float's, long double's or quad's read back
                // from its exact text.
                std::vector<LessonNumber> reference;
                if (vector_key && answer.component == 0)
                    reference = {component_of(*number, 'x'), component_of(*number, 'y'), component_of(*number, 'z')};
                else
                    reference = {component_of(*number, answer.component)};
                bool any_wrong = false, any_wrong_way = false;
                for (std::size_t k = 0; k < reference.size(); ++k) {
                    TypedNumber expected;
                    const double approximate = std::get<double>(reference[k].value);
                    std::optional<TypedNumber> exact;
                    if (!reference[k].real_text.empty() && std::isfinite(approximate)) {
                        const std::string& real = reference[k].real;
                        const RealType type = real == "float" ? RealType::float_
                                              : real == "long-double" ? RealType::long_double
                                              : real == "quad" ? RealType::quad_ : RealType::double_;
                        exact = exact_value_of(reference[k].real_text.front(), type);
                    }
                    const Verdict verdict = exact ? compare_number(*exact, answer.numbers[k], expected)
                                                  : compare_number(approximate, answer.numbers[k], expected);
                    any_wrong = any_wrong || verdict == Verdict::wrong;
                    any_wrong_way = any_wrong_way || verdict == Verdict::wrong_way;
                    check.expected.push_back(expected);
                }
                check.verdict = any_wrong ? Verdict::wrong : any_wrong_way ? Verdict::wrong_way : Verdict::right;
            }
            checks.push_back(std::move(check));
        }
    }
    return checks;
}

bool all_right(const std::vector<AnswerCheck>& checks) {
    return std::all_of(checks.begin(), checks.end(),
                       [](const AnswerCheck& c) { return c.verdict == Verdict::right || c.verdict == Verdict::blank; });
}

std::string answers_report(const std::vector<AnswerCheck>& checks, const std::vector<PixelTrace>& traces,
                           const Vocabulary& vocabulary, Language language, const std::vector<PixelTrace>& others) {
    std::string out;
    int right = 0, wrong = 0, blank = 0;
    std::optional<LessonPixel> current;
    const TraceIndex trace_of(traces);
    for (const AnswerCheck& check : checks) {
        const PixelTrace* trace = trace_of(check.pixel);
        const std::string pixel = message(language, "pixel_label", {{"i", std::to_string(check.pixel.i)}, {"j", std::to_string(check.pixel.j)}});
        if (!current || current->i != check.pixel.i || current->j != check.pixel.j) {
            current = check.pixel;
            const BranchEntry* branch = vocabulary.find_branch(branch_name(trace->branch));
            out += (out.empty() ? "" : "\n") +
                   message(language, "answers_pixel",
                           {{"pixel", pixel},
                            {"branch", branch ? (language == Language::pl ? branch->pl : branch->en) : std::string(branch_name(trace->branch))}}) +
                   "\n";
        }
        const std::optional<LessonNumber> number = lesson_number(*trace, check.answer.key, others);
        const std::string kind =
            kind_of(vocabulary, check.answer, number ? std::optional<StepValue>(number->value) : std::nullopt);
        MessageArgs args = {{"symbol", symbol_of(vocabulary, check.answer, language)}, {"typed", check.answer.text}, {"pixel", pixel}};
        std::string id;
        switch (check.verdict) {
            case Verdict::right:
                id = "answers_right";
                ++right;
                break;
            case Verdict::blank:
                id = "answers_blank";
                ++blank;
                break;
            case Verdict::not_reached:
                id = "answers_not_reached";
                ++wrong;
                break;
            case Verdict::wrong_shape:
                id = kind == "scalar" ? "answers_shape_one" : "answers_shape_three";
                ++wrong;
                break;
            case Verdict::wrong:
            case Verdict::wrong_way: {
                id = check.verdict == Verdict::wrong ? "answers_wrong" : "answers_wrong_way";
                ++wrong;
                const LessonNumber exact = component_of(*number, check.answer.component);
                const bool finite = std::all_of(check.expected.begin(), check.expected.end(),
                                                [](const TypedNumber& n) { return !n.digits.empty(); });
                const std::string exact_text = lesson_number_text(exact, kind, language);
                args.emplace_back("expected", finite ? numbers_text(check.expected, kind, language) : exact_text);
                args.emplace_back("exact", exact_text);
                break;
            }
        }
        out += "  " + message(language, id, args) + "\n";
    }
    out += "\n" + message(language, "answers_summary",
                          {{"right", std::to_string(right)}, {"count", std::to_string(right + wrong)},
                           {"wrong", std::to_string(wrong)}, {"blank", std::to_string(blank)}}) + "\n";
    return out;
}

}  // namespace promyk
