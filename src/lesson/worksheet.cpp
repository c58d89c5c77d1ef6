#include "lesson/worksheet.hpp"
#include "util/wrap.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "lesson/lesson_html.hpp"
#include "trace/messages.hpp"

namespace promyk {

namespace {

const std::string dots = "..........";  // a place to write on paper; no Markdown markup
const std::string short_dots = "......";

// The shape of a blank: the vocabulary's kind, but three numbers where one is
// meant (a light's contribution in a coloured scene) are a colour, [r, g, b].
std::string blank_kind(const Vocabulary& vocabulary, const std::string& path, const std::optional<StepValue>& value) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    const std::string kind = entry ? entry->kind : "scalar";
    if (value && std::holds_alternative<Vec3d>(*value) && kind != "point" && kind != "vector") return "colour";
    return kind;
}

// In HTML a blank is first a mark that no escaping changes (two private-use
// characters around its number); fields() makes it an <input> once the
// step's HTML is whole, so a blank inside a formula can leave the formula.
const std::string mark_open = "\xEE\x80\x80";   // U+E000
const std::string mark_close = "\xEE\x80\x81";  // U+E001
const std::string math_open = "<span class=\"math\">";

std::string blank_mark(int number) { return mark_open + std::to_string(number) + mark_close; }

// The symbol a blank's comment and label name (Δ/4 for delta, P.x for a component).
std::string blank_symbol(const Vocabulary& vocabulary, const WorksheetBlank& blank, Language language) {
    const auto [path, settings] = split_settings(blank.key);
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    std::string symbol = entry ? optional_message(language, "symbol_" + entry->key).value_or(entry->symbol) : path;
    if (blank.component != 0) symbol += std::string(".") + blank.component;
    if (!settings.empty()) symbol += " (" + settings + ")";
    return symbol;
}

}  // namespace

Worksheet::Worksheet(LessonView& view) : view_(view) {
    view_.shown_value = [this](const PixelTrace& trace, const std::string& key, char component) -> std::optional<std::string> {
        if (is_scene_value(key)) return std::nullopt;  // the scene's values are given
        // A word (the nearest object, what a test found) is no number to compute: shown filled in.
        const std::optional<LessonNumber> number = lesson_number(view_, trace, key);
        if (number && std::holds_alternative<std::string>(number->value)) return std::nullopt;
        return blank_for(trace, key, component);
    };
}

std::string Worksheet::blank_text(int number, const std::string& kind, Language language) {
    if (kind != "point" && kind != "vector" && kind != "colour") return fmt::format("{}({})", dots, number);
    // No-break spaces: a point's blank is not split across two lines.
    const char* separator = language == Language::pl ? ";\u00a0" : ",\u00a0";
    const char* open = kind == "point" ? "(" : "[";
    const char* close = kind == "point" ? ")" : "]";
    return fmt::format("{}{}{}{}{}{}{}({})", open, short_dots, separator, short_dots, separator, short_dots, close, number);
}

std::string Worksheet::blank_for(const PixelTrace& trace, const std::string& key, char component) {
    const std::optional<LessonNumber> number = lesson_number(view_, trace, key);
    const std::string kind =
        component != 0 ? "scalar" : blank_kind(view_.vocabulary, key, number ? std::optional<StepValue>(number->value) : std::nullopt);
    const auto [found, added] = index_.emplace(std::make_tuple(trace.header.i, trace.header.j, key, component), blanks_.size());
    const bool html = view_.format == LessonFormat::html;
    if (!added) {
        const int shown = blanks_[found->second].number;
        return html ? blank_mark(shown) : blank_text(shown, kind, view_.lesson.language);
    }
    WorksheetBlank blank;
    blank.number = static_cast<int>(blanks_.size()) + 1;
    blank.i = trace.header.i;
    blank.j = trace.header.j;
    blank.key = key;
    blank.component = component;
    const LessonNumber own = component_of(number.value_or(LessonNumber{StepValue{0.0}, {}, "double"}), component);
    blank.value = own.value;
    blank.real_text = own.real_text;
    blank.real = own.real;
    blanks_.push_back(blank);
    has_field_.push_back(false);
    return html ? blank_mark(blank.number) : blank_text(blank.number, kind, view_.lesson.language);
}

