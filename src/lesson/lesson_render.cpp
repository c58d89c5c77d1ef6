#include "lesson/lesson_render.hpp"

#include "util/text.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "trace/messages.hpp"
#include "trace/keys.hpp"
#include "trace/trace_text.hpp"
#include "render/world.hpp"

namespace promyk {

namespace {

constexpr std::size_t columns = 80;

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

std::string branch_text(const Vocabulary& vocabulary, Branch branch, Language language) {
    const BranchEntry* entry = vocabulary.find_branch(branch_name(branch));
    if (entry == nullptr) return std::string(branch_name(branch));
    return language == Language::pl ? entry->pl : entry->en;
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
    const std::optional<ValuePath> parsed = parse_value_path(path);
    const std::string suffix = latex ? "_latex" : "";
    if (parsed && !parsed->groups.empty())
        if (auto own = optional_message(language, "formula_" + parsed->groups.back().kind + "_" + entry.key + suffix)) return *own;
    if (auto own = optional_message(language, "formula_" + entry.key + suffix)) return *own;
    return latex ? entry.formula_latex : entry.formula;
}

// The text with its placeholders filled for one pixel (or for none: prose).
std::string fill(const LessonView& view, const std::string& text, const PixelTrace* trace) {
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
        } else if (trace == nullptr && (p.name == "i" || p.name == "j" || p.name == "branch")) {
            out += message(language, "not_reached");
        } else if (p.name == "i" || p.name == "j") {
            out += std::to_string(p.name == "i" ? trace->header.i : trace->header.j);
        } else if (p.name == "branch") {
            out += branch_text(view.vocabulary, trace->branch, language);
        } else {
            // Prose may name only the scene's values, the same in every trace.
            const PixelTrace& source = trace != nullptr ? *trace : view.traces.front();
            const std::optional<StepValue> value = lesson_value(source, p.path);
            std::optional<std::string> shown;
            if (value && trace != nullptr && view.shown_value) shown = view.shown_value(*trace, p.path, p.component);
            if (!value) {
                out += message(language, "not_reached");
            } else if (shown) {
                out += *shown;
            } else if (p.component != 0 && std::holds_alternative<Vec3d>(*value)) {
                const Vec3d& v = std::get<Vec3d>(*value);
                out += number_text(p.component == 'x' ? v.x : p.component == 'y' ? v.y : v.z, language, p.decimals);
            } else {
                out += value_text(*value, shown_kind(view.vocabulary, p.path, *value), language, p.decimals);
            }
        }
    }
    copy_literal(text.size());
    return out;
}

// A value table's cell: the value, or what a worksheet shows in its place.
std::string cell_text(const LessonView& view, const PixelTrace& trace, const std::string& key, const StepValue& value) {
    if (view.shown_value)
        if (std::optional<std::string> shown = view.shown_value(trace, key, 0)) return *shown;
    return value_text(value, shown_kind(view.vocabulary, key, value), view.lesson.language);
}

std::string pixel_label(const LessonView& view, const PixelTrace& trace) {
    return message(view.lesson.language, "pixel_label",
                   {{"i", std::to_string(trace.header.i)}, {"j", std::to_string(trace.header.j)}});
}

// A table row's groups, in the lesson's language: " (light 0, sphere 1)",
// or nothing for a top-level key.
std::string group_suffix(const LessonView& view, const std::string& key) {
    const std::optional<ValuePath> path = parse_value_path(key);
    if (!path || path->groups.empty()) return "";
    std::string out;
    for (const PathGroup& group : path->groups)
        out += (out.empty() ? "" : ", ") + group_text(view.lesson.language, group.kind, group.index);
    return " (" + out + ")";
}

