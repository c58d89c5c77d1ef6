#include "lesson/lesson_render.hpp"

#include "util/text.hpp"
#include "util/wrap.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "math/decimal.hpp"
#include "trace/messages.hpp"
#include "trace/keys.hpp"
#include "trace/trace_text.hpp"
#include "render/world.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_html.hpp"
#include "trace/intensity_formula.hpp"

namespace promyk {

namespace {

std::string kind_of(const Vocabulary& vocabulary, const std::string& path) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    return entry ? entry->kind : "scalar";
}

// How a value is written: as the vocabulary's kind says, but three numbers
// where a number is meant (a light's contribution, I_P in a coloured scene)
// are a colour, [r, g, b].
std::string shown_kind(const Vocabulary& vocabulary, const std::string& path, const StepValue& value) {
    const std::string kind = kind_of(vocabulary, path);
    if (std::holds_alternative<Vec3d>(value) && kind != "point" && kind != "vector") return "colour";
    return kind;
}

// A table's cell for a value the pixel's computation never reached: why not,
// in the branch's short name ("— (not computed: miss)").
std::string not_reached_cell(const PixelTrace& trace, Language language) {
    return message(language, "table_not_reached",
                   {{"branch", message(language, "branch_name_" + std::string(branch_name(trace.branch)))}});
}

// The branch in words, its formula the one of the trace's scene's effects.
std::string branch_text(const Vocabulary& vocabulary, const PixelTrace& trace, Language language) {
    return branch_named(vocabulary, trace.branch, effect_set(trace), language);
}

// A key's symbol in the lesson's language: the vocabulary's, unless
// messages.json has "symbol_KEY" (the words steps such as "found" are named
// in the vocabulary in Polish).
std::string lesson_symbol(Language language, const VocabularyEntry& entry) {
    return optional_message(language, "symbol_" + entry.key).value_or(entry.symbol);
}

// A table row's formula: the vocabulary's, unless messages.json has one for
// the key in its group's kind ("formula_plane_t": a plane's t is n̂·Q / n̂·E,
// not the sphere's root) or for the key in the lesson's language ("formula_KEY");
// "…_latex" for Markdown.
std::string lesson_formula(Language language, const std::string& path, const VocabularyEntry& entry, bool latex) {
    const std::optional<ValuePath> parsed = parse_value_path(split_settings(path).first);
    const std::string suffix = latex ? "_latex" : "";
    if (parsed && !parsed->groups.empty())
        if (auto own = optional_message(language, "formula_" + parsed->groups.back().kind + "_" + entry.key + suffix)) return *own;
    if (auto own = optional_message(language, "formula_" + entry.key + suffix)) return *own;
    return latex ? entry.formula_latex : entry.formula;
}

// The text with its placeholders filled for one pixel (or for none: prose).
// `named` is the pixel prose's {i} and {j} name (the step's pixel), if any.
std::string fill(const LessonView& view, const std::string& text, const PixelTrace* trace,
                 const PixelTrace* named = nullptr) {
    const Language language = view.lesson.language;
    std::string out;
    std::size_t at = 0;
    const auto copy_literal = [&](std::size_t end) {
        for (std::size_t k = at; k < end; ++k) {
            out += text[k];
            if ((text[k] == '{' || text[k] == '}') && k + 1 < end && text[k + 1] == text[k]) ++k;  // "{{" -> "{"
        }
    };
    for (const Placeholder& p : find_placeholders(text)) {
        copy_literal(p.begin);
        at = p.end;
        const VocabularyEntry* entry = view.vocabulary.find(p.name);
        if (!p.valid) {
            out += p.name;
        } else if (p.symbol) {
            out += entry ? lesson_symbol(language, *entry) : p.name;
        } else if (p.name == "w") {
            out += std::to_string(view.w);
        } else if (trace == nullptr && named != nullptr && (p.name == "i" || p.name == "j")) {
            out += std::to_string(p.name == "i" ? named->header.i : named->header.j);
        } else if (trace == nullptr && (p.name == "i" || p.name == "j" || p.name == "branch")) {
            out += message(language, "not_reached");
        } else if (p.name == "i" || p.name == "j") {
            out += std::to_string(p.name == "i" ? trace->header.i : trace->header.j);
        } else if (p.name == "branch") {
            out += branch_text(view.vocabulary, *trace, language);
        } else {
            // Prose may name only the scene's values, the same in every trace.
            const PixelTrace& source = trace != nullptr ? *trace : view.traces.front();
            const std::string qualified = qualified_path(p);
            const std::optional<LessonNumber> number = lesson_number(view, source, qualified);
            std::optional<std::string> shown;
            if (number && trace != nullptr && view.shown_value) shown = view.shown_value(*trace, qualified, p.component);
            if (!number && trace != nullptr && entry != nullptr && entry->term_of_sum) {
                out += "0";  // a term the computation did not reach adds nothing to the sum
            } else if (!number) {
                out += message(language, "not_reached");
            } else if (shown) {
                out += *shown;
            } else if (p.component != 0 && std::holds_alternative<Vec3d>(number->value)) {
                out += lesson_number_text(component_of(*number, p.component), "scalar", language, p.decimals, view.digits);
            } else {
                out += lesson_number_text(*number, shown_kind(view.vocabulary, p.path, number->value), language, p.decimals,
                                          view.digits);
            }
        }
    }
    copy_literal(text.size());
    return out;
}

// A value table's cell: the value, or what a worksheet shows in its place.
std::string cell_text(const LessonView& view, const PixelTrace& trace, const std::string& key, const LessonNumber& number) {
    if (view.shown_value)
        if (std::optional<std::string> shown = view.shown_value(trace, key, 0)) return *shown;
    return lesson_number_text(number, shown_kind(view.vocabulary, key, number.value), view.lesson.language,
                              shown_digits_default, view.digits);
}

std::string pixel_label(const LessonView& view, const PixelTrace& trace) {
    return message(view.lesson.language, "pixel_label",
                   {{"i", std::to_string(trace.header.i)}, {"j", std::to_string(trace.header.j)}});
}

// A table row's groups and settings, in the lesson's language:
// " (light 0, sphere 1)", " (float)", " (sphere 0; quad, geometric)", or
// nothing for a top-level key in the lesson's settings.
std::string group_suffix(const LessonView& view, const std::string& qualified) {
    const auto [bare, settings] = split_settings(qualified);
    const std::optional<ValuePath> path = parse_value_path(bare);
    std::string out;
    if (path)
        for (const PathGroup& group : path->groups)
            out += (out.empty() ? "" : ", ") + group_text(view.lesson.language, group.kind, group.index);
    std::string named = settings;
    for (std::size_t comma = named.find(','); comma != std::string::npos; comma = named.find(',', comma + 2))
        named.replace(comma, 1, ", ");
    if (!named.empty()) out += (out.empty() ? "" : "; ") + named;
    return out.empty() ? "" : " (" + out + ")";
}

std::string wrap(const std::string& text, std::size_t indent, std::size_t first_used);

bool shown_for(const LessonView& view, const LessonPart& part, const PixelTrace& trace) {
    return block_shown_for(view, part, trace);
}

// A scene block is shown on its scene: the lesson's own, or the one it names.
bool scene_shown(const LessonView& view, const LessonPart& part) {
    return part.scene.empty() ? view.own_scene : part.scene == view.scene_file;
}

// A table row's formula: I_P's and a light's contribution's are the ones of
// the scene's effects; the others the vocabulary's (or the lesson's own).
std::string row_formula(const LessonView& view, const std::string& key, const VocabularyEntry& entry, bool latex) {
    const std::string bare = path_key(key);
    if ((bare == "contribution" || key == "I_P") && !view.traces.empty()) {
        const std::string effects = effect_set(view.traces.front());
        if (bare == "contribution" || effects != "lambert") return step_formula(&entry, bare, effects, latex);
    }
    return lesson_formula(view.lesson.language, key, entry, latex);
}

// What a step needs, in words: "lit side, has:t".
std::string needs_text(const LessonView& view, const LessonStep& step) {
    std::string out;
    for (const std::string& branch : step.needs_branches)
        out += (out.empty() ? "" : " / ") + optional_message(view.lesson.language, "branch_name_" + branch).value_or(branch);
    // A condition in words: the value's symbol and whose it is ("s₁ (light 0, sphere 0) > 0").
    for (const Condition& condition : step.needs) {
        if (condition.op == Condition::Op::on_scene) continue;
        const VocabularyEntry* entry = view.vocabulary.find(path_key(condition.path));
        const std::string named =
            (entry ? lesson_symbol(view.lesson.language, *entry) : condition.path) + group_suffix(view, condition.path);
        static const char* const ops[] = {"", "", " < ", " ≤ ", " > ", " ≥ "};
        std::string text = message(view.lesson.language, "lesson_needs_has", {{"value", named}});
        if (condition.op == Condition::Op::missing)
            text = message(view.lesson.language, "lesson_needs_missing", {{"value", named}});
        else if (condition.op == Condition::Op::is_word)
            text = named + " = " + word_text(view.lesson.language, condition.word);
        else if (condition.op != Condition::Op::exists)
            text = named + ops[static_cast<int>(condition.op)] +
                   shown_number(condition.bound, view.lesson.language, 0);
        out += (out.empty() ? "" : ", ") + text;
    }
    return out;
}

// The line a step shows when no chosen pixel has what it needs.
std::string needs_line(const LessonView& view, const LessonStep& step) {
    const Language language = view.lesson.language;
    std::string what = needs_text(view, step);
    if (what.empty()) what = message(language, "lesson_needs_values");
    const std::optional<LessonPixel> found = pane_pixel_for(view, step);
    if (!found)
        return message(language, "lesson_needs_none", {{"what", what}, {"w", std::to_string(view.w)}});
    return message(language, "lesson_needs_pixel",
                   {{"what", what},
                    {"i", std::to_string(found->i)},
                    {"j", std::to_string(found->j)},
                    {"name", view.lesson.header.name}});
}

// True when a prose part names the step's pixel ({i}, {j}).
bool names_pixel(const std::string& text) {
    for (const Placeholder& p : find_placeholders(text))
        if (p.valid && (p.name == "i" || p.name == "j") && p.path == p.name) return true;
    return false;
}

// The chosen pane drawn by branch, a character a pixel, the chosen pixels
// marked 1, 2, … (then a, b, …), with a legend.
std::string pane_figure(const LessonView& view) {
    const Language language = view.lesson.language;
    if (!view.pane_pixel || view.w > 38) return message(language, "figure_too_large", {{"w", std::to_string(view.w)}}) + "\n";
    const auto symbol = [](Branch branch) {
        switch (branch) {
            case Branch::miss: return ".";
            case Branch::dark: return "-";
            case Branch::lit: return "#";
            case Branch::shadowed: return "s";
            default: return "!";
        }
    };
    const auto mark = [](std::size_t k) { return std::string(1, k < 9 ? static_cast<char>('1' + k) : static_cast<char>('a' + (k - 9) % 26)); };
    std::string out = "     ";
    for (int j = 0; j < view.w; ++j) out += std::to_string(j % 10) + " ";
    out += " j\n";
    for (int i = 0; i < view.w; ++i) {
        out += fmt::format("  {:>2} ", i);
        for (int j = 0; j < view.w; ++j) {
            std::string cell = symbol(view.pane_pixel(i, j).branch);
            for (std::size_t k = 0; k < view.traces.size(); ++k)
                if (view.traces[k].header.i == i && view.traces[k].header.j == j) {
                    cell = mark(k);
                    break;
                }
            out += cell + (j + 1 < view.w ? " " : "");
        }
        out += "\n";
    }
    out += "   i\n";
    std::string legend;
    for (const Branch branch : {Branch::miss, Branch::dark, Branch::lit, Branch::shadowed, Branch::non_finite}) {
        bool present = false;
        for (int i = 0; i < view.w && !present; ++i)
            for (int j = 0; j < view.w && !present; ++j) present = view.pane_pixel(i, j).branch == branch;
        if (present)
            legend += (legend.empty() ? "" : ", ") + std::string(symbol(branch)) + " " +
                      message(language, "branch_name_" + std::string(branch_name(branch)));
    }
    std::string chosen;
    for (std::size_t k = 0; k < view.traces.size(); ++k)
        chosen += (chosen.empty() ? "" : ", ") + mark(k) + " " +
                  message(language, "pixel_label", {{"i", std::to_string(view.traces[k].header.i)}, {"j", std::to_string(view.traces[k].header.j)}}) +
                  " (" + message(language, "branch_name_" + std::string(branch_name(view.traces[k].branch))) + ")";
    out += wrap(message(language, "figure_legend", {{"branches", legend}, {"chosen", chosen}}), 2, 0) + "\n";
    return out;
}

// --- terminal text -------------------------------------------------------

// Markdown markup that means nothing on a terminal.
std::string plain(std::string text) {
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text.compare(k, 2, "**") == 0 || text.compare(k, 2, "__") == 0) {
            ++k;
            continue;
        }
        if (text[k] == '$' || text[k] == '`') continue;
        out += text[k];
    }
    return out;
}