std::string Worksheet::check_command() const {
    const Language language = view_.lesson.language;
    std::string pixels;
    // Another scene or pane than the lesson's own must be named again too.
    if (!view_.own_scene && !view_.scene_file.empty()) pixels += " --scene " + view_.scene_file;
    if (view_.w != view_.lesson.header.w) pixels += " --w " + std::to_string(view_.w);
    for (const PixelTrace& trace : view_.traces) pixels += fmt::format(" --pixel {},{}", trace.header.i, trace.header.j);
    // Settings other than the lesson's own (given with --real, --formula, --spp) must be given again.
    const TraceHeader& numbers = view_.traces.front().header;
    if (numbers.real != view_.lesson.header.real) pixels += " --real " + numbers.real;
    if (numbers.formula != view_.lesson.header.formula) pixels += " --formula " + numbers.formula;
    if (numbers.spp != view_.lesson.header.spp) pixels += " --spp " + std::to_string(numbers.spp);
    return fmt::format("promyk lesson {}{} --lang {} --answers {}", view_.lesson.header.name, pixels,
                       language_code(language), message(language, "worksheet_file"));
}

std::string Worksheet::intro() const {
    const Language language = view_.lesson.language;
    const std::string one_line = check_command();
    // The intro indents the command by 4 columns: a longer one is broken
    // into shell lines ending in " \\", each within 80 columns, so it can
    // still be copied and pasted as it stands.
    constexpr std::size_t indent = 4, continued = 6;
    std::string command;
    std::size_t used = indent;
    for (std::size_t start = 0; start < one_line.size();) {
        std::size_t next = one_line.find(" --", start + 1);
        if (next == std::string::npos) next = one_line.size();
        const std::string piece = one_line.substr(start, next - start);  // " --pixel 3,4"
        if (!command.empty() && used + piece.size() + 2 > text_columns) {
            command += " \\\n" + std::string(continued, ' ') + piece.substr(1);
            used = continued + piece.size() - 1;
        } else {
            command += piece;
            used += piece.size();
        }
        start = next;
    }
    // In HTML the blanks are fields, and the command a code block.
    if (view_.format == LessonFormat::html)
        return "<section class=\"worksheet-intro\">\n" +
               html_prose(message(language, "worksheet_intro_html", {{"command", command}})) + "</section>\n";
    return "\n" + message(language, "worksheet_intro", {{"command", command}}) + "\n";
}

