#include "lesson/answers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/printable.hpp"
#include "util/text.hpp"

namespace promyk {

namespace {


// --- reading what a student typed -----------------------------------------

// The message quotes what the student typed: printable() here, since a NUL
// in it would cut the exception's C-string message short.
[[noreturn]] void fail(const std::string& file, Language language, int line, const std::string& what) {
    throw InputError(file, line > 0 ? message(language, "answers_line", {{"line", std::to_string(line)}}) : "", printable(what));
}

[[noreturn]] void fail_at(const std::string& file, const std::string& pointer, const std::string& what) {
    throw InputError(file, printable(pointer), printable(what));
}

// The numbers of one value: numerators, and denominators where one is a
// fraction (empty digits where none is).
struct ValueRead {
    std::vector<TypedNumber> numbers;
    std::vector<TypedNumber> over;
};

// "6,4" or, with `fractions`, "−3/4" (the denominator's sign moves to the
// numerator; a zero denominator is no number).
bool parse_component(const std::string& text, bool fractions, ValueRead& out) {
    const std::size_t slash = fractions ? text.find('/') : std::string::npos;
    if (slash == std::string::npos) {
        const std::optional<TypedNumber> number = parse_typed_number(text);
        if (!number) return false;
        out.numbers.push_back(*number);
        out.over.push_back(TypedNumber{false, "", 0});
        return true;
    }
    std::optional<TypedNumber> p = parse_typed_number(trim(text.substr(0, slash)));
    const std::optional<TypedNumber> q = parse_typed_number(trim(text.substr(slash + 1)));
    if (!p || !q || is_zero(*q)) return false;
    p->negative = p->negative != q->negative;
    out.numbers.push_back(*p);
    out.over.push_back(TypedNumber{false, q->digits, q->scale});
    return true;
}

// "6,4" -> one number; "(0,1; 0,2; 3)", "[0.1, 0.2, 3]" -> three. Nothing if malformed.
std::optional<ValueRead> parse_value(const std::string& text, bool fractions) {
    ValueRead out;
    if (text.empty()) return out;
    if (text.front() == '(' || text.front() == '[') {
        if (text.size() < 2 || (text.back() != ')' && text.back() != ']')) return std::nullopt;
        const std::string inner = text.substr(1, text.size() - 2);
        // With a semicolon the commas are decimal commas; without one, commas separate.
        const char separator = inner.find(';') != std::string::npos ? ';' : ',';
        std::size_t at = 0;
        while (true) {
            const std::size_t end = inner.find(separator, at);
            if (out.numbers.size() == 3 ||
                !parse_component(trim(inner.substr(at, end == std::string::npos ? std::string::npos : end - at)), fractions, out))
                return std::nullopt;
            if (end == std::string::npos) break;
            at = end + 1;
        }
        if (out.numbers.size() != 3) return std::nullopt;
    } else if (!parse_component(text, fractions, out)) {
        return std::nullopt;
    }
    // No fraction: no denominators at all.
    if (std::all_of(out.over.begin(), out.over.end(), [](const TypedNumber& q) { return q.digits.empty(); })) out.over.clear();
    return out;
}

// Edits (insertions, deletions, substitutions) from a to b, in halves: a
// letter of the other case is half an edit, so "detla" is nearer "delta"
// than "Delta".
std::size_t edit_distance(const std::string& a, const std::string& b) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    const auto substitution = [&](char x, char y) -> std::size_t { return x == y ? 0 : lower(x) == lower(y) ? 1 : 2; };
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t k = 0; k <= b.size(); ++k) row[k] = 2 * k;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = 2 * i;
        for (std::size_t k = 1; k <= b.size(); ++k) {
            const std::size_t above = row[k];
            row[k] = std::min({row[k] + 2, row[k - 1] + 2, diagonal + substitution(a[i - 1], b[k - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string keys_list(const Vocabulary& vocabulary) {
    std::string keys;
    for (const VocabularyEntry& entry : vocabulary.keys) keys += (keys.empty() ? "" : ", ") + entry.key;
    return keys;
}

// "P.x" -> ("P", 'x'), "sphere[1].t" -> ("sphere[1].t", 0): a path whose
// groups can hold its key (lesson_check.hpp), a key of the vocabulary, a
// component only of a point or vector.
std::optional<std::pair<std::string, char>> split_key(const std::string& qualified, const Vocabulary& vocabulary,
                                                      bool settings_allowed) {
    // A lesson's answers may name other settings: "delta@float", "P.x@quad,geometric".
    const auto [text, settings] = split_settings(qualified);
    if (qualified.find('@') != std::string::npos && (!settings_allowed || !parse_settings(settings))) return std::nullopt;
    std::string key = text;
    char component = 0;
    if (key.size() > 2 && key[key.size() - 2] == '.' && std::string_view("xyz").find(key.back()) != std::string_view::npos) {
        component = key.back();
        key.resize(key.size() - 2);
    }
    if (check_path(key, vocabulary).fault != PathFault::none) return std::nullopt;
    const VocabularyEntry* entry = vocabulary.find(path_key(key));
    if (entry == nullptr || (component != 0 && entry->kind != "point" && entry->kind != "vector")) return std::nullopt;
    return std::make_pair(qualified_path(key, 0, settings), component);
}

// The message for a key split_key refused: a bad settings qualifier, or an unknown key.
// A lesson's reader names the lesson's own keys and the nearest of them
// (a typo, "detla"), not the whole vocabulary.
std::string key_error(const std::string& key_text, const Vocabulary& vocabulary, Language language, const AnswerLimits& limits) {
    if (limits.settings && key_text.find('@') != std::string::npos &&
        !parse_settings(split_settings(key_text).second))
        return message(language, "answers_error_settings", {{"key", key_text}});
    if (limits.keys.empty())
        return message(language, "answers_error_key", {{"key", key_text}, {"keys", keys_list(vocabulary)}});
    std::string keys;
    const std::string* nearest = nullptr;
    std::size_t best = 0;
    for (const std::string& key : limits.keys) {
        keys += (keys.empty() ? "" : ", ") + key;
        const std::size_t distance = edit_distance(key_text.substr(0, 200), key);
        if (nearest == nullptr || distance < best) nearest = &key, best = distance;
    }
    return message(language, "answers_error_key_lesson", {{"key", key_text}, {"nearest", *nearest}, {"keys", keys}});
}

// A word (what a test found, the nearest object) is shown filled in on a
// worksheet: there is no number to check.
bool is_word(const std::string& path, const Vocabulary& vocabulary) {
    const VocabularyEntry* entry = vocabulary.find(path_key(path));
    return entry != nullptr && entry->kind == "word";
}

// The pixel's section, found through `index` (a file may head 10^5 pixels).
PixelAnswers& section(std::vector<PixelAnswers>& sections, std::map<std::pair<int, int>, std::size_t>& index,
                      LessonPixel pixel) {
    const auto [it, added] = index.emplace(std::make_pair(pixel.i, pixel.j), sections.size());
    if (added) sections.push_back({pixel, {}});
    return sections[it->second];
}

// Where `text` first is not well-formed UTF-8 (an overlong form, a
// surrogate, beyond U+10FFFF, a cut sequence), or npos.
std::size_t invalid_utf8(std::string_view text) {
    for (std::size_t k = 0; k < text.size();) {
        const auto byte = [&](std::size_t at) { return at < text.size() ? static_cast<unsigned char>(text[at]) : 0u; };
        const unsigned lead = byte(k);
        std::size_t length = lead < 0x80 ? 1 : lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3
                             : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
        if (length == 0) return k;
        for (std::size_t c = 1; c < length; ++c)
            if ((byte(k + c) & 0xC0u) != 0x80u) return k;
        // The second byte's range rules out overlong forms, surrogates and code points past U+10FFFF.
        const unsigned second = byte(k + 1);
        if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) || (lead == 0xF0 && second < 0x90) ||
            (lead == 0xF4 && second > 0x8F))
            return k;
        k += length;
    }
    return std::string_view::npos;
}

// "[3,4]", "[ 3, 4 ]" -> the pixel.
std::optional<LessonPixel> parse_heading(const std::string& line) {
    if (line.size() < 5 || line.front() != '[' || line.back() != ']') return std::nullopt;
    const std::string inner = line.substr(1, line.size() - 2);
    const std::size_t comma = inner.find(',');
    if (comma == std::string::npos) return std::nullopt;
    const auto whole = [](const std::string& text) -> std::optional<int> {
        if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
        return std::stoi(text);
    };
    const std::optional<int> i = whole(trim(inner.substr(0, comma))), j = whole(trim(inner.substr(comma + 1)));
    if (!i || !j) return std::nullopt;
    return LessonPixel{*i, *j};
}

// Forgiving: every readable answer of a pixel whose key is given more than
// once is unreadable, each saying where the others are (which one counts?).
void mark_repeated(std::vector<PixelAnswers>& sections, Language language) {
    for (PixelAnswers& section : sections) {
        std::map<std::pair<std::string, char>, std::vector<Answer*>> by_key;
        for (Answer& answer : section.answers)
            if (answer.unreadable.empty()) by_key[{answer.key, answer.component}].push_back(&answer);
        for (const auto& [key, given] : by_key) {
            if (given.size() < 2) continue;
            std::string lines;
            for (const Answer* answer : given) lines += (lines.empty() ? "" : ", ") + std::to_string(answer->line);
            const auto [path, settings] = split_settings(key.first);
            for (Answer* answer : given)
                answer->unreadable = message(language, "answers_error_repeated",
                                             {{"key", qualified_path(path, key.second, settings)}, {"lines", lines},
                                              {"i", std::to_string(section.pixel.i)}, {"j", std::to_string(section.pixel.j)}});
        }
    }
}

std::vector<PixelAnswers> parse_lines(std::string_view text, const std::string& file, const Vocabulary& vocabulary,
                                      Language language, LessonPixel first, const AnswerLimits& limits) {
    const int w = limits.w;
    std::vector<PixelAnswers> sections;
    std::map<std::pair<int, int>, std::size_t> index;
    LessonPixel pixel = first;
    int bad_heading = 0;  // forgiving: the unreadable heading the lines below stand under
    int line_number = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = text.find('\n', at);
        std::string_view raw = text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
        at = end == std::string_view::npos ? text.size() : end + 1;
        ++line_number;
        if (const std::size_t hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
        const std::string line = trim(raw);
        if (line.empty()) continue;
        // A line that cannot be read: a strict read's fault; a forgiving
        // read's unreadable answer, under the pixel it stands under.
        const auto unreadable = [&](const std::string& why) {
            if (!limits.forgiving) fail(file, language, line_number, why);
            Answer answer;
            answer.line = line_number;
            answer.text = printable(line);
            answer.unreadable = printable(why);
            section(sections, index, pixel).answers.push_back(std::move(answer));
        };
        const std::size_t equals = line.find('=');
        if (equals == std::string::npos) {
            if (line.front() != '[') {
                unreadable(message(language, "answers_error_line"));
                continue;
            }
            const std::optional<LessonPixel> heading = parse_heading(line);
            if (!heading || (w > 0 && (heading->i >= w || heading->j >= w))) {
                bad_heading = line_number;
                unreadable(!heading ? message(language, "answers_error_heading", {{"text", line}})
                                    : message(language, "answers_error_outside",
                                              {{"i", std::to_string(heading->i)}, {"j", std::to_string(heading->j)},
                                               {"w", std::to_string(w)}}));
                continue;
            }
            pixel = *heading;
            bad_heading = 0;
            section(sections, index, pixel);
            continue;
        }
        if (bad_heading > 0) {
            unreadable(message(language, "answers_error_under_heading", {{"line", std::to_string(bad_heading)}}));
            continue;
        }
        const std::string key_text = trim(line.substr(0, equals));
        const std::optional<std::pair<std::string, char>> key = split_key(key_text, vocabulary, limits.settings);
        if (!key) {
            unreadable(key_error(key_text, vocabulary, language, limits));
            continue;
        }
        if (is_word(key->first, vocabulary)) {
            unreadable(message(language, "answers_error_word", {{"key", key_text}}));
            continue;
        }
        Answer answer;
        answer.line = line_number;
        answer.key = key->first;
        answer.component = key->second;
        answer.text = trim(line.substr(equals + 1));
        std::optional<ValueRead> value = parse_value(answer.text, limits.forgiving);
        if (!value) {
            unreadable(message(language, limits.forgiving ? "answers_error_number_fraction" : "answers_error_number",
                               {{"text", answer.text}}));
            continue;
        }
        answer.numbers = std::move(value->numbers);
        answer.over = std::move(value->over);
        PixelAnswers& mine = section(sections, index, pixel);
        if (!limits.forgiving)
            for (const Answer& earlier : mine.answers)
                if (earlier.key == answer.key && earlier.component == answer.component)
                    // diff's numbers stand under no pixel (-1, -1) until a heading names one.
                    fail(file, language, line_number,
                         message(language, pixel.i < 0 ? "answers_error_twice_no_pixel" : "answers_error_twice",
                                 {{"key", key_text}, {"line", std::to_string(earlier.line)},
                                  {"i", std::to_string(pixel.i)}, {"j", std::to_string(pixel.j)}}));
        mine.answers.push_back(std::move(answer));
    }
    if (limits.forgiving) mark_repeated(sections, language);
    return sections;
}

// --- JSON, with numbers kept as typed ------------------------------------

using json = nlohmann::json;

// Builds the document with every number as the string it was written as
// (nlohmann's SAX hands over a float's raw text), so 6.40 stays 6.40.
struct RawNumbers {
    // An answer file is flat and a trace three levels deep: deeper nesting is
    // refused (the document's recursive destruction and printing would
    // overflow the stack on 100 000 levels).
    static constexpr std::size_t max_depth = 32;

    json root;
    std::vector<json*> stack;
    std::string pending_key;
    std::size_t error_position = 0;
    bool too_deep = false;
    std::optional<std::string> twice;  // a key given twice in the top object
    bool forgiving = false;            // then a key given twice is noted in `repeated`, and reading goes on
    std::set<std::string> repeated;

    json* add(json value) {
        if (stack.empty()) {
            root = std::move(value);
            return &root;
        }
        json& top = *stack.back();
        if (top.is_array()) {
            top.push_back(std::move(value));
            return &top.back();
        }
        json& slot = top[pending_key];
        slot = std::move(value);
        return &slot;
    }
    bool null() { return add(nullptr), true; }
    bool boolean(bool value) { return add(value), true; }
    bool number_integer(json::number_integer_t value) { return add(std::to_string(value)), true; }
    bool number_unsigned(json::number_unsigned_t value) { return add(std::to_string(value)), true; }
    bool number_float(json::number_float_t, const std::string& raw) { return add(raw), true; }
    bool string(std::string& value) { return add(value), true; }
    bool binary(json::binary_t&) { return add(nullptr), true; }
    bool open(json container) {
        if (stack.size() >= max_depth) return too_deep = true, false;
        return stack.push_back(add(std::move(container))), true;
    }
    bool start_object(std::size_t) { return open(json::object()); }
    bool key(std::string& key) {
        if (stack.size() == 1 && stack.back()->contains(key)) {
            if (!forgiving) return twice = key, false;
            repeated.insert(key);
        }
        return pending_key = key, true;
    }
    // A trace holds hundreds of thousands of steps: an interrupt is looked
    // at as each object ends (diff of two 50 MB traces parses for seconds).
    bool end_object() {
        throw_if_interrupted();
        stack.pop_back();
        return true;
    }
    bool start_array(std::size_t) { return open(json::array()); }
    bool end_array() { return stack.pop_back(), true; }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) {
        error_position = position;
        return false;
    }
};

// The line where the nesting first goes deeper than `depth` (strings skipped).
int line_deeper_than(std::string_view text, std::size_t depth) {
    int line = 1;
    std::size_t level = 0;
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (c == '\n') ++line;
        if (in_string) {
            if (c == '\\') ++k;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++level > depth) return line;
        } else if ((c == ']' || c == '}') && level > 0) {
            --level;
        }
    }
    return line;
}

std::string pointer_of(const std::string& key) { return (json::json_pointer() / key).to_string(); }

std::optional<ValueRead> json_value(const json& value, bool fractions) {
    if (value.is_string()) {
        std::optional<ValueRead> numbers = parse_value(trim(value.get<std::string>()), fractions);
        if (numbers && numbers->numbers.empty()) return std::nullopt;
        return numbers;
    }
    if (value.is_array() && value.size() == 3) {
        ValueRead numbers;
        for (const json& component : value)
            if (!component.is_string() || !parse_component(trim(component.get<std::string>()), fractions, numbers))
                return std::nullopt;
        if (std::all_of(numbers.over.begin(), numbers.over.end(), [](const TypedNumber& q) { return q.digits.empty(); }))
            numbers.over.clear();
        return numbers;
    }
    return std::nullopt;
}

std::string json_text_of(const json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_array()) {
        std::string out = "[";
        for (const json& component : value) out += (out.size() > 1 ? ", " : "") + json_text_of(component);
        return out + "]";
    }
    return value.dump();
}