// The lesson's prose wrapped by the one wrapper every text output uses.
std::string wrap(const std::string& text, std::size_t indent, std::size_t first_used = 0) {
    return wrap_text(text, indent, text_columns, first_used);
}

// The width of a list item's marker ("- ", "* ", "12. "), or 0.
std::size_t list_marker(const std::string& line) {
    if (line.rfind("- ", 0) == 0 || line.rfind("* ", 0) == 0) return 2;
    std::size_t k = 0;
    while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k]))) ++k;
    return k > 0 && line.compare(k, 2, ". ") == 0 ? k + 2 : 0;
}

// Paragraphs and list items reflowed to 80 columns (an item's lines hang
// under its text); tables, indented and fenced code kept as written.
std::string text_paragraphs(const std::string& text, std::size_t indent, std::size_t first_used = 0) {
    std::string out, paragraph;
    std::size_t hang = 0;  // the open list item's marker width, 0 for a paragraph
    bool code = false;
    const std::string pad(indent, ' ');
    const auto flush = [&] {
        if (paragraph.empty()) return;
        const bool first = out.empty() && first_used > 0;
        out += (first ? "" : pad) + wrap(plain(paragraph), indent + hang, first ? first_used : indent) + "\n";
        paragraph.clear();
        hang = 0;
    };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        start = end == std::string::npos ? text.size() + 1 : end + 1;
        if (line.rfind("```", 0) == 0) {
            flush();
            code = !code;
            continue;
        }
        const std::size_t first_char = line.find_first_not_of(' ');
        if (code) {
            out += pad + "    " + line + "\n";
        } else if (first_char == std::string::npos) {
            flush();
            if (!out.empty() && out.compare(out.size() - 2, 2, "\n\n") != 0) out += "\n";
        } else if (line.rfind("    ", 0) == 0 && hang == 0 && paragraph.empty()) {
            out += pad + line + "\n";  // indented code
        } else if (line.rfind("|", 0) == 0 && line.size() > 1 && line.back() == '|') {
            // A Markdown table row starts and ends with a bar; "|K|² is ..." is prose.
            flush();
            out += pad + plain(line) + "\n";
        } else if (const std::size_t marker = list_marker(line)) {
            flush();
            paragraph = line;
            hang = marker;
        } else {
            paragraph += (paragraph.empty() ? "" : " ") + line.substr(first_char);
        }
    }
    flush();
    while (out.size() > 1 && out.compare(out.size() - 2, 2, "\n\n") == 0) out.pop_back();
    return out;
}

