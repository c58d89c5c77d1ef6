// Scene bytes to a JSON value. The format is documented in
// lessons/scenes/README.md; keep the two in step.

#include "scene/scene_parse.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "scene/json_pointer.hpp"
#include "scene/scene_hints.hpp"
#include "trace/messages.hpp"
#include "util/interrupt.hpp"
#include "util/printable.hpp"

namespace promyk::scene_detail {

namespace {

// The format nests 4 levels deep ({"spheres": [{"S": [...]}]}); anything much
// deeper is not a scene, and the limit keeps the parser's memory bounded.
constexpr std::size_t max_nesting = 64;
// The format's values are at most this deep ("/spheres/0/S/1": 4); the
// places of deeper ones are not recorded.
constexpr std::size_t deepest_level = 4;

// SceneParser builds the value from the parser's events (nlohmann's SAX
// interface) and tracks the path, so that duplicate keys, out-of-range
// numbers and excessive nesting are reported by JSON pointer, and so that the
// unknown keys of each object of the format and the order of the values are
// known in file order.
//
// The cost is linear (n log n with the object's std::map) in the size of the
// file, whatever its shape. Neither of nlohmann's own ways kept it so: an
// ordered_json object inserts by linear search (a file of 131,567 keys took
// 39.5 s), and the parser with a callback scans the whole parent container at
// the end of every object or array ([{}, {}, ...] is quadratic).

// "line L, column C" of the character at nlohmann's `byte` (1-based count of
// the bytes read when the error was found); columns count characters.
std::string line_column(std::string_view text, std::size_t byte) {
    const std::size_t index = std::min(byte == 0 ? 0 : byte - 1, text.size());
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t k = 0; k < index; ++k) {
        const auto c = static_cast<unsigned char>(text[k]);
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0u) != 0x80u) {  // not a UTF-8 continuation byte
            ++column;
        }
    }
    return fmt::format("line {}, column {}", line, column);
}

// nlohmann's message without its prefix (which repeats the position) and
// without the echo of the text read ("; last read: '...'").
std::string syntax_reason(const std::string& what) {
    const std::size_t start = what.find("syntax error");
    std::string reason = start == std::string::npos ? what : what.substr(start);
    const std::size_t echo = reason.find("; last read: '");
    if (echo != std::string::npos) {
        const std::size_t expected = reason.find("'; expected ", echo);
        reason = reason.substr(0, echo) + (expected == std::string::npos ? "" : reason.substr(expected + 1));
    }
    return reason;
}

class SceneParser {
public:
    SceneParser(std::string_view text, const std::string& source) : text_(text), source_(source) {}

    bool null() { return add(nullptr); }
    bool boolean(bool value) { return add(value); }
    bool number_integer(Json::number_integer_t value) { return add(value); }
    bool number_unsigned(Json::number_unsigned_t value) { return add(value); }
    bool number_float(Json::number_float_t value, const Json::string_t& /*text*/) { return add(value); }
    bool string(Json::string_t& value) { return add(value); }
    bool binary(Json::binary_t& value) { return add(Json::binary(value)); }

    bool start_object(std::size_t /*elements*/) { return start(Json::value_t::object); }
    bool start_array(std::size_t /*elements*/) { return start(Json::value_t::array); }
    bool end_object() { return end(); }
    bool end_array() { return end(); }

    bool key(Json::string_t& key) {
        Frame& frame = frames_.back();
        const auto [member, inserted] = frame.value->get_ref<Json::object_t&>().try_emplace(key);
        frame.key = key;
        // A duplicate is a fault that does not stop the reading: its last
        // value is the one read.
        if (!inserted && parsed_.faults.size() >= max_collected_faults)
            parsed_.faults_cut = true;
        else if (!inserted)
            parsed_.faults.push_back(
                {printable(pending_pointer()), printable(ui_message("scene_duplicate_key", {{"key", shown_key(key)}}))});
        frame.member = &member->second;
        record_if_unknown(key);
        return true;
    }

    // nlohmann reports a syntax error as parse_error (101) and a number too
    // large for a double as out_of_range (406), `last_token` being its text.
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& last_token, const Exception& error) {
        if (error.id == 406)
            reject(source_, pending_pointer(), ui_message("scene_number_range", {{"number", last_token}}));
        reject(source_, line_column(text_, position), ui_message("scene_syntax", {{"reason", syntax_reason(error.what())}}));
    }

    ParsedJson take() { return std::move(parsed_); }

