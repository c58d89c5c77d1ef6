// Reading lesson files: the header between two "---" lines, then steps
// ("## [id] Title") made of prose, value tables ("= keys") and ":::" blocks.
#include <algorithm>
#include <cctype>
#include <regex>
#include <set>

#include "render/samples.hpp"
#include "lesson/lesson.hpp"
#include "util/text.hpp"
#include "trace/messages.hpp"
#include "util/printable.hpp"

namespace promyk {

namespace {

const std::vector<std::string_view> header_fields = {"name", "title", "summary", "scene", "w", "pixels", "columns", "real", "formula", "spp", "digits", "effect"};

std::vector<std::string> split_lines(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte order mark
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        std::string line(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    if (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    std::size_t k = 0;
    while (k < text.size()) {
        while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
        const std::size_t start = k;
        while (k < text.size() && !std::isspace(static_cast<unsigned char>(text[k]))) ++k;
        if (k > start) out.emplace_back(text.substr(start, k - start));
    }
    return out;
}

// Whole numbers as a person writes them (no sign games, no leading zeros).
bool plain_whole(const std::string& text, long min, long max, int& value) {
    if (text.size() > 9 || !is_plain_decimal(text)) return false;
    const long number = std::stol(text);
    if (number < min || number > max) return false;
    value = static_cast<int>(number);
    return true;
}

bool ascii_alnum(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

// The hand-written matchers below replace std::regex, whose matching recurses
// once a character: a line of a few megabytes overflowed the stack.

// [a-z0-9][a-z0-9-]*
bool lesson_name(const std::string& text) {
    const auto lower = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); };
    return !text.empty() && lower(text[0]) && std::all_of(text.begin(), text.end(), [&](char c) { return lower(c) || c == '-'; });
}

// "0,0 5,1 (3, 4)": the pixels, or nothing if the text has another form.
std::optional<std::vector<LessonPixel>> pixel_list(const std::string& text) {
    std::vector<LessonPixel> pixels;
    std::size_t k = 0;
    const auto spaces = [&] {
        while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
    };
    const auto whole = [&](int& value) {
        const std::size_t start = k;
        while (k < text.size() && text[k] >= '0' && text[k] <= '9') ++k;
        if (k == start || k - start > 5) return false;  // a pane has at most 32768 pixels a side
        value = std::stoi(text.substr(start, k - start));
        return true;
    };
    for (spaces(); k < text.size(); spaces()) {
        const bool open = text[k] == '(';
        if (open) ++k;
        LessonPixel pixel;
        spaces();
        if (!whole(pixel.i)) return std::nullopt;
        spaces();
        if (k == text.size() || text[k] != ',') return std::nullopt;
        ++k;
        spaces();
        if (!whole(pixel.j)) return std::nullopt;
        spaces();
        if (open) {
            if (k == text.size() || text[k] != ')') return std::nullopt;
            ++k;
        }
        pixels.push_back(pixel);
    }
    if (pixels.empty()) return std::nullopt;
    return pixels;
}

// "## [id] Title": the id (letters, digits, -) and the title.
bool step_heading(const std::string& line, std::string& id, std::string& title) {
    std::size_t k = 2;  // after "##"
    while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    if (k == 2 || k == line.size() || line[k] != '[') return false;
    const std::size_t close = line.find(']', k);
    if (close == std::string::npos || close == k + 1 ||
        !std::all_of(line.begin() + static_cast<long>(k) + 1, line.begin() + static_cast<long>(close),
                     [](char c) { return ascii_alnum(c) || c == '-'; }))
        return false;
    id = line.substr(k + 1, close - k - 1);
    title = trim(line.substr(close + 1));
    return true;
}

// The first character of `line` that must not reach a terminal raw (a
// control character but tab, a bidirectional control, a byte that is not
// UTF-8), escaped as printable() writes it; empty when there is none.
std::string unprintable_in(std::string line) {
    line.erase(std::remove(line.begin(), line.end(), '\t'), line.end());
    const std::string safe = printable(line);
    if (safe == line) return "";
    const std::size_t at = static_cast<std::size_t>(std::mismatch(line.begin(), line.end(), safe.begin()).first - line.begin());
    return safe.substr(at, safe[at + 1] == 'x' ? 4 : safe[at + 1] == 'u' ? 6 : 2);
}

class Parser {
public:
    Parser(const std::string& file, Language language, std::vector<LessonProblem>& problems)
        : file_(file), language_(language), problems_(problems) {}

    Lesson parse(std::string_view text) {
        Lesson lesson;
        lesson.file = file_;
        lesson.language = language_;
        const std::vector<std::string> lines = split_lines(text);
        // A lesson is printed on a terminal: its text is plain UTF-8 with no
        // control character but tab (the first fault a file is enough).
        for (std::size_t k = 0; k < lines.size(); ++k) {
            const std::string bad = unprintable_in(lines[k]);
            if (!bad.empty()) {
                problem(static_cast<int>(k + 1), "error_control_character", {{"char", bad}});
                break;
            }
        }
        std::size_t k = read_header(lines, lesson.header);
        read_body(lines, k, lesson);
        return lesson;
    }

private:
    void problem(int line, std::string_view id, const MessageArgs& args = {}) {
        problems_.push_back({file_, line, message(language_, id, args)});
    }

    // Returns the index of the first body line.
    std::size_t read_header(const std::vector<std::string>& lines, LessonHeader& header) {
        if (lines.empty() || trim(lines[0]) != "---") {
            problem(1, "error_header_missing");
            return 0;
        }
        std::vector<bool> seen(header_fields.size(), false);  // sized by the list: a new field cannot overrun it
        std::size_t k = 1;
        for (; k < lines.size(); ++k) {
            const std::string line = trim(lines[k]);
            const int number = static_cast<int>(k + 1);
            if (line == "---") break;
            if (line.empty() || line[0] == '#') continue;
            const std::size_t colon = line.find(':');
            const std::string field = trim(line.substr(0, colon));
            const auto known = std::find(header_fields.begin(), header_fields.end(), field);
            if (colon == std::string::npos || known == header_fields.end()) {
                problem(number, "error_header_field", {{"field", field}, {"fields", joined(header_fields)}});
                continue;
            }
            seen[known - header_fields.begin()] = true;
            read_field(field, trim(line.substr(colon + 1)), number, header);
        }
        if (k == lines.size()) {
            problem(1, "error_header_unclosed");
            return k;
        }
        for (const LessonPixel& pixel : header.pixels)
            if (pixel.i >= header.w || pixel.j >= header.w) {
                problem(pixels_line_, "error_header_value",
                        {{"field", "pixels"}, {"problem", "0 … w − 1 (w = " + std::to_string(header.w) + ")"}});
                break;
            }
        for (std::size_t f = 0; f < 3; ++f)
            if (!seen[f]) problem(static_cast<int>(k + 1), "error_header_required", {{"field", std::string(header_fields[f])}});
        return k + 1;
    }

    void read_field(const std::string& field, const std::string& value, int line, LessonHeader& header) {
        if (field == "name") {
            header.name_line = line;
            if (!lesson_name(value))
                problem(line, "error_header_value", {{"field", field}, {"problem", "a-z, 0-9, -"}});
            header.name = value;
        } else if (field == "title") {
            header.title = value;
        } else if (field == "summary") {
            header.summary = value;
        } else if (field == "scene") {
            header.scene_line = line;
            if (value.empty() || value.find('/') != std::string::npos || value == "." || value == "..")
                problem(line, "error_header_value", {{"field", field}, {"problem", "article, or a file of lessons/scenes/"}});
            header.scene = value;
        } else if (field == "w") {
            if (!plain_whole(value, 1, 32768, header.w))
                problem(line, "error_header_value", {{"field", field}, {"problem", "1 … 32768"}});
        } else if (field == "pixels") {
            pixels_line_ = line;
            const std::optional<std::vector<LessonPixel>> pixels = pixel_list(value);
            header.pixels = pixels.value_or(std::vector<LessonPixel>{});
            if (!pixels)
                problem(line, "error_header_value", {{"field", field}, {"problem", "I,J I,J …"}});
        } else if (field == "columns") {
            // real/formula for each pixel column, or one for all: the names
            // PRODUCT.md gives them. This version computes double/article only;
            // the runner says so when a lesson asks for another.
            static const std::regex column(
                R"((float|double|long-double|quad)/(article|stable|fma|geometric))");
            const std::vector<std::string> items = words(value);
            const bool ok = !items.empty() && std::all_of(items.begin(), items.end(), [](const std::string& item) {
                return item.size() <= 32 && std::regex_match(item, column);
            });
            if (!ok)
                problem(line, "error_header_value",
                        {{"field", field}, {"problem", "REAL/FORMULA …, e.g. double/article float/article"}});
            header.columns = value;
        } else if (field == "real") {
            if (!is_real_name(value))
                problem(line, "error_header_value", {{"field", field}, {"problem", "float, double, long-double, quad"}});
            header.real = value;
        } else if (field == "formula") {
            if (!is_formula_name(value))
                problem(line, "error_header_value", {{"field", field}, {"problem", "article, stable, fma, geometric"}});
            header.formula = value;
        } else if (field == "digits") {
            const bool number = !value.empty() && value.size() <= 2 && value.find_first_not_of("0123456789") == std::string::npos;
            if (value == "all")
                header.digits = 0;
            else if (number && std::stoi(value) >= 1 && std::stoi(value) <= 40)
                header.digits = std::stoi(value);
            else
                problem(line, "error_header_value", {{"field", field}, {"problem", "1 … 40, or all"}});
        } else if (field == "effect") {
            static const std::vector<std::string_view> effects = {"spheres", "lights", "plane", "shadows", "phong", "colour"};
            if (std::find(effects.begin(), effects.end(), value) == effects.end())
                problem(line, "error_header_value", {{"field", field}, {"problem", joined(effects)}});
            header.effect = value;
        } else if (field == "spp") {
            const bool digits = !value.empty() && value.size() <= 4 && value.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || !valid_spp(std::stoi(value)))
                problem(line, "error_header_value", {{"field", field}, {"problem", "1, 4, 9, 16, … 1024 (a square)"}});
            else
                header.spp = std::stoi(value);
        }
    }

    void read_body(const std::vector<std::string>& lines, std::size_t k, Lesson& lesson) {
        LessonStep* step = nullptr;
        LessonPart* block = nullptr;  // the open ::: block
        LessonPart prose;
        bool complained_before_step = false;
        bool fence = false;  // inside ``` … ```: lines are text, never structure
        std::set<std::string> step_ids;
        const auto flush_prose = [&] {
            // Blank lines around a part carry no meaning.
            while (!prose.text.empty() && prose.text.back() == '\n') prose.text.pop_back();
            if (step != nullptr && !trim(prose.text).empty()) step->parts.push_back(prose);
            prose = LessonPart{};
        };
        for (; k < lines.size(); ++k) {
            const std::string& line = lines[k];
            const int number = static_cast<int>(k + 1);
            const std::string trimmed = trim(line);
            if (trimmed.rfind("```", 0) == 0) fence = !fence;
            const bool in_fence = fence || trimmed.rfind("```", 0) == 0;
            if (in_fence && step != nullptr) {
                LessonPart& target = block != nullptr ? *block : prose;
                if (target.text.empty() && target.kind == PartKind::prose) {
                    target.line = number;
                }
                if (target.text_line == 0) target.text_line = number;
                if (block != nullptr)
                    target.text += (target.text.empty() ? "" : "\n") + line;
                else
                    target.text += line + "\n";
                continue;
            }
            if (block != nullptr) {
                if (trimmed == ":::") {
                    block = nullptr;
                } else if (trimmed.rfind(":::", 0) == 0) {
                    problem(number, "error_nested_block");
                } else {
                    if (block->text.empty() && !trimmed.empty()) block->text_line = number;
                    if (!block->text.empty() || !trimmed.empty()) block->text += (block->text.empty() ? "" : "\n") + line;
                }
                continue;
            }
            if (line.rfind("## ", 0) == 0) {
                flush_prose();
                LessonStep next;
                next.line = number;
                if (!step_heading(trimmed, next.id, next.title)) problem(number, "error_step_heading");
                if (!next.id.empty() && !step_ids.insert(next.id).second) problem(number, "error_duplicate_step", {{"id", next.id}});
                lesson.steps.push_back(next);
                step = &lesson.steps.back();
                continue;
            }
            if (step == nullptr) {
                if (!trimmed.empty() && !complained_before_step) {
                    problem(number, "error_text_before_step");
                    complained_before_step = true;
                }
                continue;
            }
            if (trimmed.rfind(":::", 0) == 0) {
                flush_prose();
                const std::vector<std::string> names = words(trimmed.substr(3));
                if (names.empty()) {
                    problem(number, "error_stray_close");
                    continue;
                }
                LessonPart part;
                part.line = number;
                // One-line directives: no body, no closing ":::".
                if (names[0] == "needs") {
                    if (step->needs_line != 0) problem(number, "error_needs_twice");
                    step->needs_line = number;
                    for (std::size_t n = 1; n < names.size(); ++n) {
                        if (std::optional<Condition> condition = parse_condition(names[n]))
                            step->needs.push_back(*condition);
                        else
                            step->needs_branches.push_back(names[n]);
                    }
                    if (names.size() == 1) problem(number, "error_needs_empty");
                    continue;
                }
                if (names[0] == "figure") {
                    part.kind = PartKind::figure;
                    part.figure = names.size() > 1 ? names[1] : "";
                    if (names.size() != 2 || names[1] != "pane") problem(number, "error_figure", {{"figure", trimmed}});
                    step->parts.push_back(part);
                    continue;
                }
                if (names.size() == 1 && names[0] == "answer") {
                    part.kind = PartKind::answer;
                } else if (names[0] == "scene") {
                    part.kind = PartKind::scene;
                    if (names.size() > 2) problem(number, "error_scene_block", {{"text", trimmed}});
                    if (names.size() == 2) part.scene = names[1];
                } else {
                    part.kind = PartKind::block;
                    bool every = false;
                    for (const std::string& name : names) {
                        if (std::optional<Condition> condition = parse_condition(name))
                            part.conditions.push_back(*condition);
                        else if (name == "pixel")
                            every = true;
                        else
                            part.branches.push_back(name);
                    }
                    if (every) part.branches.clear();
                }
                step->parts.push_back(part);
                block = &step->parts.back();
                continue;
            }
            if (line.rfind("= ", 0) == 0) {  // at the start of the line: an indented "= " is prose
                flush_prose();
                LessonPart part;
                part.kind = PartKind::values;
                part.line = number;
                part.keys = words(std::string_view(line).substr(2));  // "= " with nothing after: trimmed is "="
                step->parts.push_back(part);
                continue;
            }
            if (prose.text.empty()) {
                if (trimmed.empty()) continue;
                prose.line = number;
                prose.text_line = number;
            }
            prose.text += line + "\n";
        }
        flush_prose();
        if (block != nullptr) problem(block->line, "error_unclosed_block");
        if (lesson.steps.empty()) problem(std::max(1, static_cast<int>(lines.size())), "error_no_steps");  // an empty file has line 1
    }

    const std::string& file_;
    Language language_;
    std::vector<LessonProblem>& problems_;
    int pixels_line_ = 0;  // the header's "pixels:" line
};

}  // namespace

std::optional<Condition> parse_condition(const std::string& token) {
    Condition condition;
    condition.text = token;
    const auto path_ok = [](const std::string& path) {
        return !path.empty() && parse_value_path(split_settings(path).first).has_value();
    };
    if (token.rfind("on:", 0) == 0 && token.size() > 3) {
        condition.op = Condition::Op::on_scene;
        condition.path = token == "on:own" ? "" : token.substr(3);
        return condition;
    }
    if (token.rfind("has:", 0) == 0 || token.rfind("no:", 0) == 0) {
        const bool has = token[0] == 'h';
        condition.path = token.substr(has ? 4 : 3);
        condition.op = has ? Condition::Op::exists : Condition::Op::missing;
        if (!path_ok(condition.path)) return std::nullopt;
        return condition;
    }
    // PATH OP NUMBER, the operator one of < <= > >= ≤ ≥.
    static const std::vector<std::pair<std::string, Condition::Op>> ops = {
        {"<=", Condition::Op::less_equal}, {">=", Condition::Op::greater_equal}, {"\xE2\x89\xA4", Condition::Op::less_equal},
        {"\xE2\x89\xA5", Condition::Op::greater_equal}, {"<", Condition::Op::less}, {">", Condition::Op::greater}};
    for (const auto& [text, op] : ops) {
        const std::size_t at = token.find(text);
        if (at == std::string::npos || at == 0) continue;
        condition.path = token.substr(0, at);
        condition.op = op;
        std::string number = token.substr(at + text.size());
        if (number.empty() || !path_ok(condition.path)) return std::nullopt;
        std::size_t used = 0;
        try {
            condition.bound = std::stod(number, &used);
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (used != number.size()) return std::nullopt;
        return condition;
    }
    // PATH=WORD: a word step ("nearest=plane[0]": the nearest hit is plane 0).
    if (const std::size_t at = token.find('='); at != std::string::npos && at > 0 && at + 1 < token.size()) {
        condition.path = token.substr(0, at);
        condition.op = Condition::Op::is_word;
        condition.word = token.substr(at + 1);
        if (!path_ok(condition.path)) return std::nullopt;
        // An object as a path names it ("plane[0]"), the trace as a word ("plane 0").
        const std::size_t open = condition.word.find('[');
        if (open != std::string::npos && condition.word.back() == ']')
            condition.word = condition.word.substr(0, open) + " " +
                             condition.word.substr(open + 1, condition.word.size() - open - 2);
        return condition;
    }
    return std::nullopt;
}

namespace {

bool latex_brace(std::string_view text, std::size_t at) {
    if (at == 0) return false;
    const unsigned char before = static_cast<unsigned char>(text[at - 1]);
    return std::isalpha(before) || before == '\\' || before == '^' || before == '_' || before == '}';
}

}  // namespace

Lesson parse_lesson(std::string_view text, const std::string& file, Language language,
                    std::vector<LessonProblem>& problems) {
    return Parser(file, language, problems).parse(text);
}

std::optional<ValuePath> parse_value_path(std::string_view text) {
    ValuePath path;
    const auto name_char = [](char c, bool first) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (!first && c >= '0' && c <= '9');
    };
    std::size_t k = 0;
    while (true) {
        const std::size_t start = k;
        while (k < text.size() && name_char(text[k], k == start)) ++k;
        if (k == start) return std::nullopt;
        const std::string name(text.substr(start, k - start));
        if (k == text.size()) {
            path.key = name;
            return path;
        }
        // kind[N].
        if (text[k] != '[') return std::nullopt;
        const std::size_t digits = ++k;
        while (k < text.size() && text[k] >= '0' && text[k] <= '9') ++k;
        if (k == digits || k - digits > 6 || k + 1 >= text.size() || text[k] != ']' || text[k + 1] != '.') return std::nullopt;
        path.groups.push_back({name, std::stoi(std::string(text.substr(digits, k - digits)))});
        k += 2;
    }
}

std::string path_key(const std::string& qualified) {
    const std::string path = split_settings(qualified).first;
    const std::size_t group_end = path.rfind("].");
    return group_end == std::string::npos ? path : path.substr(group_end + 2);
}

bool is_real_name(std::string_view name) {
    return name == "float" || name == "double" || name == "long-double" || name == "quad";
}

bool is_formula_name(std::string_view name) {
    return name == "article" || name == "stable" || name == "fma" || name == "geometric";
}

std::optional<SettingsQualifier> parse_settings(std::string_view text) {
    SettingsQualifier settings;
    if (text.empty()) return std::nullopt;
    std::size_t at = 0;
    while (true) {
        const std::size_t comma = text.find(',', at);
        const std::string item(text.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at));
        if (is_real_name(item) && settings.real.empty()) {
            settings.real = item;
        } else if (is_formula_name(item) && settings.formula.empty()) {
            settings.formula = item;
        } else {
            return std::nullopt;
        }
        if (comma == std::string_view::npos) return settings;
        at = comma + 1;
    }
}