std::string bold(const LessonView& view, const std::string& text) {
    return view.color ? "\x1b[1m" + text + "\x1b[0m" : text;
}

std::string text_values(const LessonView& view, const LessonPart& part) {
    const Language language = view.lesson.language;
    std::string out;
    for (const std::string& key : expanded_keys(view, part.keys)) {
        const VocabularyEntry* entry = view.vocabulary.find(path_key(key));
        const std::string symbol = (entry ? lesson_symbol(language, *entry) : key) + group_suffix(view, key);
        const std::string formula = entry ? row_formula(view, key, *entry, false) : "";
        // A long formula (everything.json's I_P) wraps under its symbol.
        out += wrap_text("  " + symbol + (formula.empty() ? "" : " = " + formula), 6) + "\n";
        std::vector<std::string> cells;
        for (const PixelTrace& trace : view.traces) {
            const std::optional<LessonNumber> number = lesson_number(view, trace, key);
            cells.push_back(fmt::format("({}, {}): {}", trace.header.i, trace.header.j,
                                        number ? cell_text(view, trace, key, *number) : not_reached_cell(trace, language)));
        }
        std::size_t total = 4;
        for (const std::string& cell : cells) total += display_width(cell) + 4;
        if (total <= text_columns) {
            std::string line = "    ";
            for (std::size_t c = 0; c < cells.size(); ++c) line += (c ? "    " : "") + cells[c];
            out += line + "\n";
        } else {
            for (const std::string& cell : cells) out += "    " + cell + "\n";
        }
    }
    return out;
}

std::string text_part(const LessonView& view, const LessonPart& part, const PixelTrace* named) {
    switch (part.kind) {
        case PartKind::prose:
            return text_paragraphs(fill(view, part.text, nullptr, named), 0);
        case PartKind::scene:
            return scene_shown(view, part) ? text_paragraphs(fill(view, part.text, nullptr, named), 0) : "";
        case PartKind::figure:
            return pane_figure(view);
        case PartKind::values:
            return text_values(view, part);
        case PartKind::block: {
            std::string out;
            for (const PixelTrace& trace : view.traces) {
                if (!shown_for(view, part, trace)) continue;
                const std::string label = "▸ " + pixel_label(view, trace) + ": ";
                out += label + text_paragraphs(fill(view, part.text, &trace), 2, display_width(label));
            }
            return out;
        }
        case PartKind::answer:
            return "";
    }
    return "";
}

