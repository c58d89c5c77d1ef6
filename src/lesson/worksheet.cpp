#include "lesson/worksheet.hpp"
#include "util/wrap.hpp"

#include <algorithm>

#include <fmt/format.h>

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
    if (!added) return blank_text(blanks_[found->second].number, kind, view_.lesson.language);
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
    return blank_text(blank.number, kind, view_.lesson.language);
}

std::string Worksheet::intro() const {
    const Language language = view_.lesson.language;
    std::string pixels;
    for (const PixelTrace& trace : view_.traces) pixels += fmt::format(" --pixel {},{}", trace.header.i, trace.header.j);
    // Settings other than the lesson's own (given with --real, --formula, --spp) must be given again.
    const TraceHeader& numbers = view_.traces.front().header;
    if (numbers.real != view_.lesson.header.real) pixels += " --real " + numbers.real;
    if (numbers.formula != view_.lesson.header.formula) pixels += " --formula " + numbers.formula;
    if (numbers.spp != view_.lesson.header.spp) pixels += " --spp " + std::to_string(numbers.spp);
    const std::string one_line =
        fmt::format("promyk lesson {}{} --lang {} --answers {}", view_.lesson.header.name, pixels,
                    language_code(language), message(language, "worksheet_file"));
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
    return "\n" + message(language, "worksheet_intro", {{"command", command}}) + "\n";
}

std::string Worksheet::answer_template() const {
    const Language language = view_.lesson.language;
    const bool markdown = view_.format == LessonFormat::markdown;
    const std::string heading = message(language, "worksheet_template_heading", {{"file", message(language, "worksheet_file")}});
    std::string out = markdown ? "\n## " + heading + "\n\n" : "\n── " + heading + " ──\n\n";
    out += message(language, "worksheet_template_intro") + "\n\n";
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
            lines.push_back(key + " = ");
            width = std::max(width, lines.back().size());
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
    for (const std::string& line : lines) {
        const std::size_t tab = line.find('\t');
        if (tab == std::string::npos) {
            out += "    " + line + "\n";
        } else {
            const std::string start = line.substr(0, tab);
            const std::string comment = line.substr(tab + 1);  // "21) Δ/4", or "7" alone
            out += "    " + start + std::string(width - start.size() + 8, ' ') + "# (" + comment +
                   (comment.find(')') == std::string::npos ? ")" : "") + "\n";
        }
    }
    return out;
}

std::string Worksheet::answer_key() const {
    const Language language = view_.lesson.language;
    const bool markdown = view_.format == LessonFormat::markdown;
    const std::string heading = message(language, "worksheet_key_heading");
    std::string out = markdown ? "\n## " + heading + "\n\n" : "\n── " + heading + " ──\n\n";
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
        out += markdown ? "- " + line + "\n" : wrap_text("  " + line, 6) + "\n";
    }
    return out;
}

}  // namespace promyk
