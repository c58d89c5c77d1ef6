#include "lesson/answers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/intensity_formula.hpp"
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

// `text` in lines of at most 80 columns, the first starting at column
// `first`, the others indented by `indent` (a lesson's keys make a long line).
std::string wrapped(const std::string& text, std::size_t first, std::size_t indent) {
    constexpr std::size_t columns = 80;
    std::string out;
    std::size_t used = first;
    for (std::size_t k = 0; k < text.size();) {
        const std::size_t space = std::min(text.find(' ', k), text.size());
        const std::string word = text.substr(k, space - k);
        k = space + 1;
        if (word.empty()) continue;
        if (!out.empty() && used + 1 + display_width(word) > columns) {
            out += "\n" + std::string(indent, ' ');
            used = indent;
        } else if (!out.empty()) {
            out += ' ';
            ++used;
        }
        out += word;
        used += display_width(word);
    }
    return out;
}

bool is_right(Verdict verdict) {
    return verdict == Verdict::right || verdict == Verdict::right_more_digits || verdict == Verdict::right_nearer;
}

// A number's exact value in its own type: a double's binary value, or a
// float's, long double's or quad's read back from its exact text. Nothing
// for a non-finite one.
std::optional<TypedNumber> exact_of(const LessonNumber& number) {
    const double approximate = std::get<double>(number.value);
    if (!std::isfinite(approximate)) return std::nullopt;
    if (number.real_text.empty()) return exact_decimal(approximate);
    const RealType type = number.real == "float"         ? RealType::float_
                          : number.real == "long-double" ? RealType::long_double
                          : number.real == "quad"        ? RealType::quad_
                                                         : RealType::double_;
    if (std::optional<TypedNumber> exact = exact_value_of(number.real_text.front(), type)) return exact;
    return exact_decimal(approximate);
}

// p/q at least as near `exact` as `computed` is: |p − q·exact| ≤ q·|computed − exact|.
bool at_least_as_near(const TypedNumber& p, const TypedNumber& q, const TypedNumber& computed, const TypedNumber& exact) {
    return compare_magnitude(absolute_difference(p, multiply(q, exact)), multiply(q, absolute_difference(computed, exact))) <= 0;
}

