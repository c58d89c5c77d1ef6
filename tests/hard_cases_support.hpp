// What the hard-case tests share (tests/hard_cases_test.cpp for the article's
// formula, tests/hard_cases_formulas_test.cpp for the others): the reference
// made by tests/reference/make_hard_cases.py, the real types as it names
// them, exact readings of numbers in each type, and the engine's traced
// values labelled as the reference labels them.
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <quadmath.h>

#include "math/real.hpp"
#include "trace/keys.hpp"
#include "trace/trace.hpp"

namespace hard_cases_support {

using json = nlohmann::json;
using promyk::quad;

inline const std::string hard_cases_reference_path = PROMYK_SOURCE_DIR "/tests/reference/hard_cases_reference.json";

inline const json& hard_cases_reference() {
    static const json reference = [] {
        std::ifstream in(hard_cases_reference_path, std::ios::binary);
        if (!in) throw std::runtime_error("cannot open " + hard_cases_reference_path);
        std::ostringstream text;
        text << in.rdbuf();
        return json::parse(text.str());
    }();
    return reference;
}

struct TypeInfo {
    const char* name;  // as the reference names it
    promyk::RealType real;
    int bits;          // significand bits p
};

inline const TypeInfo real_types[] = {{"float", promyk::RealType::float_, 24},
                               {"double", promyk::RealType::double_, 53},
                               {"long-double", promyk::RealType::long_double, 64},
                               {"quad", promyk::RealType::quad_, 113}};

// A number's text read in the given type (correctly rounded by the C library
// and libquadmath), held exactly in a quad.
inline quad read_in(const std::string& text, const std::string& type) {
    const char* s = text.c_str();
    char* end = nullptr;
    quad value;
    if (type == "float")
        value = quad(std::strtof(s, &end));
    else if (type == "double")
        value = quad(std::strtod(s, &end));
    else if (type == "long-double")
        value = quad(std::strtold(s, &end));
    else
        value = strtoflt128(s, &end);
    if (text.empty() || end != s + text.size()) throw std::runtime_error("not a number: " + text);
    return value;
}

inline std::string show(quad v) {
    char buffer[64];
    quadmath_snprintf(buffer, sizeof buffer, "%.36Qg", v);
    return buffer;
}

inline quad absq(quad v) { return v < 0 ? -v : v; }

// A step's exact value in its type: the double itself, or its real_text.
inline quad step_value(const promyk::Step& step, const std::string& type) {
    if (type == "double") return quad(std::get<double>(step.value));
    REQUIRE(step.real_text.size() == 1);
    return read_in(step.real_text[0], type);
}

// The primary ray's tests and the shading's D, labelled as the reference
// labels them: "sphere 0 delta", "plane 1 t_plane", "t_hit", "light 0 D". The
// article's kernel records them at the top level (one sphere, one light).
inline std::vector<std::pair<std::string, quad>> engine_steps(const promyk::PixelTrace& trace, const std::string& type,
                                                       const std::set<std::string>& wanted) {
    std::vector<std::pair<std::string, quad>> out;
    for (const promyk::Step& step : trace.steps) {
        const std::string key(promyk::key_name(step.key));
        if (!wanted.count(key)) continue;
        std::string label;
        if (step.group < 0) {
            label = key == "D" ? "light 0 D" : key == "t_hit" ? "t_hit" : "sphere 0 " + key;
        } else {
            const promyk::TraceGroup& group = trace.groups.at(static_cast<std::size_t>(step.group));
            if (group.parent != -1) continue;  // a shadow ray's test, inside a light's group
            if (group.kind == "light" && key != "D") continue;
            label = promyk::group_title(group) + " " + key;
        }
        out.emplace_back(label, step_value(step, type));
    }
    return out;
}

// A documented failure's digits lost, as the catalogue writes it ("all" for null).
inline std::string digits_lost_text(const json& lost) {
    if (lost.is_null()) return "all";
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(1);
    out << lost.get<double>();
    return out.str();
}

inline const json& case_by_id(const std::string& id) {
    for (const json& c : hard_cases_reference().at("cases"))
        if (c.at("id") == id) return c;
    throw std::runtime_error("no hard case " + id);
}

// A reference value written as text, read exactly as a quad.
inline quad text_q(const json& v) { return strtoflt128(v.get<std::string>().c_str(), nullptr); }

}  // namespace hard_cases_support
