// A pixel's trace: the header that says what was computed and how, the steps
// in derivation order, the branch taken and the result. Its JSON form is
// described by src/trace/trace.schema.json.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <utility>

#include "trace/keys.hpp"
#include "trace/recorder.hpp"

namespace promyk {

inline constexpr int trace_schema_version = 1;

// A value the scene gives (S, r, L, ...), named by its vocabulary key.
struct GivenValue {
    std::string key;
    StepValue value;
};

// The values of one object or light, for a scene with several (the text
// header lists them: "sphere 1: S = (0.9, 0.4, 4.6), r = 1.3").
struct GivenGroup {
    std::string kind;  // sphere, plane, light
    int index = 0;
    std::vector<GivenValue> values;
};

struct TraceHeader {
    std::string scene_name;
    std::string scene_hash;
    std::string scene_file;     // the file the scene came from, or "built-in"
    std::string scene_content;  // the whole scene as compact JSON, as the scene writer prints it
    std::vector<GivenValue> given;  // the scene's values the steps use, for the text header
    std::vector<GivenGroup> given_groups;  // each object and light, when there are several
    int w = 0;
    double z_E = 0;
    int i = 0, j = 0;
    std::string real = "double";
    std::string formula = "article";
    int spp = 1;
    std::vector<std::string> effects = {"lambert"};  // the stages that ran, in order
    // The stages that did not run, each with the id of the message (in
    // lessons/messages.json) that says why: {"shadows", "stage_skip_shadows"}.
    std::vector<std::pair<std::string, std::string>> skipped;
};

// How a pixel's samples went (spp > 1): the centre sample, whose branch is
// the pixel's, and how many samples took each branch.
struct SampleSummary {
    int centre = 0;
    std::array<int, branch_count> branches{};
    bool agree() const {
        int branches_taken = 0;
        for (int count : branches) branches_taken += count != 0;
        return branches_taken <= 1;
    }
};

struct PixelTrace {
    TraceHeader header;
    std::vector<Step> steps;
    std::vector<TraceGroup> groups;  // the groups steps refer to (Step::group)
    Branch branch = Branch::miss;
    std::string hit_object;  // "sphere 1", "plane 0"; empty for a miss (and the article's kernel)
    double result = 0;       // the intensity; for a coloured scene its red channel
    std::optional<Vec3d> result_rgb;  // a coloured scene's [r, g, b]
    // For a non-double real type: the result's exact text in its own type
    // (one, or r, g, b); empty for double.
    std::vector<std::string> result_real_text;
    int grey = 0;  // the pixel's 8-bit grey level in the image (a coloured scene: red)
    std::array<int, 3> rgb{};  // a coloured scene's 8-bit r, g, b
    std::optional<SampleSummary> samples;  // for spp > 1
    // The index into steps of the first value that is NaN or infinite.
    std::optional<std::size_t> first_non_finite;
};

// The index of the first step whose value (or any component) is not finite.
std::optional<std::size_t> first_non_finite_step(const std::vector<Step>& steps);

// Appends the trace as one line of JSON (no newline): numbers as the shortest
// text that reads back to the same double, vectors as [x, y, z].
void append_trace_json(std::string& out, const PixelTrace& trace);

}  // namespace promyk