// A value table's row label in TeX (Markdown's and HTML's tables): the
// vocabulary's formula for the key, else its symbol, else the key itself.
std::string row_math(const LessonView& view, const std::string& key) {
    const VocabularyEntry* entry = view.vocabulary.find(path_key(key));
    if (entry == nullptr) return split_settings(key).first;
    std::string math = row_formula(view, key, *entry, true);
    return math.empty() ? entry->latex : math;
}

// --- Markdown -------------------------------------------------------------

std::string markdown_values(const LessonView& view, const LessonPart& part) {
    const Language language = view.lesson.language;
    std::string out = "| |";
    for (const PixelTrace& trace : view.traces) out += " " + pixel_label(view, trace) + " |";
    out += "\n|---|";
    for (std::size_t c = 0; c < view.traces.size(); ++c) out += "---|";
    out += "\n";
    for (const std::string& key : expanded_keys(view, part.keys)) {
        std::string math = row_math(view, key);
        // A | would end the table's cell: LaTeX's \vert draws the same bar.
        for (std::size_t bar = math.find('|'); bar != std::string::npos; bar = math.find('|', bar))
            math.replace(bar, 1, "\\vert ");
        out += "| $" + math + "$" + group_suffix(view, key) + " |";
        for (const PixelTrace& trace : view.traces) {
            const std::optional<LessonNumber> number = lesson_number(view, trace, key);
            out += " " + (number ? cell_text(view, trace, key, *number) : not_reached_cell(trace, language)) + " |";
        }
        out += "\n";
    }
    return out;
}

std::string markdown_part(const LessonView& view, const LessonPart& part, const PixelTrace* named) {
    switch (part.kind) {
        case PartKind::prose:
            return fill(view, part.text, nullptr, named) + "\n";
        case PartKind::scene:
            return scene_shown(view, part) ? fill(view, part.text, nullptr, named) + "\n" : "";
        case PartKind::figure:
            return "```\n" + pane_figure(view) + "```\n";
        case PartKind::values:
            return markdown_values(view, part);
        case PartKind::block: {
            std::string out;
            for (const PixelTrace& trace : view.traces) {
                if (!shown_for(view, part, trace)) continue;
                if (!out.empty()) out += "\n";
                out += "**" + pixel_label(view, trace) + ":** " + fill(view, part.text, &trace) + "\n";
            }
            return out;
        }
        case PartKind::answer:
            return "";
    }
    return "";
}

// --- HTML (the web page) -----------------------------------------------------

std::string html_values(const LessonView& view, const LessonPart& part) {
    const Language language = view.lesson.language;
    std::string out = "<table class=\"values\">\n<thead><tr><td></td>";
    for (const PixelTrace& trace : view.traces)
        out += "<th scope=\"col\">" + html_escape(pixel_label(view, trace)) + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    for (const std::string& key : expanded_keys(view, part.keys)) {
        std::string math = row_math(view, key);
        out += "<tr><th scope=\"row\">" + html_math(math) + html_escape(group_suffix(view, key)) + "</th>";
        for (const PixelTrace& trace : view.traces) {
            const std::optional<LessonNumber> number = lesson_number(view, trace, key);
            out += number ? "<td>" + html_escape(cell_text(view, trace, key, *number)) + "</td>"
                          : "<td class=\"not-reached\">" + html_escape(not_reached_cell(trace, language)) + "</td>";
        }
        out += "</tr>\n";
    }
    return out + "</tbody>\n</table>\n";
}

std::string html_part(const LessonView& view, const LessonPart& part, const PixelTrace* named) {
    switch (part.kind) {
        case PartKind::prose:
            return html_prose(fill(view, part.text, nullptr, named));
        case PartKind::scene:
            return scene_shown(view, part) ? html_prose(fill(view, part.text, nullptr, named)) : "";
        case PartKind::figure:
            return "<pre class=\"figure\">" + html_escape(pane_figure(view)) + "</pre>\n";
        case PartKind::values:
            return html_values(view, part);
        case PartKind::block: {
            std::string out;
            for (const PixelTrace& trace : view.traces) {
                if (!shown_for(view, part, trace)) continue;
                out += fmt::format("<div class=\"block\" data-i=\"{}\" data-j=\"{}\">\n<p class=\"pixel\"><strong>", trace.header.i,
                                   trace.header.j) +
                       html_escape(pixel_label(view, trace)) + ":</strong></p>\n" + html_prose(fill(view, part.text, &trace)) +
                       "</div>\n";
            }
            return out;
        }
        case PartKind::answer:
            return "";
    }
    return "";
}

}  // namespace

bool is_scene_value(const std::string& key);