bool shown_for(const LessonPart& part, const PixelTrace& trace) {
    if (part.branches.empty()) return true;
    return std::find(part.branches.begin(), part.branches.end(), branch_name(trace.branch)) != part.branches.end();
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

std::string wrap(const std::string& text, std::size_t indent, std::size_t first_used = 0) {
    std::string out;
    std::size_t used = first_used;
    std::size_t k = 0;
    bool first_word = true;
    while (k < text.size()) {
        const std::size_t space = text.find(' ', k);
        const std::string word = text.substr(k, space == std::string::npos ? std::string::npos : space - k);
        k = space == std::string::npos ? text.size() : space + 1;
        if (word.empty()) continue;
        if (!first_word && used + 1 + display_width(word) > columns) {
            out += '\n' + std::string(indent, ' ');
            used = indent;
        } else if (!first_word) {
            out += ' ';
            ++used;
        }
        out += word;
        used += display_width(word);
        first_word = false;
    }
    return out;
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
        } else if (line.rfind("|", 0) == 0) {
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
    for (const std::string& key : part.keys) {
        const VocabularyEntry* entry = view.vocabulary.find(path_key(key));
        const std::string symbol = (entry ? lesson_symbol(language, *entry) : key) + group_suffix(view, key);
        const std::string formula = entry ? lesson_formula(language, key, *entry, false) : "";
        out += "  " + symbol + (formula.empty() ? "" : " = " + formula) + "\n";
        std::vector<std::string> cells;
        for (const PixelTrace& trace : view.traces) {
            const std::optional<StepValue> value = lesson_value(trace, key);
            cells.push_back(fmt::format("({}, {}): {}", trace.header.i, trace.header.j,
                                        value ? cell_text(view, trace, key, *value) : message(language, "not_reached")));
        }
        std::size_t total = 4;
        for (const std::string& cell : cells) total += display_width(cell) + 4;
        if (total <= columns) {
            std::string line = "    ";
            for (std::size_t c = 0; c < cells.size(); ++c) line += (c ? "    " : "") + cells[c];
            out += line + "\n";
        } else {
            for (const std::string& cell : cells) out += "    " + cell + "\n";
        }
    }
    return out;
}

std::string text_part(const LessonView& view, const LessonPart& part) {
    switch (part.kind) {
        case PartKind::prose:
            return text_paragraphs(fill(view, part.text, nullptr), 0);
        case PartKind::values:
            return text_values(view, part);
        case PartKind::block: {
            std::string out;
            for (const PixelTrace& trace : view.traces) {
                if (!shown_for(part, trace)) continue;
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

// --- Markdown -------------------------------------------------------------

std::string markdown_values(const LessonView& view, const LessonPart& part) {
    const Language language = view.lesson.language;
    std::string out = "| |";
    for (const PixelTrace& trace : view.traces) out += " " + pixel_label(view, trace) + " |";
    out += "\n|---|";
    for (std::size_t c = 0; c < view.traces.size(); ++c) out += "---|";
    out += "\n";
    for (const std::string& key : part.keys) {
        const VocabularyEntry* entry = view.vocabulary.find(path_key(key));
        std::string math = key;
        if (entry != nullptr) {
            math = lesson_formula(language, key, *entry, true);
            if (math.empty()) math = entry->latex;
        }
        // A | would end the table's cell: LaTeX's \vert draws the same bar.
        for (std::size_t bar = math.find('|'); bar != std::string::npos; bar = math.find('|', bar))
            math.replace(bar, 1, "\\vert ");
        out += "| $" + math + "$" + group_suffix(view, key) + " |";
        for (const PixelTrace& trace : view.traces) {
            const std::optional<StepValue> value = lesson_value(trace, key);
            out += " " + (value ? cell_text(view, trace, key, *value) : message(language, "not_reached")) + " |";
        }
        out += "\n";
    }
    return out;
}

std::string markdown_part(const LessonView& view, const LessonPart& part) {
    switch (part.kind) {
        case PartKind::prose:
            return fill(view, part.text, nullptr) + "\n";
        case PartKind::values:
            return markdown_values(view, part);
        case PartKind::block: {
            std::string out;
            for (const PixelTrace& trace : view.traces) {
                if (!shown_for(part, trace)) continue;
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
    return std::nullopt;
}

bool is_scene_value(const std::string& key) {
    const std::optional<ValuePath> path = parse_value_path(key);
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
    const std::optional<ValuePath> path = parse_value_path(key);
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
    if (view.format == LessonFormat::markdown)
        return "# " + heading + "\n\n*" + view.lesson.header.summary + "*\n\n" + setup + "\n";
    return bold(view, heading) + "\n" + wrap(view.lesson.header.summary, 0) + "\n" + wrap(setup, 0) + "\n";
}

std::string render_step(const LessonView& view, std::size_t k) {
    const LessonStep& step = view.lesson.steps.at(k);
    const std::string heading =
        message(view.lesson.language, "step_heading",
                {{"k", std::to_string(k + 1)}, {"n", std::to_string(view.lesson.steps.size())}, {"title", step.title}});
    std::string out;
    if (view.format == LessonFormat::markdown) {
        out = "## " + heading + "\n";
        for (const LessonPart& part : step.parts) {
            const std::string text = markdown_part(view, part);
            if (!text.empty()) out += "\n" + text;
        }
        return out;
    }
    out = bold(view, "── " + heading + " ──") + "\n";
    for (const LessonPart& part : step.parts) {
        const std::string text = text_part(view, part);
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
        // The first pixel column whose computation reached every value the
        // answer names (an answer about t needs a pixel that hit).
        const PixelTrace* pixel = &view.traces.front();
        for (const PixelTrace& trace : view.traces) {
            const std::vector<Placeholder> placeholders = find_placeholders(part.text);
            if (std::all_of(placeholders.begin(), placeholders.end(), [&](const Placeholder& p) {
                    return !p.valid || p.symbol || view.vocabulary.find(p.name) == nullptr || lesson_value(trace, p.path);
                })) {
                pixel = &trace;
                break;
            }
        }
        const std::string text = fill(view, part.text, pixel);
        if (view.format == LessonFormat::markdown)
            out += "\n<details><summary>" + title + "</summary>\n\n" + text + "\n\n</details>\n";
        else
            out += "\n" + bold(view, title + ":") + "\n" + text_paragraphs(text, 0);
    }
    return out;
}

}  // namespace promyk
