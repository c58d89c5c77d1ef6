// Scene bytes to a JSON value (the first half of reading a scene): the bytes
// checked (size, NUL, byte order marks), parsed with the path of every value
// known, so that faults are named by JSON pointer and put in document order.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"

namespace promyk::scene_detail {

// Objects are std::maps (insertion in log n). They do not keep the file's key
// order: the parser records the unknown keys and the order of the values.
using Json = nlohmann::json;

struct ParsedJson {
    Json root;
    // The unknown keys of each object of the format, in file order, by the
    // pointer of the object ("", "/spheres/0", "/lights/0").
    std::map<std::string, std::vector<std::string>> unknown_keys;
    // The place of each value of the format's levels (depth 4 at most) in
    // the file, by its pointer: faults are reported in this order.
    std::unordered_map<std::string, std::size_t> order;
    // The place of the end of each object and array ('}' or ']'), by its
    // pointer: a missing key is reported where its object ends.
    std::unordered_map<std::string, std::size_t> ends;
    // Faults found while parsing that do not stop it (a duplicate key), at
    // most max_collected_faults; faults_cut when there were more.
    std::vector<SceneFault> faults;
    bool faults_cut = false;
};

// Throws InputError for a fault that stops the reading: too large, empty,
// a NUL or a second byte order mark, a syntax error, a number beyond a
// double, nesting beyond 64 levels.
ParsedJson parse_json(std::string_view text, const std::string& source);

// An InputError for one fault, with `where` and `what` made printable().
[[noreturn]] void reject(const std::string& source, std::string_view where, std::string_view what);

}  // namespace promyk::scene_detail