namespace {

// The scene's value of one object or light, as its file gives it: the
// centre S and radius r of sphere k, the position L and intensity I of light
// k. Read from the scene's text the trace's header carries (parsed once a scene).
std::optional<StepValue> scene_value(const PixelTrace& trace, const PathGroup& group, const std::string& key) {
    if (!is_scene_value(group.kind + "[0]." + key)) return std::nullopt;
    // The header names each object's, light's and material's values when the
    // scene has several (or materials); the scene's text covers the rest.
    for (const GivenGroup& given : trace.header.given_groups)
        if (given.kind == group.kind && given.index == group.index)
            for (const GivenValue& value : given.values)
                if (value.key == key) return value.value;
    static thread_local std::string parsed_content;
    static thread_local nlohmann::json parsed;
    if (parsed_content != trace.header.scene_content || parsed.is_discarded()) {
        parsed = nlohmann::json::parse(trace.header.scene_content, nullptr, false);
        parsed_content = trace.header.scene_content;
    }
    if (group.kind == "material" || key == "c") return std::nullopt;
    const char* list = group.kind == "sphere" ? "spheres" : group.kind == "light" ? "lights" : "planes";
    if (!parsed.is_object() || !parsed.contains(list) || !parsed.at(list).is_array()) return std::nullopt;
    const nlohmann::json& items = parsed.at(list);
    if (group.index < 0 || static_cast<std::size_t>(group.index) >= items.size()) return std::nullopt;
    const nlohmann::json& item = items.at(static_cast<std::size_t>(group.index));
    const auto read = [&item](const std::string& name) -> std::optional<StepValue> {
        if (!item.is_object() || !item.contains(name)) return std::nullopt;
        const nlohmann::json& value = item.at(name);
        if (value.is_number()) return StepValue{value.get<double>()};
        if (value.is_array() && value.size() == 3 &&
            std::all_of(value.begin(), value.end(), [](const nlohmann::json& c) { return c.is_number(); }))
            return StepValue{Vec3d{value[0].get<double>(), value[1].get<double>(), value[2].get<double>()}};
        return std::nullopt;
    };
    if (group.kind != "plane" || key == "Q" || key == "n") return read(key);
    // A plane's n̂ and n̂·Q, computed once a scene, as the engine computes them (render/world.hpp).
    const std::optional<StepValue> Q = read("Q"), n = read("n");
    if (!Q || !n || !std::holds_alternative<Vec3d>(*Q) || !std::holds_alternative<Vec3d>(*n)) return std::nullopt;
    const Vec3d n_hat = unit_normal<double>(std::get<Vec3d>(*n));
    if (key == "n_hat") return StepValue{n_hat};
    return StepValue{dot(n_hat, std::get<Vec3d>(*Q))};
}

}  // namespace

std::optional<StepValue> lesson_value(const PixelTrace& trace, const std::string& key) {
    const std::optional<ValuePath> path = parse_value_path(key);
    if (!path) return std::nullopt;
    // With samples (--spp), a path that names no sample is read in the centre
    // sample, whose branch is the pixel's, and then at the top level (I_mean).
    if (trace.samples && (path->groups.empty() || path->groups.front().kind != "sample")) {
        const std::string centre = "sample[" + std::to_string(trace.samples->centre) + "]." + key;
        if (std::optional<StepValue> value = lesson_value(trace, centre)) return value;
    }
    // The article's kernel records no groups: sphere 0 and light 0 are its
    // one sphere and one light, whose steps stand at the top level.
    if (trace.groups.empty() && path->groups.size() == 1 && path->groups[0].index == 0 &&
        (path->groups[0].kind == "sphere" || path->groups[0].kind == "light") && !trace.header.given.empty())
        if (std::optional<StepValue> value = lesson_value(trace, path->key)) return value;
    // The group the path names: each one's parent is the one before it.
    int group = -1;
    for (const PathGroup& wanted : path->groups) {
        int found = -1;
        for (std::size_t g = 0; g < trace.groups.size() && found < 0; ++g) {
            const TraceGroup& candidate = trace.groups[g];
            if (candidate.parent == group && candidate.kind == wanted.kind && candidate.index == wanted.index)
                found = static_cast<int>(g);
        }
        // Not traced for this pixel: a scene's value of the object can still be named.
        if (found < 0) return path->groups.size() == 1 ? scene_value(trace, path->groups[0], path->key) : std::nullopt;
        group = found;
    }
    for (const Step& step : trace.steps)
        if (step.group == group && key_name(step.key) == path->key) return step.value;
    if (!path->groups.empty()) return path->groups.size() == 1 ? scene_value(trace, path->groups[0], path->key) : std::nullopt;
    for (const GivenValue& given : trace.header.given)
        if (given.key == path->key) return given.value;
    if (path->key == "I_P") return trace.result_rgb ? StepValue{*trace.result_rgb} : StepValue{trace.result};
    // A general scene (several objects or lights, planes, shadows, Phong)
    // records the article's steps in groups: a lesson about the article's one
    // sphere and one light, run on it, names by a top-level key the nearest
    // hit's step (t: t_hit), else sphere 0's, else light 0's.
    if (path->groups.empty() && !trace.groups.empty()) {
        if (path->key == "t")
            if (std::optional<StepValue> value = lesson_value(trace, "t_hit")) return value;
        std::vector<std::string> prefixes;
        const std::size_t space = trace.hit_object.find(' ');
        if (space != std::string::npos)
            prefixes.push_back(trace.hit_object.substr(0, space) + "[" + trace.hit_object.substr(space + 1) + "].");
        prefixes.push_back("sphere[0].");
        prefixes.push_back("light[0].");
        for (const std::string& prefix : prefixes)
            if (std::optional<StepValue> value = lesson_value(trace, prefix + path->key)) return value;
    }
    return std::nullopt;
}

bool is_scene_value(const std::string& qualified) {
    const std::optional<ValuePath> path = parse_value_path(split_settings(qualified).first);
    if (!path) return false;
    if (path->groups.empty()) {
        const VocabularyEntry* entry = builtin_vocabulary().find(path->key);
        return entry != nullptr && entry->given;
    }
    if (path->groups.size() != 1) return false;
    const std::string& kind = path->groups[0].kind;
    const std::string& name = path->key;
    return (kind == "sphere" && (name == "S" || name == "r")) ||
           (kind == "light" && (name == "L" || name == "I" || name == "c")) ||
           (kind == "plane" && (name == "Q" || name == "n" || name == "n_hat" || name == "NQ")) ||
           (kind == "material" && (name == "k_a" || name == "k_d" || name == "k_s" || name == "exponent" || name == "m"));
}

