// Scene files: reading (with validation that names the faulty field) and
// writing. The format is documented in lessons/scenes/README.md; keep the two
// in step.

#include "scene/scene_json.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "math/vec3.hpp"
#include "util/edit_distance.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/printable.hpp"

namespace promyk {

namespace {

// Objects are std::maps (insertion in log n). They do not keep the file's key
// order: SceneParser records the first unknown key of each object of the
// format in file order instead.
using Json = nlohmann::json;

constexpr std::size_t max_name_chars = 200;
// The format nests 4 levels deep ({"spheres": [{"S": [...]}]}); anything much
// deeper is not a scene, and the limit keeps the parser's memory bounded.
constexpr std::size_t max_nesting = 64;
// A material's exponent n (Phong's shininess): a whole number in this range.
constexpr int min_exponent = 1;
constexpr int max_exponent = 10000;

// ---------------------------------------------------------------------------
// JSON pointers and message helpers

// One reference token of a JSON pointer (RFC 6901): '~' -> "~0", '/' -> "~1".
std::string pointer_token(std::string_view token) {
    std::string out;
    out.reserve(token.size());
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string child(const std::string& pointer, std::string_view key) { return pointer + "/" + pointer_token(key); }
std::string child(const std::string& pointer, std::size_t index) { return pointer + "/" + std::to_string(index); }

// A key as shown inside a message: JSON string escapes, without the quotes,
// and printable() for what JSON leaves raw (DEL, C1 controls, ...).
std::string shown(const std::string& key) {
    const std::string quoted = Json(key).dump(-1, ' ', false, Json::error_handler_t::replace);
    return printable(std::string_view(quoted).substr(1, quoted.size() - 2));
}

// Every InputError of the loader is made here: the pointer (built from keys
// of the file) and the message are printable() (the file name is the
// caller's and is left as given).
[[noreturn]] void reject(const std::string& source, std::string_view where, std::string_view what) {
    throw InputError(source, printable(where), printable(what));
}

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// ---------------------------------------------------------------------------
// The objects of the format and their keys

struct Alias {
    std::string_view alias;  // lower case
    std::string_view key;
};

struct Level {
    std::string_view name;               // "the scene", "a sphere", "a light"
    std::vector<std::string_view> keys;  // in the documented order
    std::vector<Alias> aliases;          // common other names for the keys
    std::string_view home;               // where keys of this level belong
    bool has_material = false;           // an object: it names a material by its index
};

const Level& scene_level() {
    static const Level level{"the scene",
                             {"name", "z_E", "background", "shadows", "spheres", "planes", "lights", "materials"},
                             {{"title", "name"},
                              {"pane", "z_E"},
                              {"bg", "background"},
                              {"colour", "background"},
                              {"color", "background"},
                              {"shadow", "shadows"},
                              {"objects", "spheres"},
                              {"sphere", "spheres"},
                              {"plane", "planes"},
                              {"light", "lights"},
                              {"material", "materials"}},
                             "at the top level of the scene"};
    return level;
}

const Level& sphere_level() {
    static const Level level{"a sphere",
                             {"S", "r", "material"},
                             {{"radius", "r"},
                              {"center", "S"},
                              {"centre", "S"},
                              {"position", "S"},
                              {"pos", "S"},
                              {"mat", "material"}},
                             "in a sphere, inside \"spheres\"",
                             true};
    return level;
}

const Level& plane_level() {
    static const Level level{"a plane",
                             {"Q", "n", "material"},
                             {{"point", "Q"},
                              {"position", "Q"},
                              {"pos", "Q"},
                              {"normal", "n"},
                              {"mat", "material"}},
                             "in a plane, inside \"planes\"",
                             true};
    return level;
}

const Level& light_level() {
    static const Level level{"a light",
                             {"L", "I", "colour"},
                             {{"position", "L"},
                              {"pos", "L"},
                              {"intensity", "I"},
                              {"power", "I"},
                              {"brightness", "I"},
                              {"color", "colour"}},
                             "in a light, inside \"lights\""};
    return level;
}

// In a material 'n' is the exponent (the n), not a plane's normal.
const Level& material_level() {
    static const Level level{"a material",
                             {"ambient", "diffuse", "specular", "exponent", "colour"},
                             {{"ka", "ambient"},
                              {"k_a", "ambient"},
                              {"kd", "diffuse"},
                              {"k_d", "diffuse"},
                              {"ks", "specular"},
                              {"k_s", "specular"},
                              {"n", "exponent"},
                              {"shininess", "exponent"},
                              {"phong", "exponent"},
                              {"exp", "exponent"},
                              {"color", "colour"}},
                             "in a material, inside \"materials\""};
    return level;
}

const std::vector<const Level*>& levels() {
    static const std::vector<const Level*> all{&scene_level(), &sphere_level(), &plane_level(), &light_level(),
                                               &material_level()};
    return all;
}

// The level of an element of the top-level array `array`; nullptr for others.
const Level* element_level(std::string_view array) {
    return array == "spheres"     ? &sphere_level()
           : array == "planes"    ? &plane_level()
           : array == "lights"    ? &light_level()
           : array == "materials" ? &material_level()
                                  : nullptr;
}

bool has_key(const Level& level, std::string_view key) {
    return std::find(level.keys.begin(), level.keys.end(), key) != level.keys.end();
}

// "'k' belongs in a light, inside "lights", or in a material, inside
// "materials"" when `key` is a key of levels other than `level`; else empty.
// An object's hint adds how it refers to a material.
std::string belongs_hint(std::string_view key, const Level& level) {
    std::string homes;
    bool in_material = false;
    for (const Level* other : levels()) {
        if (other == &level || !has_key(*other, key)) continue;
        homes += fmt::format("{}{}", homes.empty() ? "" : ", or ", other->home);
        in_material = in_material || other == &material_level();
    }
    if (homes.empty()) return "";
    std::string hint = fmt::format("'{}' belongs {}", key, homes);
    if (in_material && level.has_material)
        hint += fmt::format("; {} names its material by index, as \"material\": 0", level.name);
    return hint;
}

// The hint after "unknown key 'k'": a common other name for a key of this
// level (before the levels a key belongs to: in a material 'n' is the
// exponent), the level a known key belongs to, a key differing only in case,
// or a key within edit distance 2 (that is not a complete rewrite of it);
// else the allowed keys. 'color' is 'colour' wherever a colour belongs.
std::string unknown_key_hint(const std::string& key, const Level& level) {
    const std::string lower = lowercase(key);
    for (const Alias& alias : level.aliases) {
        if (alias.alias == lower) return fmt::format("did you mean '{}'?", alias.key);
    }
    if (std::string hint = belongs_hint(key, level); !hint.empty()) return hint;
    if (lower == "color") return "did you mean 'colour'? " + belongs_hint("colour", level);
    for (std::string_view known : level.keys) {
        if (lowercase(known) == lower) return fmt::format("did you mean '{}'?", known);
    }
    std::string_view best;
    std::size_t best_distance = 3;
    for (std::string_view known : level.keys) {
        const std::size_t distance = edit_distance(key, known);
        if (distance < best_distance && distance < std::max(key.size(), known.size())) {
            best = known;
            best_distance = distance;
        }
    }
    if (!best.empty()) return fmt::format("did you mean '{}'?", best);
    std::string list;
    for (std::string_view known : level.keys) list += fmt::format("{}'{}'", list.empty() ? "" : ", ", known);
    return fmt::format("the keys of {} are {}", level.name, list);
}

// ---------------------------------------------------------------------------
// Parsing: JSON text to a JSON value. SceneParser builds the value from the
// parser's events (nlohmann's SAX interface) and tracks the path, so that
// duplicate keys, out-of-range numbers and excessive nesting are reported by
// JSON pointer, and so that the first unknown key of each object of the
// format is known in file order.
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

// The first unknown key of each object of the format, in file order, by the
// pointer of the object ("", "/spheres/0", "/lights/0").
using FirstUnknownKeys = std::map<std::string, std::string>;

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
        if (!inserted)
            reject(source_, pending_pointer(),
                   fmt::format("duplicate key '{}'; a key may appear only once in an object", shown(key)));
        frame.member = &member->second;
        record_if_unknown(key);
        return true;
    }