// A fraction p/q: right when it is the computed value, right_nearer when it
// lies at least as near the exact value, else wrong.
Verdict judge_fraction(const TypedNumber& p, const TypedNumber& q, const TypedNumber& computed, const TypedNumber& exact) {
    if (is_zero(absolute_difference(p, multiply(q, computed)))) return Verdict::right;
    return at_least_as_near(p, q, computed, exact) ? Verdict::right_nearer : Verdict::wrong;
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
        out += (k ? coordinate_separator(language) : "") + typed_number_text(numbers[k], language);
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

int digits_held(const std::string& real) {
    if (real == "float") return std::numeric_limits<float>::digits10;
    if (real == "long-double") return std::numeric_limits<long double>::digits10;
    if (real == "quad") return 33;  // FLT128_DIG
    return std::numeric_limits<double>::digits10;
}

int significant_digits(const TypedNumber& number) {
    const std::string digits = strip_zeros(number.digits);
    return digits == "0" ? 0 : static_cast<int>(digits.size());
}

std::string exact_settings(const std::string& settings) {
    const std::optional<SettingsQualifier> qualifier = parse_settings(settings);
    return qualifier && !qualifier->formula.empty() ? "quad," + qualifier->formula : "quad";
}

std::vector<AnswerCheck> check_answers(const std::vector<PixelAnswers>& answers, const std::vector<PixelTrace>& traces,
                                       const std::vector<PixelTrace>& others) {
    const Vocabulary& vocabulary = builtin_vocabulary();
    std::vector<AnswerCheck> checks;
    const TraceIndex trace_of(traces);
    for (const PixelAnswers& pixel : answers) {
        const PixelTrace* trace = trace_of(pixel.pixel);
        if (trace == nullptr) throw std::logic_error("check_answers: no trace for an answered pixel");
        // Unreadable answers last, in the file's order.
        std::vector<std::pair<std::size_t, const Answer*>> sorted;
        for (const Answer& answer : pixel.answers)
            sorted.emplace_back(answer.unreadable.empty() ? derivation_rank(*trace, vocabulary, answer.key)
                                                          : std::numeric_limits<std::size_t>::max(),
                                &answer);
        std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [rank, answer_of] : sorted) {
            const Answer& answer = *answer_of;
            AnswerCheck check{pixel.pixel, answer, Verdict::right, {}};
            if (!answer.unreadable.empty()) {
                check.verdict = Verdict::unreadable;
                checks.push_back(std::move(check));
                continue;
            }
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
                // The exact value: the same pixel and formula in quad, when it was traced.
                const auto [path, settings] = split_settings(answer.key);
                const std::optional<LessonNumber> exact_number =
                    lesson_number(*trace, qualified_path(path, 0, exact_settings(settings)), others);
                const auto components = [&](const LessonNumber& of) {
                    return vector_key && answer.component == 0
                               ? std::vector<LessonNumber>{component_of(of, 'x'), component_of(of, 'y'), component_of(of, 'z')}
                               : std::vector<LessonNumber>{component_of(of, answer.component)};
                };
                const std::vector<LessonNumber> reference = components(*number);
                const std::vector<LessonNumber> truth =
                    exact_number && exact_number->value.index() == number->value.index() ? components(*exact_number)
                                                                                         : std::vector<LessonNumber>{};
                std::vector<Verdict> verdicts;
                for (std::size_t k = 0; k < reference.size(); ++k) {
                    TypedNumber expected;
                    const std::optional<TypedNumber> computed = exact_of(reference[k]);
                    const std::optional<TypedNumber> exact = truth.empty() ? computed : exact_of(truth[k]);
                    const TypedNumber* over = answer.over.empty() || answer.over[k].digits.empty() ? nullptr : &answer.over[k];
                    if (!computed) {
                        verdicts.push_back(Verdict::wrong);
                    } else if (over != nullptr) {
                        expected = *computed;
                        verdicts.push_back(judge_fraction(answer.numbers[k], *over, *computed, exact.value_or(*computed)));
                        check.needs_exact = check.needs_exact || (truth.empty() && verdicts.back() == Verdict::wrong);
                    } else {
                        Verdict verdict = compare_number(*computed, answer.numbers[k], expected);
                        // More digits than the type holds: judged by the distance to the exact value.
                        if (verdict != Verdict::right && significant_digits(answer.numbers[k]) > digits_held(reference[k].real)) {
                            if (exact && at_least_as_near(answer.numbers[k], TypedNumber{false, "1", 0}, *computed, *exact))
                                verdict = Verdict::right_more_digits;
                            check.needs_exact = check.needs_exact || (truth.empty() && !is_right(verdict));
                        }
                        verdicts.push_back(verdict);
                    }
                    check.expected.push_back(expected);
                }
                // The worst of the numbers' verdicts.
                for (const Verdict verdict : {Verdict::wrong, Verdict::wrong_way, Verdict::right_nearer, Verdict::right_more_digits})
                    if (std::find(verdicts.begin(), verdicts.end(), verdict) != verdicts.end()) {
                        check.verdict = verdict;
                        break;
                    }
            }
            checks.push_back(std::move(check));
        }
    }
    return checks;
}

bool all_right(const std::vector<AnswerCheck>& checks) {
    return std::all_of(checks.begin(), checks.end(),
                       [](const AnswerCheck& c) { return is_right(c.verdict) || c.verdict == Verdict::blank; });
}