std::size_t derivation_rank(const PixelTrace& trace, const Vocabulary& vocabulary, const std::string& key) {
    const std::size_t keys = vocabulary.keys.size();
    const auto vocabulary_index = [&](std::string_view name) {
        for (std::size_t k = 0; k < keys; ++k)
            if (vocabulary.keys[k].key == name) return k;
        return keys;
    };
    const std::string bare = path_key(key);
    const std::size_t own = vocabulary_index(bare);
    const VocabularyEntry* entry = vocabulary.find(bare);
    if (entry != nullptr && entry->given) return own;
    const std::optional<ValuePath> path = parse_value_path(split_settings(key).first);
    std::size_t after = 0;  // 1 + the last step whose key comes no later in the vocabulary
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const Step& step = trace.steps[k];
        const std::string_view name = key_name(step.key);
        if (path && name == path->key) {
            // The step itself, when it is in the path's group.
            std::vector<int> chain;
            for (int g = step.group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent) chain.insert(chain.begin(), g);
            bool same = chain.size() == path->groups.size();
            for (std::size_t c = 0; same && c < chain.size(); ++c) {
                const TraceGroup& traced = trace.groups[static_cast<std::size_t>(chain[c])];
                same = traced.kind == path->groups[c].kind && traced.index == path->groups[c].index;
            }
            if (same) return keys + 2 * (k + 1);
        }
        if (vocabulary_index(name) <= own) after = k + 1;
    }
    return keys + 2 * after + 1;
}

std::pair<std::string, std::string> resolve_settings(const std::string& settings, const std::string& real,
                                                     const std::string& formula) {
    const std::optional<SettingsQualifier> parsed = parse_settings(settings);
    if (!parsed) return {real, formula};
    return {parsed->real.empty() ? real : parsed->real, parsed->formula.empty() ? formula : parsed->formula};
}

const PixelTrace* settings_trace(const PixelTrace& trace, const std::string& settings, const std::vector<PixelTrace>& others) {
    if (settings.empty()) return &trace;
    if (!parse_settings(settings)) return nullptr;
    const auto [real, formula] = resolve_settings(settings, trace.header.real, trace.header.formula);
    if (real == trace.header.real && formula == trace.header.formula) return &trace;
    for (const PixelTrace& other : others)
        if (other.header.i == trace.header.i && other.header.j == trace.header.j && other.header.real == real &&
            other.header.formula == formula)
            return &other;
    return nullptr;
}

std::optional<LessonNumber> lesson_number(const PixelTrace& trace, const std::string& qualified,
                                          const std::vector<PixelTrace>& others) {
    const auto [path, settings] = split_settings(qualified);
    const PixelTrace* source = settings_trace(trace, settings, others);
    if (source == nullptr) return std::nullopt;
    const std::optional<StepValue> value = lesson_value(*source, path);
    if (!value) return std::nullopt;
    LessonNumber number{*value, {}, source->header.real};
    // The step's exact text in its own type, when the trace is not in double.
    const std::optional<ValuePath> parsed = parse_value_path(path);
    if (parsed && source->header.real != "double") {
        if (parsed->groups.empty() && parsed->key == "I_P") {
            number.real_text = source->result_real_text;
        } else {
            int group = -1;
            bool found_groups = true;
            for (const PathGroup& wanted : parsed->groups) {
                int found = -1;
                for (std::size_t g = 0; g < source->groups.size() && found < 0; ++g) {
                    const TraceGroup& candidate = source->groups[g];
                    if (candidate.parent == group && candidate.kind == wanted.kind && candidate.index == wanted.index)
                        found = static_cast<int>(g);
                }
                if (found < 0) found_groups = false;
                group = found;
            }
            if (found_groups)
                for (const Step& step : source->steps)
                    if (step.group == group && key_name(step.key) == parsed->key) {
                        number.real_text = step.real_text;
                        break;
                    }
        }
    }
    return number;
}

std::optional<LessonNumber> lesson_number(const LessonView& view, const PixelTrace& trace, const std::string& qualified) {
    return lesson_number(trace, qualified, view.others);
}

LessonNumber component_of(const LessonNumber& number, char component) {
    const Vec3d* v = std::get_if<Vec3d>(&number.value);
    if (component == 0 || v == nullptr) return number;
    const std::size_t k = static_cast<std::size_t>(component - 'x');
    LessonNumber out{k == 0 ? v->x : k == 1 ? v->y : v->z, {}, number.real};
    if (number.real_text.size() == 3) out.real_text = {number.real_text[k]};
    return out;
}

namespace {

// A real type's exact value, given as its shortest text, rounded to
// `decimals` digits after the point as fmt rounds a double's exact value
// (to nearest, ties to even), written the language's way.
std::string rounded_real_text(const std::string& text, const std::string& real, Language language, int decimals) {
    const RealType type = real == "float" ? RealType::float_ : real == "long-double" ? RealType::long_double : RealType::quad_;
    const std::optional<TypedNumber> exact = exact_value_of(text, type);
    if (!exact) return local_number_text(text, language);  // inf, nan
    std::string digits = exact->digits;
    int scale = exact->scale;
    if (scale < decimals) {
        digits += std::string(static_cast<std::size_t>(decimals - scale), '0');
        scale = decimals;
    }
    const std::size_t drop = static_cast<std::size_t>(scale - decimals);
    if (digits.size() < drop + 1) digits.insert(0, drop + 1 - digits.size(), '0');
    std::string kept = digits.substr(0, digits.size() - drop);
    const std::string rest = digits.substr(digits.size() - drop);
    const bool above_half = !rest.empty() && (rest[0] > '5' || (rest[0] == '5' && rest.find_first_not_of('0', 1) != std::string::npos));
    const bool half = !rest.empty() && rest[0] == '5' && rest.find_first_not_of('0', 1) == std::string::npos;
    if (above_half || (half && (kept.back() - '0') % 2 == 1)) {
        std::size_t k = kept.size();
        while (k > 0 && kept[k - 1] == '9') kept[--k] = '0';
        if (k == 0) kept.insert(0, "1");
        else ++kept[k - 1];
    }
    if (kept.size() < static_cast<std::size_t>(decimals) + 1) kept.insert(0, static_cast<std::size_t>(decimals) + 1 - kept.size(), '0');
    std::string out = kept.substr(0, kept.size() - static_cast<std::size_t>(decimals));
    if (decimals > 0) out += "." + kept.substr(kept.size() - static_cast<std::size_t>(decimals));
    if (exact->negative) out = "-" + out;  // fmt writes -0.000 for a small negative too
    return local_number_text(out, language);
}

}  // namespace