std::string Worksheet::form_lines(const std::map<int, std::string>& typed, std::size_t indent) const {
    const Language language = view_.lesson.language;
    // Each pixel's blanks, gathered once (a lesson may have 10^5 pixels).
    std::map<std::pair<int, int>, std::vector<const WorksheetBlank*>> by_pixel;
    for (const WorksheetBlank& blank : blanks_) by_pixel[{blank.i, blank.j}].push_back(&blank);
    std::vector<std::string> lines;
    std::size_t width = 0;
    for (const PixelTrace& trace : view_.traces) {
        const int i = trace.header.i, j = trace.header.j;
        const auto found = by_pixel.find({i, j});
        if (found == by_pixel.end()) continue;
        std::vector<const WorksheetBlank*> mine = std::move(found->second);
        by_pixel.erase(found);  // a pixel chosen twice gets one heading
        // In derivation order, as the answers are checked.
        const auto order = [&](const WorksheetBlank* blank) { return derivation_rank(trace, view_.vocabulary, blank->key); };
        std::stable_sort(mine.begin(), mine.end(), [&](const WorksheetBlank* a, const WorksheetBlank* b) { return order(a) < order(b); });
        if (mine.empty()) continue;
        lines.push_back(fmt::format("[{},{}]", i, j));
        for (const WorksheetBlank* blank : mine) {
            const auto [path, settings] = split_settings(blank->key);
            const std::string key = qualified_path(path, blank->component, settings);
            // A typed value on one line: a line break or a '#' would end it early.
            std::string value;
            if (const auto given = typed.find(blank->number); given != typed.end())
                for (const char c : given->second) value += c == '\n' || c == '\r' || c == '#' ? ' ' : c;
            value.erase(0, value.find_first_not_of(" \t"));
            value.erase(value.find_last_not_of(" \t") + 1);
            lines.push_back(key + " = " + value);
            width = std::max(width, display_width(lines.back()));
            lines.back() += "\t" + std::to_string(blank->number);
            // The symbol beside a key that does not read as one (delta: Δ/4, EE: |E|²).
            if (const VocabularyEntry* entry = view_.vocabulary.find(path_key(path))) {
                std::string symbol = optional_message(language, "symbol_" + entry->key).value_or(entry->symbol);
                if (blank->component != 0) symbol += std::string(".") + blank->component;
                if (symbol != key && symbol != path && symbol != path_key(path)) lines.back() += ") " + symbol;
            }
        }
    }
    // "key = " then a comment naming the blank, aligned.
    std::string out;
    for (const std::string& line : lines) {
        const std::size_t tab = line.find('\t');
        if (tab == std::string::npos) {
            out += std::string(indent, ' ') + line + "\n";
        } else {
            const std::string start = line.substr(0, tab);
            const std::string comment = line.substr(tab + 1);  // "21) Δ/4", or "7" alone
            out += std::string(indent, ' ') + start + std::string(width - display_width(start) + 8, ' ') + "# (" + comment +
                   (comment.find(')') == std::string::npos ? ")" : "") + "\n";
        }
    }
    return out;
}

std::string Worksheet::answer_lines(const std::map<int, std::string>& typed) const { return form_lines(typed, 0); }

std::string Worksheet::answer_template() const {
    const Language language = view_.lesson.language;
    const std::string heading = message(language, "worksheet_template_heading", {{"file", message(language, "worksheet_file")}});
    if (view_.format == LessonFormat::html)
        return "<section class=\"worksheet-form\">\n<h2>" + html_escape(heading) + "</h2>\n" +
               html_prose(message(language, "worksheet_template_intro")) + "<pre><code>" + html_escape(form_lines({}, 0)) +
               "</code></pre>\n</section>\n";
    const bool markdown = view_.format == LessonFormat::markdown;
    std::string out = markdown ? "\n## " + heading + "\n\n" : "\n── " + heading + " ──\n\n";
    out += message(language, "worksheet_template_intro") + "\n\n";
    return out + form_lines({}, 4);
}

std::string Worksheet::answer_key() const {
    const Language language = view_.lesson.language;
    const bool markdown = view_.format == LessonFormat::markdown;
    const bool html = view_.format == LessonFormat::html;
    const std::string heading = message(language, "worksheet_key_heading");
    std::string out = html       ? "<section class=\"worksheet-key\">\n<h2>" + html_escape(heading) + "</h2>\n<ul>\n"
                      : markdown ? "\n## " + heading + "\n\n"
                                 : "\n── " + heading + " ──\n\n";
    for (const WorksheetBlank& blank : blanks_) {
        const VocabularyEntry* entry = view_.vocabulary.find(path_key(blank.key));
        const auto [path, settings] = split_settings(blank.key);
        std::string symbol = entry ? entry->symbol : path;
        if (blank.component != 0) symbol += std::string(".") + blank.component;
        if (!settings.empty()) symbol += " (" + settings + ")";
        const std::string key = qualified_path(path, blank.component, settings);
        const std::string kind = blank.component != 0 ? "scalar" : blank_kind(view_.vocabulary, blank.key, blank.value);
        const std::string line = message(
            language, "worksheet_key_line",
            {{"n", std::to_string(blank.number)},
             {"pixel", message(language, "pixel_label", {{"i", std::to_string(blank.i)}, {"j", std::to_string(blank.j)}})},
             {"symbol", symbol},
             {"key", key},
             {"value", lesson_number_text(LessonNumber{blank.value, blank.real_text, blank.real}, kind, language,
                                          shown_digits_default, view_.digits)}});
        out += html ? "<li>" + html_escape(line) + "</li>\n" : markdown ? "- " + line + "\n" : wrap_text("  " + line, 6) + "\n";
    }
    return html ? out + "</ul>\n</section>\n" : out;
}