private:
    struct Frame {
        Json* value;             // the object or array being read
        std::string key;         // objects: the last key read
        Json* member = nullptr;  // objects: the value of that key, to be filled
        std::string pointer;     // the format's levels: where the container is
    };

    // Stores a value where the parser is: the root, the next element of an
    // array, the value of an object's last key.
    template <class Value>
    Json* place(Value&& value) {
        if (frames_.size() <= deepest_level) parsed_.order.emplace(pending_pointer(), places_++);
        if (frames_.empty()) {
            parsed_.root = Json(std::forward<Value>(value));
            return &parsed_.root;
        }
        Frame& frame = frames_.back();
        if (frame.value->is_array()) {
            auto& array = frame.value->get_ref<Json::array_t&>();
            array.emplace_back(std::forward<Value>(value));
            return &array.back();
        }
        *frame.member = Json(std::forward<Value>(value));
        return frame.member;
    }

    template <class Value>
    bool add(Value&& value) {
        place(std::forward<Value>(value));
        return true;
    }

    bool start(Json::value_t type) {
        if (frames_.size() >= max_nesting)
            reject(source_, pending_pointer(), ui_message("scene_nesting", {{"max", std::to_string(max_nesting)}}));
        std::string pointer = frames_.size() <= deepest_level ? pending_pointer() : std::string();
        Json* value = place(type);
        frames_.push_back(Frame{value, {}, nullptr, std::move(pointer)});
        return true;
    }

    bool end() {
        throw_if_interrupted();  // once an object or array: a scene may hold thousands
        if (frames_.size() - 1 <= deepest_level) parsed_.ends.emplace(std::move(frames_.back().pointer), places_++);
        frames_.pop_back();
        return true;
    }

    // The pointer of the value the parser is reading now: the last key of an
    // object, the next index of an array.
    std::string pending_pointer() const {
        std::string pointer;
        for (std::size_t k = 0; k < frames_.size(); ++k) {
            const Frame& frame = frames_[k];
            const bool innermost = k + 1 == frames_.size();
            if (frame.value->is_array())
                pointer = child(pointer, innermost ? frame.value->size() : frame.value->size() - 1);
            else
                pointer = child(pointer, frame.key);
        }
        return pointer;
    }

    // Unknown keys are found here, in file order, and reported by the
    // validation where it checks the object's keys.
    void record_if_unknown(const std::string& key) {
        if (frames_.size() == 1) {  // the top level (an object: a key was read)
            if (!has_key(scene_level(), key)) parsed_.unknown_keys[""].push_back(key);
            return;
        }
        // An element of one of the top level's arrays ("spheres", "planes", ...).
        if (frames_.size() != 3 || !frames_[1].value->is_array() || !frames_[2].value->is_object()) return;
        const std::string& array = frames_[0].key;
        const Level* level = element_level(array);
        if (level && !has_key(*level, key))
            parsed_.unknown_keys[child(child("", array), frames_[1].value->size() - 1)].push_back(key);
    }

    std::string_view text_;
    const std::string& source_;
    std::vector<Frame> frames_;
    ParsedJson parsed_;
    std::size_t places_ = 0;  // the values and ends of containers seen so far
};

// The whole file is the JSON text, with at most one UTF-8 byte order mark at
// its start (removed from `text` here). A NUL byte anywhere is rejected: the
// parser would take it for the end of the input and ignore what follows. So
// is a second byte order mark, or one anywhere else (the parser skips one at
// the start of what it reads, so two at the start hid one from both checks).
// Other bytes that are not JSON text are the parser's syntax errors: outside
// strings anything but JSON's tokens and whitespace, inside strings raw
// control characters and ill-formed UTF-8.
void check_bytes(std::string_view& text, const std::string& source) {
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
    const std::size_t nul = text.find('\0');
    const std::size_t second_bom = text.find(bom);
    if (nul != std::string_view::npos && nul < second_bom)
        reject(source, line_column(text, nul + 1), ui_message("scene_nul"));
    if (second_bom != std::string_view::npos) reject(source, line_column(text, second_bom + 1), ui_message("scene_second_bom"));
}

}  // namespace

[[noreturn]] void reject(const std::string& source, std::string_view where, std::string_view what) {
    throw InputError(source, printable(where), printable(what));
}

ParsedJson parse_json(std::string_view text, const std::string& source) {
    if (text.size() > max_scene_file_bytes)
        reject(source, "",
               ui_message("scene_too_large",
                          {{"size", std::to_string(text.size())}, {"limit", std::to_string(max_scene_file_bytes)}}));
    check_bytes(text, source);
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        reject(source, "",
               ui_message("scene_empty", {{"example", "{\"spheres\": [{\"S\": [0, 0, 3.2], \"r\": 1.1}], "
                                                      "\"lights\": [{\"L\": [1.5, 1, 1]}]}"}}));
    SceneParser parser(text, source);
    Json::sax_parse(text.begin(), text.end(), &parser);
    return parser.take();
}

}  // namespace promyk::scene_detail