bool scene_has_effect(const Scene& scene, const std::string& effect) {
    if (effect == "spheres") return scene.spheres.size() > 1;
    if (effect == "lights") return scene.lights.size() > 1;
    if (effect == "plane") return !scene.planes.empty();
    if (effect == "shadows") return scene.shadows && scene.object_count() > 1;
    if (effect == "phong")
        return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.specular > 0; });
    if (effect == "colour") return is_coloured(scene);
    return true;
}

bool condition_holds(const LessonView& view, const PixelTrace& trace, const Condition& condition) {
    if (condition.op == Condition::Op::on_scene) return condition.path.empty() ? view.own_scene : condition.path == view.scene_file;
    const std::optional<LessonNumber> number = lesson_number(view, trace, condition.path);
    if (condition.op == Condition::Op::exists) return number.has_value();
    if (condition.op == Condition::Op::missing) return !number.has_value();
    if (condition.op == Condition::Op::is_word) {
        const std::string* word = number ? std::get_if<std::string>(&number->value) : nullptr;
        return word != nullptr && *word == condition.word;
    }
    const double* value = number ? std::get_if<double>(&number->value) : nullptr;
    if (value == nullptr) return false;
    switch (condition.op) {
        case Condition::Op::less: return *value < condition.bound;
        case Condition::Op::less_equal: return *value <= condition.bound;
        case Condition::Op::greater: return *value > condition.bound;
        case Condition::Op::greater_equal: return *value >= condition.bound;
        default: return false;
    }
}

bool block_shown_for(const LessonView& view, const LessonPart& part, const PixelTrace& trace) {
    if (!part.branches.empty() &&
        std::find(part.branches.begin(), part.branches.end(), branch_name(trace.branch)) == part.branches.end())
        return false;
    return std::all_of(part.conditions.begin(), part.conditions.end(),
                       [&](const Condition& condition) { return condition_holds(view, trace, condition); });
}

namespace {

// True when the pixel has what the step needs: its branch and conditions,
// and every value its answers name.
bool has_needs(const LessonView& view, const LessonStep& step, const PixelTrace& trace) {
    if (!step.needs_branches.empty() &&
        std::find(step.needs_branches.begin(), step.needs_branches.end(), branch_name(trace.branch)) == step.needs_branches.end())
        return false;
    for (const Condition& condition : step.needs)
        if (!condition_holds(view, trace, condition)) return false;
    for (const LessonPart& part : step.parts) {
        if (part.kind != PartKind::answer) continue;
        for (const Placeholder& p : find_placeholders(part.text))
            if (p.valid && !p.symbol && view.vocabulary.find(p.name) != nullptr && !lesson_number(view, trace, qualified_path(p)))
                return false;
    }
    return true;
}

}  // namespace

const PixelTrace* step_pixel(const LessonView& view, const LessonStep& step) {
    for (const PixelTrace& trace : view.traces)
        if (has_needs(view, step, trace)) return &trace;
    return nullptr;
}

std::optional<LessonPixel> pane_pixel_for(const LessonView& view, const LessonStep& step) {
    if (!view.pane_pixel) return std::nullopt;
    for (int i = 0; i < view.w; ++i)
        for (int j = 0; j < view.w; ++j)
            if (has_needs(view, step, view.pane_pixel(i, j))) return LessonPixel{i, j};
    return std::nullopt;
}

std::vector<std::string> expanded_keys(const LessonView& view, const std::vector<std::string>& keys) {
    std::vector<std::string> out;
    std::vector<std::string> pending(keys.rbegin(), keys.rend());
    while (!pending.empty()) {
        const std::string key = pending.back();
        pending.pop_back();
        const std::size_t star = key.find("[*]");
        if (star == std::string::npos) {
            // A row about an object the scene lacks (light[1] in a scene of one light) is left out.
            if (view.scene == nullptr || check_path(split_settings(key).first, view.vocabulary, view.scene).fault != PathFault::index)
                out.push_back(key);
            continue;
        }
        if (view.scene == nullptr) continue;
        std::size_t begin = star;
        while (begin > 0 && std::isalpha(static_cast<unsigned char>(key[begin - 1]))) --begin;
        const std::string kind = key.substr(begin, star - begin);
        const std::size_t count = kind == "sphere" ? view.scene->spheres.size()
                                  : kind == "plane" ? view.scene->planes.size()
                                  : kind == "light" ? view.scene->lights.size()
                                  : kind == "material" ? view.scene->materials.size() : 0;
        for (std::size_t k = count; k-- > 0;)
            pending.push_back(key.substr(0, star) + "[" + std::to_string(k) + "]" + key.substr(star + 3));
    }
    return out;
}

std::string lesson_number_text(const LessonNumber& number, const std::string& kind, Language language, int decimals,
                               int digits) {
    const int significant = decimals == every_digit ? 0 : digits;  // shown_number's 0: every digit
    if (number.real_text.empty() || std::holds_alternative<std::string>(number.value)) {
        if (decimals >= 0) return value_text(number.value, kind, language, decimals);
        return shown_value_text(number.value, kind, language, significant);
    }
    const RealType type = number.real == "float"         ? RealType::float_
                          : number.real == "double"      ? RealType::double_
                          : number.real == "long-double" ? RealType::long_double
                                                         : RealType::quad_;
    const auto one = [&](const std::string& text, double value) {
        // A float is exactly a double: its double value rounds the same.
        if (decimals >= 0 && (number.real == "float" || number.real == "double")) return number_text(value, language, decimals);
        if (decimals >= 0) return rounded_real_text(text, number.real, language, decimals);
        return shown_real_text(text, type, language, significant);
    };
    if (const double* value = std::get_if<double>(&number.value)) return one(number.real_text.front(), *value);
    const Vec3d& v = std::get<Vec3d>(number.value);
    if (number.real_text.size() != 3) return shown_value_text(number.value, kind, language, significant);
    const bool vector = kind == "vector" || kind == "colour";
    const char* separator = coordinate_separator(language);
    return std::string(vector ? "[" : "(") + one(number.real_text[0], v.x) + separator + one(number.real_text[1], v.y) +
           separator + one(number.real_text[2], v.z) + (vector ? "]" : ")");
}