    // nlohmann reports a syntax error as parse_error (101) and a number too
    // large for a double as out_of_range (406), `last_token` being its text.
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& last_token, const Exception& error) {
        if (error.id == 406)
            reject(source_, pending_pointer(),
                   fmt::format("the number {} is out of the range of a double (it is not finite)", last_token));
        reject(source_, line_column(text_, position), syntax_reason(error.what()));
    }

    Json& root() { return root_; }
    const FirstUnknownKeys& first_unknown_keys() const { return first_unknown_; }

private:
    struct Frame {
        Json* value;             // the object or array being read
        std::string key;         // objects: the last key read
        Json* member = nullptr;  // objects: the value of that key, to be filled
    };

    // Stores a value where the parser is: the root, the next element of an
    // array, the value of an object's last key.
    template <class Value>
    Json* place(Value&& value) {
        if (frames_.empty()) {
            root_ = Json(std::forward<Value>(value));
            return &root_;
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
            reject(source_, pending_pointer(),
                   fmt::format("nested deeper than {} levels; a scene nests 4", max_nesting));
        frames_.push_back(Frame{place(type), {}});
        return true;
    }

    bool end() {
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

    // Unknown keys are found here, in file order, and reported by SceneReader
    // where it checks the object's keys (so the order of the faults reported
    // stays: the file as a whole, then the top level, then each field).
    void record_if_unknown(const std::string& key) {
        if (frames_.size() == 1) {  // the top level (an object: a key was read)
            if (!has_key(scene_level(), key)) first_unknown_.try_emplace("", key);
            return;
        }
        // An element of one of the top level's arrays ("spheres", "planes", ...).
        if (frames_.size() != 3 || !frames_[1].value->is_array() || !frames_[2].value->is_object()) return;
        const std::string& array = frames_[0].key;
        const Level* level = element_level(array);
        if (level && !has_key(*level, key))
            first_unknown_.try_emplace(child(child("", array), frames_[1].value->size() - 1), key);
    }

    std::string_view text_;
    const std::string& source_;
    Json root_;
    std::vector<Frame> frames_;
    FirstUnknownKeys first_unknown_;
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
        reject(source, line_column(text, nul + 1),
               "a NUL byte (U+0000), which JSON text never holds; the parser would ignore everything after it");
    if (second_bom != std::string_view::npos)
        reject(source, line_column(text, second_bom + 1),
               "a UTF-8 byte order mark (U+FEFF) is allowed only once, at the very start of the file");
}

struct ParsedJson {
    Json root;
    FirstUnknownKeys first_unknown_keys;
};

ParsedJson parse_json(std::string_view text, const std::string& source) {
    if (text.size() > max_scene_file_bytes)
        reject(source, "",
               fmt::format("the scene is {} bytes, more than the limit of {} bytes (1 MiB)", text.size(),
                           max_scene_file_bytes));
    check_bytes(text, source);
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        reject(source, "",
               "the scene is empty; a scene is a JSON object such as "
               "{\"spheres\": [{\"S\": [0, 0, 3.2], \"r\": 1.1}], \"lights\": [{\"L\": [1.5, 1, 1]}]}");
    SceneParser parser(text, source);
    Json::sax_parse(text.begin(), text.end(), &parser);
    return {std::move(parser.root()), parser.first_unknown_keys()};
}

// ---------------------------------------------------------------------------
// Validation: JSON value to Scene

class SceneReader {
public:
    SceneReader(const std::string& source, const FirstUnknownKeys& first_unknown_keys)
        : source_(source), first_unknown_keys_(first_unknown_keys) {}

    // The faults are looked for in this order, the first one found reported:
    // the top level's unknown keys, name, z_E, background, shadows, the
    // materials (before the objects that refer to them), the spheres, the
    // planes, that there is an object, the lights. Each object's unknown
    // keys come before its fields.
    Scene read(const Json& root) const {
        if (!root.is_object()) fail("", fmt::format("a scene must be a JSON object {{...}}, got {}", type_of(root)));
        check_keys("", scene_level());

        Scene scene;
        scene.source = source_;
        if (const auto it = root.find("name"); it != root.end()) scene.name = read_name(*it, "/name");
        if (const auto it = root.find("z_E"); it != root.end()) {
            scene.z_E = read_number(*it, "/z_E", "z_E");
            if (!(scene.z_E > 0))
                fail("/z_E", fmt::format("z_E (the pane's distance from the eye) must be > 0, got {}", scene.z_E));
        }
        if (const auto it = root.find("background"); it != root.end()) scene.background = read_background(*it);
        if (const auto it = root.find("shadows"); it != root.end()) {
            if (!it->is_boolean())
                fail("/shadows", fmt::format("shadows must be true or false, got {}", type_of(*it)));
            scene.shadows = it->get<bool>();
        }
        if (const Json* materials = find_array(root, "materials", "material"))
            for (std::size_t k = 0; k < materials->size(); ++k)
                scene.materials.push_back(read_material((*materials)[k], child("/materials", k)));
        if (const Json* spheres = find_array(root, "spheres", "sphere"))
            for (std::size_t k = 0; k < spheres->size(); ++k)
                scene.spheres.push_back(read_sphere((*spheres)[k], child("/spheres", k), scene.materials.size()));
        if (const Json* planes = find_array(root, "planes", "plane"))
            for (std::size_t k = 0; k < planes->size(); ++k)
                scene.planes.push_back(read_plane((*planes)[k], child("/planes", k), scene.materials.size()));
        if (scene.object_count() == 0)
            fail("/spheres",
                 "the scene has no objects: put at least one sphere in \"spheres\" or one plane in \"planes\"");
        const Json* lights = find_array(root, "lights", "light");
        if (!lights)
            fail("/lights", "missing required key 'lights' (an array of the point lights, at least one)");
        if (lights->empty()) fail("/lights", "a scene needs at least one light in \"lights\", got none");
        for (std::size_t k = 0; k < lights->size(); ++k)
            scene.lights.push_back(read_light((*lights)[k], child("/lights", k)));
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const { reject(source_, where, what); }

    static std::string type_of(const Json& value) {
        return value.is_number()    ? "a number"
               : value.is_object()  ? "an object"
               : value.is_array()   ? "an array"
               : value.is_string()  ? "a string"
               : value.is_boolean() ? "a boolean"
               : value.is_null()    ? "null"
                                    : value.type_name();
    }

    // The first unknown key in file order, as SceneParser recorded it.
    void check_keys(const std::string& pointer, const Level& level) const {
        const auto it = first_unknown_keys_.find(pointer);
        if (it == first_unknown_keys_.end()) return;
        const std::string& key = it->second;
        fail(child(pointer, key), fmt::format("unknown key '{}'; {}", shown(key), unknown_key_hint(key, level)));
    }

    double read_number(const Json& value, const std::string& pointer, std::string_view what) const {
        if (!value.is_number()) fail(pointer, fmt::format("{} must be a number, got {}", what, type_of(value)));
        const double number = value.get<double>();
        if (!std::isfinite(number)) fail(pointer, fmt::format("{} must be a finite number, got {}", what, number));
        return number;
    }

    // Three numbers: a point or vector [x, y, z] or a colour [r, g, b].
    Vec3d read_triple(const Json& value, const std::string& pointer, std::string_view what, std::string_view form,
                      const char* const (&names)[3]) const {
        if (!value.is_array())
            fail(pointer, fmt::format("{} must be an array of 3 numbers {}, got {}", what, form, type_of(value)));
        if (value.size() != 3)
            fail(pointer, fmt::format("{} must be an array of 3 numbers {}, got {} element{}", what, form,
                                      value.size(), value.size() == 1 ? "" : "s"));
        double xyz[3];
        for (std::size_t k = 0; k < 3; ++k)
            xyz[k] = read_number(value[k], child(pointer, k), fmt::format("{}[{}] ({})", what, k, names[k]));
        return {xyz[0], xyz[1], xyz[2]};
    }

    Vec3d read_vec3(const Json& value, const std::string& pointer, std::string_view what) const {
        static const char* const axes[3] = {"x", "y", "z"};
        return read_triple(value, pointer, what, "[x, y, z]", axes);
    }

    // [r, g, b], each channel from 0 to 1.
    Colour read_colour(const Json& value, const std::string& pointer, std::string_view what) const {
        static const char* const channels[3] = {"red", "green", "blue"};
        const Colour colour = read_triple(value, pointer, what, "[r, g, b] (each from 0 to 1)", channels);
        const double rgb[3] = {colour.x, colour.y, colour.z};
        for (std::size_t k = 0; k < 3; ++k)
            if (!(rgb[k] >= 0 && rgb[k] <= 1))
                fail(child(pointer, k), fmt::format("{}[{}] ({}) must be between 0 and 1, got {}", what, k,
                                                    channels[k], rgb[k]));
        return colour;
    }

    // A grey level (a number) or a colour [r, g, b].
    Colour read_background(const Json& value) const {
        if (value.is_array()) return read_colour(value, "/background", "background");
        if (!value.is_number())
            fail("/background",
                 fmt::format("background must be a number (a grey level) or an array [r, g, b], got {}",
                             type_of(value)));
        const double grey = read_number(value, "/background", "background");
        if (!(grey >= 0 && grey <= 1))
            fail("/background",
                 fmt::format("background (the intensity of a ray that misses) must be between 0 and 1, got {}",
                             grey));
        return {grey, grey, grey};
    }

    std::string read_name(const Json& value, const std::string& pointer) const {
        if (!value.is_string()) fail(pointer, fmt::format("name must be a string, got {}", type_of(value)));
        const std::string& name = value.get_ref<const std::string&>();
        if (name.empty()) fail(pointer, "name must not be empty");
        std::size_t chars = 0;
        for (std::size_t k = 0; k < name.size();) {  // valid UTF-8: nlohmann checked it
            const auto lead = static_cast<unsigned char>(name[k]);
            std::size_t length = lead < 0x80u ? 1 : lead < 0xE0u ? 2 : lead < 0xF0u ? 3 : 4;
            std::uint32_t code = length == 1   ? lead
                                 : length == 2 ? (lead & 0x1Fu)
                                 : length == 3 ? (lead & 0x0Fu)
                                               : (lead & 0x07u);
            for (std::size_t m = 1; m < length && k + m < name.size(); ++m)
                code = (code << 6) | (static_cast<unsigned char>(name[k + m]) & 0x3Fu);
            if (code < 0x20u || (code >= 0x7Fu && code <= 0x9Fu))
                fail(pointer, fmt::format("name must not contain control characters, found U+{:04X} at character {}",
                                          code, chars + 1));
            k += length;
            ++chars;
        }
        if (chars > max_name_chars)
            fail(pointer, fmt::format("name is too long: {} characters, at most {}", chars, max_name_chars));
        return name;
    }

    // One of the top level's arrays, or nullptr when the key is absent.
    const Json* find_array(const Json& root, const char* key, std::string_view noun) const {
        const auto it = root.find(key);
        if (it == root.end()) return nullptr;
        if (!it->is_array())
            fail(child("", key), fmt::format("{} must be an array of {}s, got {}", key, noun, type_of(*it)));
        return &*it;
    }

    const Json& require(const Json& object, const char* key, const std::string& pointer,
                        std::string_view meaning) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(child(pointer, key), fmt::format("missing required key '{}' ({})", key, meaning));
        return *it;
    }

    // An element of spheres, planes, lights or materials: an object whose
    // keys are known.
    void check_element(const Json& value, const std::string& pointer, const Level& level,
                       std::string_view example) const {
        if (!value.is_object())
            fail(pointer, fmt::format("{} must be an object {}, got {}", level.name, example, type_of(value)));
        check_keys(pointer, level);
    }

    // An object's "material": the index of an element of "materials".
    int read_material_index(const Json& object, const std::string& pointer, std::size_t materials) const {
        const auto it = object.find("material");
        if (it == object.end()) return no_material;
        const std::string where = child(pointer, "material");
        const char* meaning = "the index of a material in \"materials\", counted from 0";
        if (!it->is_number())
            fail(where, fmt::format("material must be a whole number ({}), got {}", meaning, type_of(*it)));
        const double index = read_number(*it, where, "material");
        if (std::floor(index) != index)
            fail(where, fmt::format("material must be a whole number ({}), got {}", meaning, index));
        if (index < 0) fail(where, fmt::format("material must be >= 0 ({}), got {}", meaning, index));
        if (!(index < static_cast<double>(materials))) {
            const std::string have = materials == 0   ? "no materials (\"materials\" is empty or absent)"
                                     : materials == 1 ? "1 material (0)"
                                     : materials == 2 ? "2 materials (0 and 1)"
                                                      : fmt::format("{} materials (0 to {})", materials, materials - 1);
            fail(where, fmt::format("material {} does not exist: the scene has {}", index, have));
        }
        return static_cast<int>(index);
    }

    Sphere read_sphere(const Json& value, const std::string& pointer, std::size_t materials) const {
        check_element(value, pointer, sphere_level(), "{\"S\": [x, y, z], \"r\": r}");
        Sphere sphere;
        sphere.S = read_vec3(require(value, "S", pointer, "the sphere's centre [x, y, z]"), child(pointer, "S"), "S");
        sphere.r = read_number(require(value, "r", pointer, "the sphere's radius"), child(pointer, "r"), "r");
        if (!(sphere.r > 0))
            fail(child(pointer, "r"), fmt::format("r (the sphere's radius) must be > 0, got {}", sphere.r));
        sphere.material = read_material_index(value, pointer, materials);
        // Computed as the article's program computes it: S := x_S² + y_S² + z_S², then S − r².
        if (!std::isfinite(length_squared(sphere.S) - sphere.r * sphere.r))
            fail(pointer, "the sphere is too far or too large to compute with doubles (|S|² − r² is not finite)");
        return sphere;
    }

    Plane read_plane(const Json& value, const std::string& pointer, std::size_t materials) const {
        check_element(value, pointer, plane_level(), "{\"Q\": [x, y, z], \"n\": [x, y, z]}");
        Plane plane;
        plane.Q = read_vec3(require(value, "Q", pointer, "a point of the plane [x, y, z]"), child(pointer, "Q"), "Q");
        const std::string n_pointer = child(pointer, "n");
        plane.n = read_vec3(require(value, "n", pointer, "the plane's normal [x, y, z]"), n_pointer, "n");
        if (plane.n == Vec3d{0, 0, 0}) fail(n_pointer, "n (the plane's normal) must not be the zero vector [0, 0, 0]");
        // The engine's n̂ = n/√(n·n), each component divided, and n̂·Q.
        const double nn = length_squared(plane.n);
        if (!std::isfinite(nn))
            fail(n_pointer, "n (the plane's normal) is too long to compute with doubles (n·n is not finite); only "
                            "its direction matters: divide it");
        if (nn == 0)
            fail(n_pointer, "n (the plane's normal) is too short to compute with doubles (n·n underflows to 0); "
                            "only its direction matters: multiply it");
        plane.material = read_material_index(value, pointer, materials);
        if (!std::isfinite(dot(plane.n / std::sqrt(nn), plane.Q)))
            fail(pointer, "the plane is too far to compute with doubles (n̂·Q, its distance from the eye, is not "
                          "finite)");
        return plane;
    }

    Light read_light(const Json& value, const std::string& pointer) const {
        check_element(value, pointer, light_level(), "{\"L\": [x, y, z], \"I\": I}");
        Light light;
        light.L = read_vec3(require(value, "L", pointer, "the light's position [x, y, z]"), child(pointer, "L"), "L");
        if (const auto it = value.find("I"); it != value.end()) {
            light.I = read_number(*it, child(pointer, "I"), "I");
            if (!(light.I >= 0))
                fail(child(pointer, "I"), fmt::format("I (the light's intensity) must be >= 0, got {}", light.I));
        }
        if (const auto it = value.find("colour"); it != value.end())
            light.colour = read_colour(*it, child(pointer, "colour"), "colour");
        return light;
    }

    // ambient, diffuse, specular: a finite number >= 0.
    double read_coefficient(const Json& object, const std::string& pointer, const char* key, std::string_view meaning,
                            double fallback) const {
        const auto it = object.find(key);
        if (it == object.end()) return fallback;
        const double value = read_number(*it, child(pointer, key), key);
        if (!(value >= 0)) fail(child(pointer, key), fmt::format("{} ({}) must be >= 0, got {}", key, meaning, value));
        return value;
    }

    Material read_material(const Json& value, const std::string& pointer) const {
        check_element(value, pointer, material_level(),
                      "such as {\"diffuse\": 0.7, \"specular\": 0.5, \"exponent\": 20}");
        Material material;
        material.ambient = read_coefficient(value, pointer, "ambient", "k_a, the light that reaches every point",
                                            material.ambient);
        material.diffuse = read_coefficient(value, pointer, "diffuse", "k_d, the article's Lambert term",
                                            material.diffuse);
        material.specular = read_coefficient(value, pointer, "specular", "k_s, Phong's highlight",
                                             material.specular);
        if (const auto it = value.find("exponent"); it != value.end()) {
            const std::string where = child(pointer, "exponent");
            const double exponent = read_number(*it, where, "exponent");
            if (!(exponent >= min_exponent && exponent <= max_exponent && std::floor(exponent) == exponent))
                fail(where, fmt::format("exponent (n, Phong's shininess) must be a whole number from {} to {}, got {}",
                                        min_exponent, max_exponent, exponent));
            material.exponent = static_cast<int>(exponent);
        }
        if (const auto it = value.find("colour"); it != value.end())
            material.colour = read_colour(*it, child(pointer, "colour"), "colour");
        return material;
    }

    const std::string& source_;
    const FirstUnknownKeys& first_unknown_keys_;
};

// ---------------------------------------------------------------------------
// Writing

// The shortest text that reads back to the same double. "-0.0" keeps the sign
// of a negative zero (JSON readers take "-0" for the integer 0). Non-finite
// numbers have no JSON form: null (such a scene does not load back).
std::string number_text(double value) {
    if (!std::isfinite(value)) return "null";
    if (value == 0 && std::signbit(value)) return "-0.0";
    return fmt::format("{}", value);
}

std::string vec3_text(const Vec3d& v) {
    return fmt::format("[{}, {}, {}]", number_text(v.x), number_text(v.y), number_text(v.z));
}

// True when a and b are the same double, down to the sign of zero: a colour
// is written as one grey number only when that number reads back as all
// three channels.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A grey colour as one number, any other as [r, g, b].
std::string colour_text(const Colour& c) {
    return same_bits(c.x, c.y) && same_bits(c.y, c.z) ? number_text(c.x) : vec3_text(c);
}

// `"key": [` then each item on its own line, then `]` (`[]` when empty).
std::string array_text(std::string_view key, const std::vector<std::string>& items) {
    std::string text = fmt::format("  \"{}\": [", key);
    for (std::size_t k = 0; k < items.size(); ++k) text += fmt::format("{}\n    {}", k == 0 ? "" : ",", items[k]);
    return text + (items.empty() ? "]" : "\n  ]");
}

std::string material_index_text(int material) {
    return material == no_material ? "" : fmt::format(", \"material\": {}", material);
}

// Closes a file descriptor when it goes out of scope.
struct Descriptor {
    int fd;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() { ::close(fd); }
};

std::string errno_text(int error) { return std::error_code(error, std::generic_category()).message(); }

}  // namespace

// A FIFO, a pipe or a slow device may give the file in pieces: read until the
// end of the file (read() returning 0), not until a short read. A signal that
// interrupts open() (waiting for a FIFO's writer) or read() (EINTR) is
// promyk's interrupt (SIGINT, SIGTERM: Interrupted, exit 128 + signal) or
// else harmless, and the call is made again.
Scene load_scene_file(const std::string& path) {
    int fd = -1;
    for (;;) {
        fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd >= 0) break;
        const int error = errno;
        if (error == EINTR) {
            throw_if_interrupted();
            continue;
        }
        throw SceneFileError(path, "cannot open the scene file: " + errno_text(error), error);
    }
    const Descriptor file{fd};
    std::string text;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t got = ::read(file.fd, buffer, sizeof buffer);
        if (got == 0) break;
        if (got < 0) {
            const int error = errno;
            if (error == EINTR) {
                throw_if_interrupted();
                continue;
            }
            throw SceneFileError(path, "cannot read the scene file: " + errno_text(error), error);
        }
        text.append(buffer, static_cast<std::size_t>(got));
        if (text.size() > max_scene_file_bytes)
            reject(path, "",
                   fmt::format("the scene file is larger than the limit of {} bytes (1 MiB)", max_scene_file_bytes));
    }
    return parse_scene(text, path);
}

