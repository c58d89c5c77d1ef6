#include "trace/trace_read.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace {

using OrderedJson = nlohmann::ordered_json;  // scene_content keeps its order

// "-0" as a JSON number reads as the integer 0: written back it would lose
// its sign. The text with every such token (outside strings) as "-0.0".
// True when the character just appended to `out` begins a value (it follows
// ':', ',' or '[', spaces aside): a '-' there is a number's sign, not an
// exponent's.
bool starts_value(const std::string& out) {
    std::size_t k = out.size() - 1;  // out ends with the '-'
    while (k > 0 && (out[k - 1] == ' ' || out[k - 1] == '\t' || out[k - 1] == '\n' || out[k - 1] == '\r')) --k;
    return k == 0 || out[k - 1] == ':' || out[k - 1] == ',' || out[k - 1] == '[';
}

std::string negative_zeros_as_floats(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        out += c;
        if (in_string) {
            if (c == '\\' && k + 1 < text.size())
                out += text[++k];
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '-' && k + 1 < text.size() && text[k + 1] == '0' && starts_value(out) &&
                   (k + 2 == text.size() || (text[k + 2] != '.' && text[k + 2] != 'e' && text[k + 2] != 'E'))) {
            out += "0.0";
            ++k;
        }
    }
    return out;
}

struct Reader {
    const std::string& file;
    std::string line;  // "line 3" in a file, else ""

    // The fault's place: "line 3, /steps/2/value", "line 3", "/steps/2/value".
    [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
        throw InputError(file, line.empty() ? pointer : pointer.empty() ? line : line + ", " + pointer, what);
    }
    [[noreturn]] void bad(const std::string& pointer, const std::string& problem) const {
        fail(pointer, ui_message("trace_read_bad_field", {{"field", pointer}, {"problem", problem}}));
    }

    const OrderedJson& field(const OrderedJson& object, const char* name, const std::string& pointer) const {
        const auto it = object.find(name);
        if (it == object.end()) fail(pointer + "/" + name, ui_message("trace_read_not_trace", {{"problem", std::string("no \"") + name + "\""}}));
        return *it;
    }
    std::string text(const OrderedJson& object, const char* name, const std::string& pointer) const {
        const OrderedJson& value = field(object, name, pointer);
        if (!value.is_string()) bad(pointer + "/" + name, "not a string");
        return value.get<std::string>();
    }
    int integer(const OrderedJson& object, const char* name, const std::string& pointer, long long low, long long high) const {
        const OrderedJson& value = field(object, name, pointer);
        if (!value.is_number_integer()) bad(pointer + "/" + name, "not an integer");
        const long long n = value.get<long long>();
        if (n < low || n > high) bad(pointer + "/" + name, "out of range");
        return static_cast<int>(n);
    }
    // A number, or null with its "inf", "-inf", "nan" text.
    double number(const OrderedJson& value, const OrderedJson* text, const std::string& pointer) const {
        if (value.is_number()) return value.get<double>();
        if (value.is_null() && text && text->is_string()) {
            const std::string t = text->get<std::string>();
            if (t == "inf") return std::numeric_limits<double>::infinity();
            if (t == "-inf") return -std::numeric_limits<double>::infinity();
            if (t == "nan") return std::numeric_limits<double>::quiet_NaN();
        }
        bad(pointer, "not a number");
    }
    std::vector<std::string> real_texts(const OrderedJson& object, const char* name, std::size_t count,
                                        const std::string& pointer) const {
        const auto it = object.find(name);
        if (it == object.end()) return {};
        std::vector<std::string> out;
        if (count == 1 && it->is_string()) return {it->get<std::string>()};
        if (!it->is_array() || it->size() != count) bad(pointer + "/" + name, "not " + std::to_string(count) + " texts");
        for (const OrderedJson& t : *it) {
            if (!t.is_string()) bad(pointer + "/" + name, "not a string");
            out.push_back(t.get<std::string>());
        }
        return out;
    }
    Vec3d vector(const OrderedJson& value, const OrderedJson* text, const std::string& pointer) const {
        if (!value.is_array() || value.size() != 3) bad(pointer, "not three numbers");
        double c[3];
        for (std::size_t k = 0; k < 3; ++k) {
            const OrderedJson* t = text && text->is_array() && text->size() == 3 ? &(*text)[k] : nullptr;
            c[k] = number(value[k], t, pointer + "/" + std::to_string(k));
        }
        return {c[0], c[1], c[2]};
    }