AnswerFile parse_json(std::string_view text, const std::string& file, const Vocabulary& vocabulary, Language language,
                      LessonPixel first, const AnswerLimits& limits) {
    const int w = limits.w;
    RawNumbers builder;
    builder.forgiving = limits.forgiving;
    if (!json::sax_parse(text, &builder)) {
        if (builder.twice) fail_at(file, pointer_of(*builder.twice), message(language, "answers_error_twice_json", {{"key", *builder.twice}}));
        if (builder.too_deep) fail(file, language, line_deeper_than(text, RawNumbers::max_depth), message(language, "answers_error_deep", {{"depth", std::to_string(RawNumbers::max_depth)}}));
        const std::size_t end = std::min(builder.error_position, text.size());
        const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
        fail(file, language, line, message(language, "answers_error_json"));
    }
    const json& root = builder.root;
    PixelAnswers answers{first, {}};
    std::optional<TraceSummary> summary;
    // An answer that cannot be read: a strict read's fault; a forgiving read's unreadable answer.
    const auto unreadable = [&](const json& value, const std::string& pointer, const std::string& why) {
        if (!limits.forgiving) fail_at(file, pointer, why);
        Answer answer;
        answer.pointer = printable(pointer);
        answer.text = printable(json_text_of(value));
        answer.unreadable = printable(why);
        answers.answers.push_back(std::move(answer));
    };
    const auto add = [&](const std::string& key_text, const json& value, const std::string& pointer,
                         const json& real_text = json(), bool top = false) {
        if (top && builder.repeated.count(key_text) > 0)
            return unreadable(value, pointer, message(language, "answers_error_repeated_json", {{"key", key_text}}));
        const std::optional<std::pair<std::string, char>> key = split_key(key_text, vocabulary, limits.settings);
        if (!key) return unreadable(value, pointer, key_error(key_text, vocabulary, language, limits));
        if (is_word(key->first, vocabulary))
            return unreadable(value, pointer, message(language, "answers_error_word", {{"key", key_text}}));
        std::optional<ValueRead> numbers = json_value(value, limits.forgiving);
        if (!numbers)
            return unreadable(value, pointer,
                              message(language, limits.forgiving ? "answers_error_number_fraction" : "answers_error_number",
                                      {{"text", json_text_of(value)}}));
        Answer answer;
        answer.key = key->first;
        answer.component = key->second;
        answer.pointer = pointer;
        answer.text = json_text_of(value);
        answer.numbers = std::move(numbers->numbers);
        answer.over = std::move(numbers->over);
        // A non-double trace's text of each value in its own type.
        if (real_text.is_string() && answer.numbers.size() == 1) answer.real_text = {real_text.get<std::string>()};
        if (real_text.is_array() && real_text.size() == answer.numbers.size() &&
            std::all_of(real_text.begin(), real_text.end(), [](const json& t) { return t.is_string(); }))
            for (const json& t : real_text) answer.real_text.push_back(t.get<std::string>());
        answers.answers.push_back(std::move(answer));
    };
    if (root.contains("steps") && root.at("steps").is_array()) {
        // A whole trace, as promyk trace --format json prints it.
        const auto whole = [](const json& value) -> std::optional<int> {
            if (!value.is_string()) return std::nullopt;
            const std::string& digits = value.get_ref<const std::string&>();
            if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
            const long long number = std::stoll(digits);
            if (number > 2147483647) return std::nullopt;
            return static_cast<int>(number);
        };
        const json pixel = root.value("pixel", json::object());
        if (!pixel.is_object()) fail_at(file, "/pixel", message(language, "answers_error_trace"));
        const std::optional<int> i = whole(pixel.value("i", json())), j = whole(pixel.value("j", json()));
        if (!i || !j) fail_at(file, "/pixel", message(language, "answers_error_trace"));
        const std::optional<int> trace_w = whole(root.value("w", json()));
        // A trace of another scene would make every number "wrong" without saying why.
        const json trace_hash = root.value("scene_hash", json());
        if (!limits.scene_hash.empty() && trace_hash.is_string() && trace_hash.get<std::string>() != limits.scene_hash)
            fail_at(file, "/scene_hash",
                    message(language, "answers_error_trace_scene",
                            {{"scene", root.value("scene", json()).is_string() ? root.at("scene").get<std::string>() : "?"}}));
        if (w > 0 && trace_w && *trace_w != w)
            fail_at(file, "/w", message(language, "answers_error_trace_w", {{"w", std::to_string(*trace_w)}, {"lesson_w", std::to_string(w)}}));
        if (w > 0 && (*i >= w || *j >= w))
            fail_at(file, "/pixel", message(language, "answers_error_outside",
                                            {{"i", std::to_string(*i)}, {"j", std::to_string(*j)}, {"w", std::to_string(w)}}));
        answers.pixel = {*i, *j};
        summary.emplace();
        const auto text_of = [](const json& object, const char* key) {
            return object.is_object() && object.contains(key) && object.at(key).is_string() ? object.at(key).get<std::string>() : "";
        };
        const json numeric = root.value("numeric", json::object());
        if (!text_of(numeric, "real").empty()) summary->real = text_of(numeric, "real");
        // Each step's tolerance follows the type: a type promyk has no precision for is refused.
        if (numeric.is_object() && numeric.contains("real")) {
            const std::string real = text_of(numeric, "real");
            if (real != "float" && real != "double" && real != "long-double" && real != "quad")
                fail_at(file, "/numeric/real",
                        message(language, "diff_real_unknown", {{"real", printable(json_text_of(numeric.at("real")))}}));
        }
        summary->formula = text_of(numeric, "formula");
        summary->scene = text_of(root, "scene");
        summary->scene_hash = text_of(root, "scene_hash");
        summary->w = trace_w.value_or(0);
        summary->branch = text_of(root, "branch");
        summary->hit = text_of(root, "hit");
        // The steps, and those of each group ({"group": "sphere", "index": 1,
        // "steps": [...]}) under their path, sphere[1].t; words are not numbers.
        const std::function<void(const json&, const std::string&, const std::string&)> read_steps =
            [&](const json& steps, const std::string& prefix, const std::string& pointer) {
                for (std::size_t k = 0; k < steps.size(); ++k) {
                    if ((k & 4095) == 0) throw_if_interrupted();
                    const json& step = steps[k];
                    if (!step.is_object()) continue;
                    if (step.contains("group")) {
                        const json& kind = step.at("group");
                        const std::optional<int> index = whole(step.value("index", json()));
                        // An index promyk never writes (2^31, -1, 1.5) would drop the group and
                        // every difference in it: refused, not skipped.
                        if (!index)
                            fail_at(file, fmt::format("{}/{}/index", pointer, k),
                                    message(language, "diff_group_index",
                                            {{"index", printable(json_text_of(step.value("index", json())))}}));
                        if (kind.is_string() && index && step.contains("steps") && step.at("steps").is_array())
                            read_steps(step.at("steps"), prefix + kind.get<std::string>() + "[" + std::to_string(*index) + "].",
                                       fmt::format("{}/{}/steps", pointer, k));
                        continue;
                    }
                    if (!step.contains("key") || !step.at("key").is_string()) continue;
                    if (!step.contains("value")) continue;
                    const std::string key = prefix + step.at("key").get<std::string>();
                    // Non-finite (null, or a point with a null component): no number to check.
                    const json& value = step.at("value");
                    if (value.is_null() ||
                        (value.is_array() && std::any_of(value.begin(), value.end(), [](const json& c) { return c.is_null(); }))) {
                        std::string shown = "nan";
                        if (value.is_array()) {
                            // Each component as it stands, or its text (null where the number stands).
                            const json texts = step.value("text", json());
                            shown = "[";
                            for (std::size_t c = 0; c < value.size(); ++c) {
                                const bool named = !value[c].is_null() || !texts.is_array() || c >= texts.size() || !texts[c].is_string();
                                shown += (c ? ", " : "") + (named ? json_text_of(value[c]) : texts[c].get<std::string>());
                            }
                            shown += "]";
                        } else if (step.contains("text") && step.at("text").is_string()) {
                            shown = step.at("text").get<std::string>();
                        }
                        summary->non_finite.push_back({key, shown, answers.answers.size()});
                        continue;
                    }
                    if (is_word(key, vocabulary)) continue;
                    add(key, value, fmt::format("{}/{}/value", pointer, k), step.value("real_text", json()));
                }
            };
        read_steps(root.at("steps"), "", "/steps");
        if (root.contains("result") && (root.at("result").is_string() || root.at("result").is_array()))
            add("I_P", root.at("result"), "/result", root.value("result_real_text", json()));
    } else if (root.is_object()) {
        for (const auto& [key, value] : root.items()) add(key, value, pointer_of(key), json(), true);
    } else {
        fail(file, language, 1, message(language, "answers_error_json"));
    }
    // Moved, not copied: a trace's hundreds of thousands of answers (an
    // initializer list's elements are const, and copied again).
    AnswerFile read;
    read.pixels.push_back(std::move(answers));
    read.trace = std::move(summary);
    return read;
}

}  // namespace

