// A pixel's trace: the header that says what was computed and how, the steps
// in derivation order, the branch taken and the result. Its JSON form is
// described by src/trace/trace.schema.json.
#pragma once

#include <string>
#include <vector>

#include "trace/keys.hpp"
#include "trace/recorder.hpp"

namespace promyk {

inline constexpr int trace_schema_version = 1;

struct TraceHeader {
    std::string scene_name;
    std::string scene_hash;
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
};

// Appends the trace as one line of JSON (no newline): numbers as the shortest
// text that reads back to the same double, vectors as [x, y, z].
void append_trace_json(std::string& out, const PixelTrace& trace);

}  // namespace promyk