    void steps(const OrderedJson& list, const std::string& pointer, int parent, PixelTrace& trace, int depth = 0) const {
        if (!list.is_array()) bad(pointer, "not a list");
        // Groups nest a sample, a light, an object: a few levels at most.
        if (depth > 8) bad(pointer, "groups nested too deep");
        for (std::size_t k = 0; k < list.size(); ++k) {
            const OrderedJson& item = list[k];
            const std::string at = pointer + "/" + std::to_string(k);
            if (!item.is_object()) bad(at, "not an object");
            if (item.contains("group")) {
                TraceGroup group;
                group.kind = text(item, "group", at);
                if (group.kind != "sphere" && group.kind != "plane" && group.kind != "light" && group.kind != "sample")
                    bad(at + "/group", "unknown group \"" + group.kind + "\"");
                group.index = integer(item, "index", at, 0, 1 << 20);
                group.parent = parent;
                trace.groups.push_back(group);
                steps(field(item, "steps", at), at + "/steps", static_cast<int>(trace.groups.size()) - 1, trace, depth + 1);
                continue;
            }
            Step step;
            const std::string key = text(item, "key", at);
            bool known = false;
            for (std::size_t n = 0; n < key_names.size(); ++n)
                if (key_names[n] == key) {
                    step.key = static_cast<Key>(n);
                    known = true;
                }
            if (!known) bad(at + "/key", "unknown key \"" + key + "\"");
            step.group = parent;
            const OrderedJson& value = field(item, "value", at);
            const auto t = item.find("text");
            const OrderedJson* text_of = t == item.end() ? nullptr : &*t;
            if (value.is_string()) {
                step.value = value.get<std::string>();
            } else if (value.is_array()) {
                step.value = vector(value, text_of, at + "/value");
                step.real_text = real_texts(item, "real_text", 3, at);
            } else {
                step.value = number(value, text_of, at + "/value");
                step.real_text = real_texts(item, "real_text", 1, at);
            }
            if (const auto d = item.find("digits_lost"); d != item.end()) {
                if (!d->is_number()) bad(at + "/digits_lost", "not a number");
                step.digits_lost = d->get<double>();
            }
            trace.steps.push_back(std::move(step));
        }
    }

    PixelTrace trace(const OrderedJson& j) const {
        if (!j.is_object()) fail("", ui_message("trace_read_not_trace", {{"problem", "not a JSON object"}}));
        if (integer(j, "schema", "", 0, 1 << 20) != trace_schema_version) bad("/schema", "not schema 1");
        PixelTrace trace;
        TraceHeader& h = trace.header;
        h.scene_name = text(j, "scene", "");
        h.scene_hash = text(j, "scene_hash", "");
        h.scene_file = text(j, "scene_file", "");
        if (const auto content = j.find("scene_content"); content != j.end()) {
            if (!content->is_object()) bad("/scene_content", "not an object");
            h.scene_content = content->dump();
        }
        h.w = integer(j, "w", "", 1, 1 << 16);
        h.z_E = number(field(j, "z_E", ""), nullptr, "/z_E");
        const OrderedJson& pixel = field(j, "pixel", "");
        if (!pixel.is_object()) bad("/pixel", "not an object");
        h.i = integer(pixel, "i", "/pixel", 0, h.w - 1);
        h.j = integer(pixel, "j", "/pixel", 0, h.w - 1);
        const OrderedJson& numeric = field(j, "numeric", "");
        if (!numeric.is_object()) bad("/numeric", "not an object");
        h.real = text(numeric, "real", "/numeric");
        if (h.real != "float" && h.real != "double" && h.real != "long-double" && h.real != "quad")
            bad("/numeric/real", "unknown real type \"" + h.real + "\"");
        h.formula = text(numeric, "formula", "/numeric");
        if (h.formula != "article" && h.formula != "stable" && h.formula != "fma" && h.formula != "geometric")
            bad("/numeric/formula", "unknown formula \"" + h.formula + "\"");
        h.spp = integer(numeric, "spp", "/numeric", 1, 1 << 20);
        const OrderedJson& effects = field(j, "effects", "");
        if (!effects.is_array()) bad("/effects", "not a list");
        h.effects.clear();
        for (const OrderedJson& e : effects) {
            if (!e.is_string()) bad("/effects", "not a list of names");
            h.effects.push_back(e.get<std::string>());
        }
        if (const auto skipped = j.find("skipped"); skipped != j.end()) {
            if (!skipped->is_array()) bad("/skipped", "not a list");
            // The reason is written in English: its message id is found back.
            const std::vector<std::string> ids = message_ids(Language::en);
            for (std::size_t k = 0; k < skipped->size(); ++k) {
                const std::string at = "/skipped/" + std::to_string(k);
                if (!(*skipped)[k].is_object()) bad(at, "not an object");
                const std::string stage = text((*skipped)[k], "stage", at);
                const std::string why = text((*skipped)[k], "why", at);
                std::string id;
                for (const std::string& candidate : ids)
                    if (candidate.rfind("stage_skip_", 0) == 0 && message(Language::en, candidate) == why) id = candidate;
                if (id.empty()) bad(at + "/why", "not a reason this version gives");
                h.skipped.emplace_back(stage, id);
            }
        }
        steps(field(j, "steps", ""), "/steps", -1, trace);
        trace.first_non_finite = first_non_finite_step(trace.steps);
        const std::string branch = text(j, "branch", "");
        bool known = false;
        for (int b = 0; b < branch_count; ++b)
            if (branch_name(static_cast<Branch>(b)) == branch) {
                trace.branch = static_cast<Branch>(b);
                known = true;
            }
        if (!known) bad("/branch", "unknown branch \"" + branch + "\"");
        if (const auto samples = j.find("samples"); samples != j.end()) {
            if (!samples->is_object()) bad("/samples", "not an object");
            SampleSummary summary;
            summary.centre = integer(*samples, "centre", "/samples", 0, h.spp - 1);
            const OrderedJson& branches = field(*samples, "branches", "/samples");
            if (!branches.is_object()) bad("/samples/branches", "not an object");
            for (int b = 0; b < branch_count; ++b) {
                const std::string name(branch_name(static_cast<Branch>(b)));
                if (branches.contains(name))
                    summary.branches[static_cast<std::size_t>(b)] = integer(branches, name.c_str(), "/samples/branches", 1, h.spp);
            }
            trace.samples = summary;
        }
        if (const auto hit = j.find("hit"); hit != j.end()) trace.hit_object = text(j, "hit", "");
        const OrderedJson& result = field(j, "result", "");
        const auto result_text = j.find("result_text");
        const OrderedJson* result_text_of = result_text == j.end() ? nullptr : &*result_text;
        if (result.is_array()) {
            const Vec3d rgb = vector(result, result_text_of, "/result");
            trace.result_rgb = rgb;
            trace.result = rgb.x;
            trace.result_real_text = real_texts(j, "result_real_text", 3, "");
            const OrderedJson& levels = field(j, "rgb", "");
            if (!levels.is_array() || levels.size() != 3) bad("/rgb", "not three levels");
            for (std::size_t k = 0; k < 3; ++k) {
                if (!levels[k].is_number_integer() || levels[k].get<long long>() < 0 || levels[k].get<long long>() > 255)
                    bad("/rgb/" + std::to_string(k), "not a level 0 ... 255");
                trace.rgb[k] = levels[k].get<int>();
            }
            trace.grey = trace.rgb[0];
        } else {
            trace.result = number(result, result_text_of, "/result");
            trace.result_real_text = real_texts(j, "result_real_text", 1, "");
            trace.grey = integer(j, "grey", "", 0, 255);
        }
        return trace;
    }
};