Scene parse_scene(std::string_view text, const std::string& source) {
    const ParsedJson parsed = parse_json(text, source);
    return SceneReader(source, parsed.first_unknown_keys).read(parsed.root);
}

std::string scene_to_json(const Scene& scene, SceneDefaults defaults) {
    const bool all = defaults == SceneDefaults::written;
    const std::string name = Json(scene.name).dump(-1, ' ', false, Json::error_handler_t::replace);
    std::vector<std::string> fields = {
        fmt::format("  \"name\": {}", name),
        fmt::format("  \"z_E\": {}", number_text(scene.z_E)),
        fmt::format("  \"background\": {}", colour_text(scene.background)),
    };
    if (scene.shadows || all) fields.push_back(fmt::format("  \"shadows\": {}", scene.shadows ? "true" : "false"));
    std::vector<std::string> items;
    for (const Sphere& s : scene.spheres)
        items.push_back(fmt::format("{{\"S\": {}, \"r\": {}{}}}", vec3_text(s.S), number_text(s.r),
                                    material_index_text(s.material)));
    fields.push_back(array_text("spheres", items));
    items.clear();
    for (const Plane& p : scene.planes)
        items.push_back(
            fmt::format("{{\"Q\": {}, \"n\": {}{}}}", vec3_text(p.Q), vec3_text(p.n), material_index_text(p.material)));
    if (!items.empty() || all) fields.push_back(array_text("planes", items));
    items.clear();
    for (const Light& l : scene.lights)
        items.push_back(fmt::format("{{\"L\": {}, \"I\": {}{}}}", vec3_text(l.L), number_text(l.I),
                                    l.colour == white && !all ? "" : ", \"colour\": " + vec3_text(l.colour)));
    fields.push_back(array_text("lights", items));
    items.clear();
    for (const Material& m : scene.materials)
        items.push_back(fmt::format(
            "{{\"ambient\": {}, \"diffuse\": {}, \"specular\": {}, \"exponent\": {}, \"colour\": {}}}",
            number_text(m.ambient), number_text(m.diffuse), number_text(m.specular), m.exponent,
            vec3_text(m.colour)));
    if (!items.empty() || all) fields.push_back(array_text("materials", items));

    std::string text = "{\n";
    for (std::size_t k = 0; k < fields.size(); ++k) text += fields[k] + (k + 1 < fields.size() ? ",\n" : "\n");
    return text + "}\n";
}

}  // namespace promyk