AnswerFile read_answers(std::string_view text, const std::string& file, const Vocabulary& vocabulary, Language language,
                        LessonPixel first, const AnswerLimits& limits) {
    if (limits.forgiving) {
        // What no line can be read from: a file that is too large or not text.
        if (text.size() > max_answer_bytes)
            fail(file, language, 0, message(language, "answers_error_size", {{"mib", std::to_string(max_answer_bytes >> 20)}}));
        if (const std::size_t bad = invalid_utf8(text); bad != std::string_view::npos)
            fail(file, language, 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n')),
                 message(language, "answers_error_utf8"));
    }
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a byte order mark some editors write
    const std::size_t start = text.find_first_not_of(" \t\r\n");
    AnswerFile answers = start != std::string_view::npos && text[start] == '{'
                             ? parse_json(text, file, vocabulary, language, first, limits)
                             : AnswerFile{parse_lines(text, file, vocabulary, language, first, limits), std::nullopt};
    const Answer* first_unreadable = nullptr;
    bool any = false;
    for (const PixelAnswers& pixel : answers.pixels) {
        for (const Answer& answer : pixel.answers) {
            any = any || (answer.unreadable.empty() && !answer.numbers.empty());
            if (!answer.unreadable.empty() && (first_unreadable == nullptr || answer.line < first_unreadable->line))
                first_unreadable = &answer;
        }
    }
    if (!any && first_unreadable != nullptr) {
        // Nothing to check: the file is refused at its first unreadable line.
        const std::string why = first_unreadable->unreadable + "; " + message(language, "answers_error_nothing_readable");
        if (!first_unreadable->pointer.empty()) fail_at(file, first_unreadable->pointer, why);
        fail(file, language, first_unreadable->line, why);
    }
    if (!any) fail(file, language, 0, message(language, "answers_error_empty"));
    return answers;
}

std::vector<PixelAnswers> parse_answers(std::string_view text, const std::string& file, const Vocabulary& vocabulary,
                                        Language language, LessonPixel first, int w, const std::string& scene_hash,
                                        bool settings) {
    AnswerLimits limits;
    limits.w = w;
    limits.scene_hash = scene_hash;
    limits.settings = settings;
    return read_answers(text, file, vocabulary, language, first, limits).pixels;
}

}  // namespace promyk
