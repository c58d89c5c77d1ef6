#include "trace/trace_text.hpp"

#include "trace/intensity_formula.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "trace/digits_alarm.hpp"
#include "trace/digits_lost.hpp"
#include "trace/messages.hpp"
#include "trace/type_example.hpp"
#include "util/interrupt.hpp"
#include "util/text.hpp"
#include "util/wrap.hpp"

namespace promyk {

namespace {

// The scene's numbers in the header's order (each object's and light's in
// turn when there are several), for the closing note's example.
std::vector<double> given_numbers(const TraceHeader& header) {
    std::vector<double> numbers;
    const auto add = [&](const std::vector<GivenValue>& values) {
        for (const GivenValue& given : values) {
            if (const double* x = std::get_if<double>(&given.value)) numbers.push_back(*x);
            if (const Vec3d* v = std::get_if<Vec3d>(&given.value)) numbers.insert(numbers.end(), {v->x, v->y, v->z});
        }
    };
    add(header.given);
    for (const GivenGroup& group : header.given_groups) add(group.values);
    return numbers;
}

std::string pad_left(const std::string& text, std::size_t width) {
    return std::string(width - std::min(width, display_width(text)), ' ') + text;
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
        if (width > indent && width + display_width(piece) > text_columns) {
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

std::string value_of(const StepValue& value, const Vocabulary& vocabulary, const std::string& key, Language language,
                     int digits = 0);

}  // namespace

// The pixel's intensities when they follow from the steps (lit or
// shadowed); empty when the branch fixes the result (background, dark).
std::vector<double> trace_intensities(const PixelTrace& trace) {
    if (trace.branch != Branch::lit && trace.branch != Branch::shadowed && !trace.samples) return {};
    if (trace.result_rgb) return {trace.result_rgb->x, trace.result_rgb->y, trace.result_rgb->z};
    return {trace.result};
}

bool trace_step_alarm(const Step& step, const PixelTrace& trace) {
    return digits_lost_alarm(step.digits_lost, full_digits_of(trace.header.real), trace_intensities(trace));
}

// A step that loses many digits: "⚠ 9.1 digits lost" when the loss matters
// (digits_alarm.hpp), "3.0 digits lost" when it is shown only as a count;
// empty below the count's threshold.
std::string trace_digits_lost_mark(const Step& step, const PixelTrace& trace, Language language) {
    if (std::isnan(step.digits_lost) || !loses_many_digits(step.digits_lost)) return "";
    const std::string text = message(language, "trace_digits_lost_count",
                                     {{"digits", number_text(rounded_digits(step.digits_lost), language, 1)},
                                      {"full", number_text(std::round(full_digits_of(trace.header.real)), language, 0)}});
    return trace_step_alarm(step, trace) ? "⚠ " + text : text;
}

std::string trace_kind(const Vocabulary& vocabulary, const std::string& key);

// A step's value as text, rounded to `digits` significant digits (0: every
// digit): in a real type other than double, from its exact text in that
// type (the Polish way in Polish: a decimal comma); else value_of.
std::string trace_step_value_text(const Step& step, const Vocabulary& vocabulary, const std::string& key,
                            Language language, const std::string& real, int digits) {
    if (step.real_text.empty()) return value_of(step.value, vocabulary, key, language, digits);
    const RealType type = real == "float" ? RealType::float_ : real == "long-double" ? RealType::long_double : RealType::quad_;
    auto local = [&](const std::string& text) { return shown_real_text(text, type, language, digits); };
    if (step.real_text.size() == 1) return local(step.real_text.front());
    const std::string kind = trace_kind(vocabulary, key);
    const char* separator = coordinate_separator(language);
    const bool vector = kind == "vector" || kind == "colour";
    std::string out = vector ? "[" : "(";
    for (std::size_t k = 0; k < step.real_text.size(); ++k)
        out += (k ? separator : "") + local(step.real_text[k]);
    return out + (vector ? "]" : ")");
}

// A key's symbol in the language: the vocabulary's, unless messages have a
// "symbol_KEY" for the language (the symbols that are English words:
// background, found, nearest, flipped, blocker).
std::string trace_symbol(const Vocabulary& vocabulary, const std::string& key, Language language) {
    if (std::optional<std::string> own = optional_message(language, "symbol_" + key)) return *own;
    const VocabularyEntry* entry = vocabulary.find(key);
    return entry ? entry->symbol : key;
}

std::string trace_kind(const Vocabulary& vocabulary, const std::string& key) {
    const VocabularyEntry* entry = vocabulary.find(key);
    return entry ? entry->kind : "point";
}

namespace {

std::string header_text(const PixelTrace& trace, const Vocabulary& vocabulary, Language language) {
    const TraceHeader& h = trace.header;
    const std::string file = h.scene_file == "built-in" ? message(language, "trace_builtin") : h.scene_file;
    std::string out = wrap_text(message(language, "trace_pixel",
                              {{"i", std::to_string(h.i)},
                               {"j", std::to_string(h.j)},
                               {"w", std::to_string(h.w)},
                               {"pane", pane_phrase(h.w)},
                               {"scene", h.scene_name},
                               {"file", file}}),
                                2) +
                      "\n";
    out += message(language, "trace_numbers", {{"real", h.real}, {"formula", h.formula}, {"spp", std::to_string(h.spp)}}) +
           "\n";
    const std::string separator = coordinate_separator(language);
    if (!h.skipped.empty() || h.effects.size() != 1 || h.effects.front() != "lambert") {
        // A scene beyond the article's: what the engine ran and what not, and why.
        std::string stages;
        for (const std::string& id : h.effects) stages += (stages.empty() ? "" : separator) + id;
        const std::string lead = message(language, "trace_stages");
        out += wrap(lead, stages, display_width(lead), separator);
        const std::string skipped = message(language, "trace_skipped");
        for (const auto& [id, reason] : h.skipped)
            out += wrap(skipped, id + " — " + message(language, reason), display_width(skipped));
    }
    std::string given;
    for (const GivenValue& value : h.given) {
        given += (given.empty() ? "" : separator) + trace_symbol(vocabulary, value.key, language) + " = " +
                 value_of(value.value, vocabulary, value.key, language);
    }
    const std::string lead = message(language, "trace_given");
    if (!given.empty()) out += wrap(lead, given, display_width(lead), separator);
    for (const GivenGroup& group : h.given_groups) {
        std::string values;
        for (const GivenValue& value : group.values)
            values += (values.empty() ? "" : separator) + trace_symbol(vocabulary, value.key, language) + " = " +
                      value_of(value.value, vocabulary, value.key, language);
        const std::string title = "  " + group_text(language, group.kind, group.index) + ": ";
        out += wrap(title, values, display_width(title), separator);
    }
    return out + '\n';
}

// The chain of groups from the top level down to `group` (empty for -1).
std::vector<int> chain_of(const std::vector<TraceGroup>& groups, int group) {
    std::vector<int> chain;
    for (int g = group; g >= 0; g = groups[static_cast<std::size_t>(g)].parent) chain.insert(chain.begin(), g);
    return chain;
}

// Titles of the groups a step opens ("sphere 1", "light 0"), each on its own
// line, indented two spaces a level; `open` becomes the step's chain.
std::string group_titles(const PixelTrace& trace, const Step& step, std::vector<int>& open, Language language) {
    const std::vector<int> chain = chain_of(trace.groups, step.group);
    std::size_t common = 0;
    while (common < open.size() && common < chain.size() && open[common] == chain[common]) ++common;
    std::string out;
    for (std::size_t k = common; k < chain.size(); ++k) {
        const TraceGroup& group = trace.groups[static_cast<std::size_t>(chain[k])];
        out += std::string(2 * k, ' ') + "▸ " + group_text(language, group.kind, group.index) + "\n";
    }
    open = chain;
    return out;
}

std::string narrow_steps(const PixelTrace& trace, const Vocabulary& vocabulary, const TraceTextOptions& options) {
    std::size_t key_width = 0;
    for (const Step& step : trace.steps) key_width = std::max(key_width, key_name(step.key).size());
    const std::size_t number_width = std::to_string(trace.steps.size()).size();
    std::string out;
    std::vector<int> open;
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        if ((k & 4095) == 0) throw_if_interrupted();  // a trace of millions of steps takes seconds
        const Step& step = trace.steps[k];
        out += group_titles(trace, step, open, options.language);
        const std::string margin(2 * open.size(), ' ');
        const std::size_t indent = margin.size() + number_width + 2 + key_width + 2;
        const std::string key(key_name(step.key));
        const VocabularyEntry* entry = vocabulary.find(key);
        const std::string symbol = trace_symbol(vocabulary, key, options.language);
        const std::string lead = fmt::format("{}{:>{}}  {}", margin, k + 1, number_width, pad(key, key_width + 2));
        const std::string formula = step_formula(entry, key, effect_set(trace));
        out += wrap(lead, !formula.empty() ? symbol + " = " + formula : symbol, indent);
        if (options.explain && entry)
            out += wrap(std::string(indent, ' '), options.language == Language::pl ? entry->pl : entry->en, indent);
        out += wrap(std::string(indent, ' ') + "= ",
                    trace_step_value_text(step, vocabulary, key, options.language, trace.header.real, options.digits),
                    indent + 2,
                    // a word ("behind the eye: ...") breaks at spaces; a Polish vector only after "; "
                    options.language == Language::pl && !std::holds_alternative<std::string>(step.value) ? "; " : " ");
        const std::string mark = trace_digits_lost_mark(step, trace, options.language);
        if (!mark.empty()) out += std::string(indent, ' ') + mark + "\n";
    }
    return out;
}

std::string wide_steps(const PixelTrace& trace, const Vocabulary& vocabulary, const TraceTextOptions& options) {
    struct Row {
        std::string step, key, symbol, formula, value;
    };
    const Language language = options.language;
    std::vector<Row> rows = {{message(language, "trace_column_step"), message(language, "trace_column_key"),
                              message(language, "trace_column_symbol"), message(language, "trace_column_formula"),
                              message(language, "trace_column_value")}};
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        if ((k & 4095) == 0) throw_if_interrupted();
        const Step& step = trace.steps[k];
        // A step in a group is named by its path: "sphere 1 / t".
        std::string key(key_name(step.key));
        const std::string bare = key;
        for (auto it = chain_of(trace.groups, step.group); !it.empty(); it.pop_back()) {
            const TraceGroup& group = trace.groups[static_cast<std::size_t>(it.back())];
            key = group_text(language, group.kind, group.index) + " / " + key;
        }
        const VocabularyEntry* entry = vocabulary.find(bare);
        const std::string mark = trace_digits_lost_mark(step, trace, language);
        rows.push_back({std::to_string(k + 1), key, trace_symbol(vocabulary, bare, language),
                        step_formula(entry, bare, effect_set(trace)),
                        trace_step_value_text(step, vocabulary, bare, language, trace.header.real, options.digits) +
                            (mark.empty() ? "" : "  " + mark)});
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
        out += fmt::format("{}  {}  {}  {}  {}\n", pad_left(row.step, widths[0]), pad(row.key, widths[1]),
                           pad(row.symbol, widths[2]), pad(row.formula, widths[3]), row.value);
    }
    return out;
}

// How the samples went: all in one branch, or how many took each.
std::string samples_text(const SampleSummary& samples, int spp, Language language) {
    std::string counts, only;
    for (int b = 0; b < branch_count; ++b) {
        const int n = samples.branches[static_cast<std::size_t>(b)];
        if (n == 0) continue;
        only = message(language, "branch_name_" + std::string(branch_name(static_cast<Branch>(b))));
        counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + only;
    }
    if (samples.agree())
        return wrap("", message(language, "trace_samples_agree", {{"spp", std::to_string(spp)}, {"branch", only}}), 2);
    return wrap("",
                message(language, "trace_samples_disagree",
                        {{"counts", counts}, {"centre", std::to_string(samples.centre)}, {"spp", std::to_string(spp)}}),
                2);
}

// The steps whose cancellation --formula geometric avoids: the discriminant
// and the roots' numerators of the eye's rays (shadow rays keep their test
// whatever the formula).
bool geometric_avoids(Key key) {
    return key == Key::delta || key == Key::delta_fma || key == Key::t || key == Key::t_far;
}

// When a step loses many digits: what the mark means, and, when the
// discriminant or a root's numerator lost them and the formula is not
// already the geometric one, the suggestion to try it.
std::string digits_lost_notes(const PixelTrace& trace, const Vocabulary& vocabulary, Language language) {
    bool marked = false;
    const Step* worst = nullptr;
    for (const Step& step : trace.steps) {
        if (std::isnan(step.digits_lost) || !loses_many_digits(step.digits_lost) || !trace_step_alarm(step, trace)) continue;
        marked = true;
        if (geometric_avoids(step.key) && (!worst || step.digits_lost > worst->digits_lost)) worst = &step;
    }
    if (!marked) return "";
    std::string out = "\n" + wrap("", message(language, "trace_digits_lost_about",
                                       {{"half", number_text(full_digits_of(trace.header.real) / 2, language, 1)}}),
                           2);
    if (worst && trace.header.formula != "geometric") {
        const std::string key(key_name(worst->key));
        out += wrap("", message(language, "trace_suggest_geometric",
                                {{"symbol", trace_symbol(vocabulary, key, language)},
                                 {"digits", number_text(rounded_digits(worst->digits_lost), language, 1)},
                                 {"formula", trace.header.formula}}),
                    2);
    }
    return out;
}

// The value of a vocabulary key among the top-level steps (nothing when
// the trace lacks it or it is not a number).
std::optional<double> top_level_number(const PixelTrace& trace, Key key) {
    for (const Step& step : trace.steps)
        if (step.key == key && step.group < 0)
            if (const double* value = std::get_if<double>(&step.value)) return *value;
    return std::nullopt;
}

std::string footer_text(const PixelTrace& trace, const Vocabulary& vocabulary, const TraceTextOptions& options) {
    const Language language = options.language;
    const std::string branch(branch_name(trace.branch));
    const std::string branch_lead = message(language, "trace_branch");
    std::string out = "\n" + wrap(branch_lead, branch_named(vocabulary, trace.branch, effect_set(trace), language),
                                  display_width(branch_lead));
    const VocabularyEntry* result = vocabulary.find("I_P");
    const std::string I_P = result ? result->symbol : "I_P";
    std::string value = trace.result_rgb ? shown_value_text(StepValue{*trace.result_rgb}, "colour", language, options.digits)
                                         : shown_number(trace.result, language, options.digits);
    if (!trace.result_real_text.empty()) {
        const Step exact{Key::E, StepValue{0.0}, -1, trace.result_real_text};
        value = trace_step_value_text(exact, vocabulary, trace.result_rgb ? "m" : "I_P", language, trace.header.real,
                                options.digits);
    }
    if (trace.samples) out += samples_text(*trace.samples, trace.header.spp, language);
    if (!trace.hit_object.empty())
        out += message(language, "trace_hit") + word_text(language, trace.hit_object) + "\n";
    // The article's kernel's result is its formula; a general scene's is a sum.
    // With samples, it is their mean.
    const VocabularyEntry* mean = vocabulary.find("I_mean");
    const std::string formula = trace.samples ? (mean ? mean->formula : "")
                                : trace.hit_object.empty() ? (result ? result->formula : "")
                                                           : intensity_formula(effect_set(trace)).formula;
    // What the formula's letters mean, when the article did not say (sₖ, cₖ).
    const IntensityFormula& effects_formula = intensity_formula(effect_set(trace));
    const std::string& note = language == Language::pl ? effects_formula.pl : effects_formula.en;
    const bool noted = !trace.hit_object.empty() && !trace.samples && !note.empty() &&
                       (trace.branch == Branch::lit || trace.branch == Branch::shadowed);
    const std::string result_lead = message(language, "trace_result");
    out += wrap(result_lead,
                I_P + " = " +
                    ((trace.branch == Branch::lit || trace.branch == Branch::shadowed || trace.samples) &&
                             !formula.empty()
                         ? formula + " = "
                         : "") +
                    value,
                display_width(result_lead),
                trace.hit_object.empty() ? coordinate_separator(language) : " ");
    if (noted) out += wrap(std::string(display_width(result_lead), ' '), note, display_width(result_lead));
    // cos α is a cosine only for a point on the sphere: above 1 (beyond
    // rounding) the "hit" is not on the sphere at all, and I_P with it is
    // no intensity (a tangent ray whose Δ/4 lost every digit).
    if (const std::optional<double> cos_alpha = top_level_number(trace, Key::cos_alpha);
        cos_alpha && std::fabs(*cos_alpha) > 1 + 1e-6)
        out += wrap("", message(language, "trace_cos_above_one", {{"cos", shown_number(*cos_alpha, language, 4)}}), 2);
    if (trace.first_non_finite && *trace.first_non_finite < trace.steps.size()) {
        const std::size_t k = *trace.first_non_finite;
        const std::string key(key_name(trace.steps[k].key));
        const bool decides = trace.branch == Branch::non_finite;
        out += wrap(message(language, "trace_first_non_finite"),
                    message(language, decides ? "trace_non_finite_decides" : "trace_non_finite_lesson",
                            {{"k", std::to_string(k + 1)},
                             {"symbol", trace_symbol(vocabulary, key, language)},
                             {"value", value_of(trace.steps[k].value, vocabulary, key, language)}}),
                    2);
    }
    if (trace.result_rgb) {
        const std::string levels = fmt::format("[{}, {}, {}]", trace.rgb[0], trace.rgb[1], trace.rgb[2]);
        out += wrap(message(language, "trace_rgb"), message(language, "trace_rgb_rule", {{"rgb", levels}, {"I_P", I_P}}), 2);
    } else {
        out += wrap(message(language, "trace_grey"),
                    message(language, "trace_grey_rule", {{"grey", std::to_string(trace.grey)}, {"I_P", I_P}}) +
                        (trace.result != trace.result ? message(language, "trace_grey_nan") : ""),
                    2);
    }
    out += digits_lost_notes(trace, vocabulary, language) + "\n";
    if (options.digits > 0)
        return out + message(language, "trace_note_digits", {{"digits", std::to_string(options.digits)}}) + "\n";
    // The note's example: a number of this scene, in the trace's own type
    // (float's 3.2 is not double's).
    const TypeExample example = type_example(trace.header.real, given_numbers(trace.header));
    return out + wrap("",
                      message(language, "trace_note",
                              {{"type", example.type},
                               {"number", local_number_text(example.number, language)},
                               {"stored", local_number_text(example.stored, language) + (example.cut ? "…" : "")},
                               {"square", local_number_text(example.square, language)},
                               {"exact_square", local_number_text(example.exact_square, language)}}),
                      0);
}

std::string value_of(const StepValue& value, const Vocabulary& vocabulary, const std::string& key, Language language,
                     int digits) {
    return shown_value_text(value, trace_kind(vocabulary, key), language, digits);
}

}  // namespace

std::string pane_phrase(int w) {
    const std::string digits = std::to_string(w);
    // Spoken "eight…", "eleven…", "eighteen…" take "an".
    const bool vowel = digits[0] == '8' || w == 11 || w == 18 || (w >= 11000 && w < 12000) ||
                       (w >= 18000 && w < 19000);
    return fmt::format("{} {} × {} pane", vowel ? "an" : "a", w, w);
}

std::string format_trace_text(const PixelTrace& trace, const Vocabulary& vocabulary, const TraceTextOptions& options) {
    std::string out = header_text(trace, vocabulary, options.language);
    out += options.layout == TraceLayout::wide ? wide_steps(trace, vocabulary, options) : narrow_steps(trace, vocabulary, options);
    return out + footer_text(trace, vocabulary, options);
}

}  // namespace promyk