bool has_answers(const LessonStep& step) {
    return std::any_of(step.parts.begin(), step.parts.end(), [](const LessonPart& p) { return p.kind == PartKind::answer; });
}

std::string render_lesson_title(const LessonView& view) {
    const Language language = view.lesson.language;
    std::string pixels;
    for (const PixelTrace& trace : view.traces)
        pixels += fmt::format("{}({}, {})", pixels.empty() ? "" : ", ", trace.header.i, trace.header.j);
    const std::string heading = message(language, "lesson_heading", {{"title", view.lesson.header.title}});
    const std::string setup = message(language, "lesson_setup",
                                      {{"scene", view.scene_name},
                                       {"w", std::to_string(view.w)},
                                       {"pane", pane_phrase(view.w)},
                                       {"pixels", pixels}});
    // The numbers' type and formula, when they are not the article's double.
    const TraceHeader& numbers = view.traces.front().header;
    std::string settings;
    if (numbers.real != "double" || numbers.formula != "article")
        settings = message(language, "lesson_numbers", {{"real", numbers.real}, {"formula", numbers.formula}});
    if (numbers.spp > 1)
        settings += (settings.empty() ? "" : " ") +
                    message(language, "lesson_samples", {{"spp", std::to_string(numbers.spp)}});
    // A scene without the lesson's effect: one line says so and names the lesson's own scene.
    const std::string& effect = view.lesson.header.effect;
    if (!effect.empty() && view.scene != nullptr && !scene_has_effect(*view.scene, effect))
        settings += (settings.empty() ? "" : " ") +
                    message(language, "lesson_scene_lacks",
                            {{"scene", view.scene_name},
                             {"effect", message(language, "effect_" + effect)},
                             {"example", view.lesson.header.scene},
                             {"name", view.lesson.header.name}});
    if (view.format == LessonFormat::html)
        return "<header class=\"lesson-head\">\n<h1>" + html_escape(heading) + "</h1>\n<p class=\"summary\"><em>" +
               html_inline(view.lesson.header.summary) + "</em></p>\n<p class=\"setup\">" + html_escape(setup) + "</p>\n" +
               (settings.empty() ? "" : "<p class=\"settings\">" + html_escape(settings) + "</p>\n") + "</header>\n";
    if (view.format == LessonFormat::markdown)
        return "# " + heading + "\n\n*" + view.lesson.header.summary + "*\n\n" + setup + (settings.empty() ? "" : "\n\n" + settings) + "\n";
    return bold(view, heading) + "\n" + wrap(view.lesson.header.summary, 0) + "\n" + wrap(setup, 0) + "\n" +
           (settings.empty() ? "" : wrap(settings, 0) + "\n");
}

std::string render_step(const LessonView& view, std::size_t k) {
    const LessonStep& step = view.lesson.steps.at(k);
    const std::string heading =
        message(view.lesson.language, "step_heading",
                {{"k", std::to_string(k + 1)}, {"n", std::to_string(view.lesson.steps.size())}, {"title", step.title}});
    std::string out;
    // The pixel the step's prose names ({i}, {j}) and its answers are about;
    // when no chosen pixel has what the step needs, the step says so, names
    // a pixel of the pane that has it, and leaves out what names the pixel.
    const PixelTrace* named = step_pixel(view, step);
    const bool needs = step.needs_line != 0 || has_answers(step);
    const std::string missing = named == nullptr && needs ? needs_line(view, step) : "";
    const auto skipped = [&](const LessonPart& part) {
        return named == nullptr && (part.kind == PartKind::prose || part.kind == PartKind::scene) && names_pixel(part.text);
    };
    if (view.format == LessonFormat::html) {
        out = fmt::format("<section class=\"lesson-step\" data-step=\"{}\" data-steps=\"{}\">\n<h2>", k + 1, view.lesson.steps.size()) +
              html_escape(heading) + "</h2>\n";
        if (!missing.empty()) out += "<p class=\"needs\"><em>" + html_escape(missing) + "</em></p>\n";
        for (const LessonPart& part : step.parts)
            if (!skipped(part)) out += html_part(view, part, named);
        return out + "</section>\n";
    }
    if (view.format == LessonFormat::markdown) {
        out = "## " + heading + "\n";
        if (!missing.empty()) out += "\n*" + missing + "*\n";
        for (const LessonPart& part : step.parts) {
            if (skipped(part)) continue;
            const std::string text = markdown_part(view, part, named);
            if (!text.empty()) out += "\n" + text;
        }
        return out;
    }
    out = bold(view, "── " + heading + " ──") + "\n";
    if (!missing.empty()) out += "\n" + wrap(missing, 0, 0) + "\n";
    for (const LessonPart& part : step.parts) {
        if (skipped(part)) continue;
        const std::string text = text_part(view, part, named);
        if (!text.empty()) out += "\n" + text;
    }
    return out;
}

std::string render_answers(const LessonView& view, std::size_t k) {
    const LessonStep& step = view.lesson.steps.at(k);
    const std::string title = message(view.lesson.language, "answer");
    std::string out;
    for (const LessonPart& part : step.parts) {
        if (part.kind != PartKind::answer) continue;
        // The step's pixel: the first pixel column that has what the step
        // needs and whose computation reached every value its answers name
        // (an answer about t needs a pixel that hit). With none, no answer:
        // the step has said which pixel has one.
        const PixelTrace* pixel = step_pixel(view, step);
        if (pixel == nullptr) return "";
        const std::string text = fill(view, part.text, pixel);
        if (view.format == LessonFormat::html)
            out += fmt::format("<details class=\"answer\" data-step=\"{}\"><summary>", k + 1) + html_escape(title) +
                   "</summary>\n" + html_prose(text) + "</details>\n";
        else if (view.format == LessonFormat::markdown)
            out += "\n<details><summary>" + title + "</summary>\n\n" + text + "\n\n</details>\n";
        else
            out += "\n" + bold(view, title + ":") + "\n" + text_paragraphs(text, 0);
    }
    return out;
}

}  // namespace promyk