AnswerMark answer_mark(const AnswerCheck& check, const PixelTrace* trace, const Vocabulary& vocabulary, Language language,
                       const std::vector<PixelTrace>& others) {
    const std::string pixel = message(language, "pixel_label", {{"i", std::to_string(check.pixel.i)}, {"j", std::to_string(check.pixel.j)}});
    AnswerMark mark;
    if (check.verdict == Verdict::unreadable) {
        // Where it stands and what it says, since its key may be unknown.
        const Answer& answer = check.answer;
        const auto [path, settings] = split_settings(answer.key);
        const std::string where =
            answer.pointer.empty() ? message(language, "answers_line", {{"line", std::to_string(answer.line)}}) : answer.pointer;
        const std::string text =
            answer.key.empty() ? answer.text : qualified_path(path, answer.component, settings) + " = " + answer.text;
        mark.id = "answers_unreadable";
        mark.text = message(language, mark.id, {{"where", where}, {"text", text}, {"reason", answer.unreadable}});
        return mark;
    }
    const std::optional<LessonNumber> number = trace ? lesson_number(*trace, check.answer.key, others) : std::nullopt;
    const std::string kind =
        kind_of(vocabulary, check.answer, number ? std::optional<StepValue>(number->value) : std::nullopt);
    MessageArgs args = {{"symbol", symbol_of(vocabulary, check.answer, language)}, {"typed", check.answer.text}, {"pixel", pixel}};
    switch (check.verdict) {
        case Verdict::right:
            mark.id = "answers_right";
            break;
        case Verdict::right_more_digits:
        case Verdict::right_nearer:
            mark.id = check.verdict == Verdict::right_more_digits ? "answers_right_more_digits" : "answers_right_nearer";
            args.emplace_back("real", message(language, "answers_real_" + (number ? number->real : std::string("double"))));
            break;
        case Verdict::unreadable:
            break;
        case Verdict::blank:
            mark.id = "answers_blank";
            break;
        case Verdict::not_reached:
            mark.id = "answers_not_reached";
            break;
        case Verdict::wrong_shape:
            mark.id = kind == "scalar" ? "answers_shape_one" : "answers_shape_three";
            break;
        case Verdict::wrong:
        case Verdict::wrong_way: {
            mark.id = !check.answer.over.empty()      ? "answers_wrong_fraction"
                      : check.verdict == Verdict::wrong ? "answers_wrong"
                                                        : "answers_wrong_way";
            const LessonNumber exact = component_of(*number, check.answer.component);
            const bool finite = std::all_of(check.expected.begin(), check.expected.end(),
                                            [](const TypedNumber& n) { return !n.digits.empty(); });
            const std::string exact_text = lesson_number_text(exact, kind, language);
            args.emplace_back("expected", finite ? numbers_text(check.expected, kind, language) : exact_text);
            args.emplace_back("exact", exact_text);
            break;
        }
    }
    mark.text = message(language, mark.id, args);
    return mark;
}

std::string answers_report(const std::vector<AnswerCheck>& checks, const std::vector<PixelTrace>& traces,
                           const Vocabulary& vocabulary, Language language, const std::vector<PixelTrace>& others) {
    std::string out;
    int right = 0, wrong = 0, blank = 0, unreadable = 0;
    std::optional<LessonPixel> current;
    const TraceIndex trace_of(traces);
    for (const AnswerCheck& check : checks) {
        const PixelTrace* trace = trace_of(check.pixel);
        const std::string pixel = message(language, "pixel_label", {{"i", std::to_string(check.pixel.i)}, {"j", std::to_string(check.pixel.j)}});
        if (!current || current->i != check.pixel.i || current->j != check.pixel.j) {
            current = check.pixel;
            out += (out.empty() ? "" : "\n") +
                   message(language, "answers_pixel",
                           {{"pixel", pixel},
                            {"branch", branch_named(vocabulary, trace->branch, effect_set(*trace), language)}}) +
                   "\n";
        }
        const AnswerMark mark = answer_mark(check, trace, vocabulary, language, others);
        if (check.verdict == Verdict::unreadable) ++unreadable;
        else if (check.verdict == Verdict::blank) ++blank;
        else if (is_right(check.verdict)) ++right;
        else ++wrong;
        // The older verdicts' lines are kept as they were; the new ones fit 80 columns.
        const bool wrap = mark.id == "answers_unreadable" || mark.id == "answers_right_more_digits" ||
                          mark.id == "answers_right_nearer" || mark.id == "answers_wrong_fraction";
        out += "  " + (wrap ? wrapped(mark.text, 2, 4) : mark.text) + "\n";
    }
    out += "\n" + message(language, "answers_summary",
                          {{"right", std::to_string(right)}, {"count", std::to_string(right + wrong + unreadable)},
                           {"wrong", std::to_string(wrong)}, {"blank", std::to_string(blank)}});
    if (unreadable > 0) out += " " + message(language, "answers_summary_unreadable", {{"unreadable", std::to_string(unreadable)}});
    return out + "\n";
}

}  // namespace promyk