std::string Worksheet::field(const WorksheetBlank& blank, bool first) const {
    const Language language = view_.lesson.language;
    const std::string kind = blank.component != 0 ? "scalar" : blank_kind(view_.vocabulary, blank.key, blank.value);
    const std::string n = std::to_string(blank.number);
    if (!first)  // the same number again: its number, as on paper; the page may show what was typed
        return "<span class=\"blank-copy\" data-blank=\"" + n + "\">" + html_escape(blank_text(blank.number, kind, language)) +
               "</span>";
    const auto [path, settings] = split_settings(blank.key);
    const std::string label = message(
        language, "worksheet_field_label",
        {{"n", n},
         {"symbol", blank_symbol(view_.vocabulary, blank, language)},
         {"pixel", message(language, "pixel_label", {{"i", std::to_string(blank.i)}, {"j", std::to_string(blank.j)}})}});
    const bool three = kind == "point" || kind == "vector" || kind == "colour";
    return fmt::format("<span class=\"blank\" data-blank=\"{0}\"><input type=\"text\" id=\"blank-{0}\" name=\"blank-{0}\" "
                       "class=\"blank-field\" data-blank=\"{0}\" data-kind=\"{1}\" data-key=\"{2}\" data-i=\"{3}\" "
                       "data-j=\"{4}\" size=\"{5}\" autocomplete=\"off\" spellcheck=\"false\">"
                       "<label for=\"blank-{0}\"><span aria-hidden=\"true\">({0})</span><span class=\"sr-only\">{6}</span></label>"
                       "</span>",
                       n, html_escape(kind), html_escape(qualified_path(path, blank.component, settings)), blank.i, blank.j,
                       three ? 22 : 9, html_escape(label));
}

std::string Worksheet::fields(const std::string& rendered) {
    if (view_.format != LessonFormat::html || rendered.find(mark_open) == std::string::npos) return rendered;
    std::string out;
    out.reserve(rendered.size() + 512);
    bool in_math = false;  // inside <span class="math">: its TeX has no tags, its </span> closes it
    for (std::size_t k = 0; k < rendered.size();) {
        if (rendered.compare(k, math_open.size(), math_open) == 0) {
            in_math = true;
            out += math_open;
            k += math_open.size();
            continue;
        }
        if (in_math && rendered.compare(k, 7, "</span>") == 0) in_math = false;
        if (rendered.compare(k, mark_open.size(), mark_open) == 0) {
            const std::size_t end = rendered.find(mark_close, k);
            const int number = std::stoi(rendered.substr(k + mark_open.size(), end - k - mark_open.size()));
            const std::size_t index = static_cast<std::size_t>(number - 1);
            const std::string made = field(blanks_[index], !has_field_[index]);
            has_field_[index] = true;
            // A field is no TeX: the formula is closed before it and opened again after it.
            out += in_math ? "</span>" + made + math_open : made;
            k = end + mark_close.size();
            continue;
        }
        out += rendered[k++];
    }
    // A formula split at its start or end leaves an empty one.
    const std::string empty = math_open + "</span>";
    for (std::size_t at; (at = out.find(empty)) != std::string::npos;) out.erase(at, empty.size());
    return out;
}

}  // namespace promyk