std::pair<std::string, std::string> split_settings(const std::string& qualified) {
    const std::size_t at = qualified.find('@');
    if (at == std::string::npos) return {qualified, ""};
    return {qualified.substr(0, at), qualified.substr(at + 1)};
}

std::string qualified_path(const std::string& path, char component, const std::string& settings) {
    std::string out = path;
    if (component != 0) out += std::string(".") + component;
    if (!settings.empty()) out += "@" + settings;
    return out;
}

std::string qualified_path(const Placeholder& placeholder) {
    return qualified_path(placeholder.path, 0, placeholder.settings);
}

std::vector<Placeholder> find_placeholders(std::string_view text) {
    static const std::regex form(
        R"((symbol:)?((?:[A-Za-z_]+\[[0-9]{1,6}\]\.)*([A-Za-z_][A-Za-z0-9_]*))(?:\.([xyz]))?(?:@([a-z-]+(?:,[a-z-]+)?))?(?::([0-9]|1[0-7]|all))?)");
    std::vector<Placeholder> found;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text[k] != '{') continue;
        if (k + 1 < text.size() && text[k + 1] == '{') {  // "{{": a literal brace
            ++k;
            continue;
        }
        if (latex_brace(text, k)) continue;
        const std::size_t close = text.find('}', k);
        Placeholder placeholder;
        placeholder.begin = k;
        placeholder.end = close == std::string_view::npos ? text.size() : close + 1;
        const std::string inside(text.substr(k + 1, placeholder.end - k - 1 - (close == std::string_view::npos ? 0 : 1)));
        std::smatch match;
        // A key is a few letters: a longer "placeholder" is never matched
        // (std::regex recurses once a character and would overflow the stack).
        if (close == std::string_view::npos || inside.size() > 64 || !std::regex_match(inside, match, form) ||
            (match[1].matched && (match[4].matched || match[5].matched || match[6].matched))) {
            placeholder.valid = false;
            placeholder.name = std::string(text.substr(k, placeholder.end - k));
            placeholder.path = placeholder.name;
        } else {
            placeholder.symbol = match[1].matched;
            placeholder.path = match[2];
            placeholder.name = match[3];
            if (match[4].matched) placeholder.component = match[4].str()[0];
            if (match[5].matched) placeholder.settings = match[5];
            if (match[6].matched)
                placeholder.decimals = match[6].str() == "all" ? every_digit : std::stoi(match[6].str());
        }
        found.push_back(placeholder);
        k = placeholder.end - 1;
    }
    return found;
}

}  // namespace promyk