OrderedJson parse_json(std::string_view text, const Reader& reader) {
    try {
        return OrderedJson::parse(negative_zeros_as_floats(text));
    } catch (const OrderedJson::exception& e) {  // a syntax error, a number too large for a double
        reader.fail("", ui_message("trace_read_not_trace", {{"problem", e.what()}}));
    }
}

}  // namespace

PixelTrace read_trace_json(std::string_view text, const std::string& file, const std::string& where) {
    const Reader reader{file, where};
    return reader.trace(parse_json(text, reader));
}

TraceFile read_trace_file(std::string_view bytes, const std::string& file) {
    if (bytes.size() > max_trace_file_bytes)
        throw InputError(file, "", ui_message("trace_read_too_large", {{"bytes", std::to_string(bytes.size())},
                                                                        {"max", std::to_string(max_trace_file_bytes)}}));
    TraceFile out;
    std::set<std::pair<int, int>> seen;
    std::size_t start = 0;
    for (int line = 1; start < bytes.size(); ++line) {
        std::size_t end = bytes.find('\n', start);
        if (end == std::string_view::npos) end = bytes.size();
        std::string_view text = bytes.substr(start, end - start);
        start = end + 1;
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        if (text.find_first_not_of(" \t") == std::string_view::npos) continue;
        const std::string where = "line " + std::to_string(line);
        PixelTrace trace = read_trace_json(text, file, where);
        if (!out.traces.empty()) {
            const TraceHeader& first = out.traces.front().header;
            const TraceHeader& h = trace.header;
            const char* differs = h.scene_hash != first.scene_hash ? "scene_hash"
                                  : h.w != first.w                 ? "w"
                                  : h.real != first.real           ? "real"
                                  : h.formula != first.formula     ? "formula"
                                  : h.spp != first.spp             ? "spp"
                                                                   : nullptr;
            if (differs) throw InputError(file, where, ui_message("trace_read_differs", {{"field", differs}}));
        }
        if (!seen.insert({trace.header.i, trace.header.j}).second)
            throw InputError(file, where,
                             ui_message("trace_read_twice", {{"i", std::to_string(trace.header.i)},
                                                             {"j", std::to_string(trace.header.j)}}));
        out.traces.push_back(std::move(trace));
        out.lines.emplace_back(text);
    }
    if (out.traces.empty()) throw InputError(file, "", ui_message("trace_read_empty"));
    return out;
}

}  // namespace promyk
