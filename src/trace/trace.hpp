// A pixel's trace: the header that says what was computed and how, the steps
// in derivation order, the branch taken and the result. Its JSON form is
// described by src/trace/trace.schema.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trace/keys.hpp"
#include "trace/recorder.hpp"

namespace promyk {

inline constexpr int trace_schema_version = 1;

// A value the scene gives (S, r, L, ...), named by its vocabulary key.
struct GivenValue {
    std::string key;
    StepValue value;
};

struct TraceHeader {
    std::string scene_name;
    std::string scene_hash;
    std::string scene_file;     // the file the scene came from, or "built-in"
    std::string scene_content;  // the whole scene as compact JSON, as the scene writer prints it
    std::vector<GivenValue> given;  // the scene's values the steps use, for the text header
    int w = 0;
    double z_E = 0;
    int i = 0, j = 0;
    std::string real = "double";
    std::string formula = "article";
    int spp = 1;
    std::vector<std::string> effects = {"lambert"};
};

struct PixelTrace {
    TraceHeader header;
    std::vector<Step> steps;
    Branch branch = Branch::miss;
    double result = 0;
    int grey = 0;  // the pixel's 8-bit grey level in the image
    // The index into steps of the first value that is NaN or infinite.
    std::optional<std::size_t> first_non_finite;
};

// The index of the first step whose value (or any component) is not finite.
std::optional<std::size_t> first_non_finite_step(const std::vector<Step>& steps);

// Appends the trace as one line of JSON (no newline): numbers as the shortest
// text that reads back to the same double, vectors as [x, y, z].
void append_trace_json(std::string& out, const PixelTrace& trace);

}  // namespace promyk
