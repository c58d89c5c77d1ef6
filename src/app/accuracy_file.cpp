#include "app/accuracy_file.hpp"

#include <algorithm>
#include <set>
#include <string_view>

#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"

namespace promyk::app {

namespace {

using json = nlohmann::json;

// What a value should have been, by its message id (messages_precision_lab.json).
[[noreturn]] void refuse(const std::string& path, const std::string& where, const char* expected) {
    throw InputError(path, where, ui_message("bench_file_expected", {{"expected", ui_message(expected)}}));
}

const json& field(const json& object, const char* key, const std::string& path, const std::string& where) {
    const auto it = object.find(key);
    if (it == object.end()) throw InputError(path, where, ui_message("bench_file_missing", {{"key", key}}));
    return *it;
}

void number_at_least_0(const json& v, bool null_allowed, const std::string& path, const std::string& where) {
    if (null_allowed && v.is_null()) return;
    if (!v.is_number() || !(v.get<double>() >= 0))
        refuse(path, where, null_allowed ? "bench_file_number_or_null" : "bench_file_number");
}

void whole_at_least(const json& v, long long low, const std::string& path, const std::string& where) {
    if (!v.is_number_integer() || v.get<long long>() < low)
        refuse(path, where, low == 0 ? "bench_file_whole_0" : "bench_file_whole_1");
}

// Deeper than the format ever nests (4): refused before the parser builds it.
bool nests_deeper_than(std::string_view text, int most) {
    int depth = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > most) return true;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

}  // namespace

json read_accuracy_file(const std::string& text, const std::string& path) {
    if (nests_deeper_than(text, 64)) throw InputError(path, "", ui_message("bench_file_not_accuracy"));
    json file;
    try {
        file = json::parse(text);
    } catch (const json::parse_error& e) {
        // The line and column of the byte the parser stopped at.
        const std::size_t at = std::min(static_cast<std::size_t>(e.byte > 0 ? e.byte - 1 : 0), text.size());
        const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
        const std::size_t start = text.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t column = at - (start == std::string::npos || at == 0 ? 0 : start + 1) + 1;
        throw InputError(path, "", ui_message("bench_file_not_json", {{"line", std::to_string(line)},
                                                                      {"column", std::to_string(column)}}));
    } catch (const json::out_of_range& e) {
        // A number beyond double's range ("1e999"): the parser reports it
        // apart from the syntax errors, quoting the number (found by fuzz_accuracy).
        const std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        const std::string number = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
        throw InputError(path, "", ui_message("bench_file_number_overflow", {{"number", printable(number)}}));
    }
    if (!file.is_object() || file.value("bench", json()) != "accuracy" || file.value("schema", json()) != 1)
        throw InputError(path, "", ui_message("bench_file_not_accuracy"));

    const json& scenes = field(file, "scenes", path, "");
    if (!scenes.is_array() || scenes.empty()) refuse(path, "/scenes", "bench_file_array");
    std::set<std::string> names;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const std::string at = "/scenes/" + std::to_string(k);
        const json& scene = scenes[k];
        if (!scene.is_object()) refuse(path, at, "bench_file_object");
        const json& name = field(scene, "name", path, at);
        if (!name.is_string()) refuse(path, at + "/name", "bench_file_string");
        names.insert(name.get<std::string>());
        number_at_least_0(field(scene, "base_ns_per_pixel", path, at), false, path, at + "/base_ns_per_pixel");
    }

    const json& results = field(file, "results", path, "");
    if (!results.is_array()) refuse(path, "/results", "bench_file_array");
    for (std::size_t k = 0; k < results.size(); ++k) {
        const std::string at = "/results/" + std::to_string(k);
        const json& r = results[k];
        if (!r.is_object()) refuse(path, at, "bench_file_object");
        const json& scene = field(r, "scene", path, at);
        if (!scene.is_string() || !names.count(scene.get<std::string>())) refuse(path, at + "/scene", "bench_file_scene");
        const json& real = field(r, "real", path, at);
        static const std::set<std::string> reals = {"float", "double", "long-double", "quad"};
        if (!real.is_string() || !reals.count(real.get<std::string>())) refuse(path, at + "/real", "bench_file_real");
        const json& formula = field(r, "formula", path, at);
        static const std::set<std::string> formulas = {"article", "stable", "fma", "geometric"};
        if (!formula.is_string() || !formulas.count(formula.get<std::string>()))
            refuse(path, at + "/formula", "bench_file_formula");
        whole_at_least(field(r, "spp", path, at), 1, path, at + "/spp");
        whole_at_least(field(r, "pixels", path, at), 1, path, at + "/pixels");
        for (const char* key : {"sphere_pixels", "branch_differs", "non_finite"})
            whole_at_least(field(r, key, path, at), 0, path, at + "/" + key);
        number_at_least_0(field(r, "ns_per_pixel", path, at), false, path, at + "/ns_per_pixel");
        for (const char* key : {"ratio", "max_error", "median_error"})
            number_at_least_0(field(r, key, path, at), true, path, at + "/" + key);
    }
    return file;
}

}  // namespace promyk::app
