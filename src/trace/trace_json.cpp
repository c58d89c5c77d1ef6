#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "util/interrupt.hpp"
#include "trace/json_text.hpp"
#include "trace/messages.hpp"
#include "trace/trace.hpp"
#include "trace/trace_json_parts.hpp"

namespace promyk {

namespace {

using json_text::append_integer;
using json_text::append_number;
using json_text::append_string;
using json_text::non_finite_text;

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite_value(const StepValue& value) {
    if (const double* number = std::get_if<double>(&value)) return std::isfinite(*number);
    if (const Vec3d* vector = std::get_if<Vec3d>(&value)) return finite(*vector);
    return true;
}

// [x,y,z], and, when a component is not finite, `text_key` beside it with
// the text of each component (null where the number stands as it is).
void append_vector(std::string& out, const Vec3d& v, const char* text_key) {
    out += '[';
    append_number(out, v.x);
    out += ',';
    append_number(out, v.y);
    out += ',';
    append_number(out, v.z);
    out += ']';
    if (finite(v)) return;
    out += text_key;
    out += '[';
    const double components[3] = {v.x, v.y, v.z};
    for (int k = 0; k < 3; ++k) {
        if (k) out += ',';
        if (std::isfinite(components[k]))
            out += "null";
        else
            append_string(out, non_finite_text(components[k]));
    }
    out += ']';
}

// A step's value, after "value": (and its text when not finite).
void append_value(std::string& out, double value) {
    append_number(out, value);
    if (!std::isfinite(value)) {
        out += ",\"text\":";
        append_string(out, non_finite_text(value));
    }
}

void append_value(std::string& out, const Vec3d& value) { append_vector(out, value, ",\"text\":"); }

void append_value(std::string& out, const std::string& word) { append_string(out, word); }

// {"key":"E","value": for every key: how each step begins, written in one
// piece (most of a trace line is its steps).
const std::array<std::string, key_names.size()>& step_openings() {
    static const std::array<std::string, key_names.size()> openings = [] {
        std::array<std::string, key_names.size()> texts;
        for (std::size_t k = 0; k < key_names.size(); ++k) {
            texts[k] = "{\"key\":";
            append_string(texts[k], key_names[k]);
            texts[k] += ",\"value\":";
        }
        return texts;
    }();
    return openings;
}

// A non-double value's exact text in its own type: "real_text": "0.1" for a
// number, ["0.1", "0.2", "3"] for a vector.
void append_real_text(std::string& out, const std::vector<std::string>& texts, const char* key = ",\"real_text\":") {
    if (texts.empty()) return;
    out += key;
    if (texts.size() == 1) {
        append_string(out, texts.front());
        return;
    }
    out += '[';
    for (std::size_t k = 0; k < texts.size(); ++k) {
        if (k) out += ',';
        append_string(out, texts[k]);
    }
    out += ']';
}

// The chain of groups from the top level down to `group` (empty for -1).
void group_chain(const std::vector<TraceGroup>& groups, int group, std::vector<int>& chain) {
    chain.clear();
    for (int g = group; g >= 0; g = groups[static_cast<std::size_t>(g)].parent) chain.push_back(g);
    std::reverse(chain.begin(), chain.end());
}

// Steps in order, nested in their groups: a group's steps are recorded
// together, so opening and closing groups as the chain changes rebuilds the
// tree ({"group": "sphere", "index": 0, "steps": [...]}).
void append_steps(std::string& out, const PixelTrace& trace) {
    out += ",\"steps\":[";
    std::vector<int> open;   // the groups open now, outermost first
    std::vector<int> chain;  // the groups of the step being written
    int group = -1;          // the innermost open group
    bool first = true;       // no element yet in the innermost open array
    std::size_t written = 0;
    const std::array<std::string, key_names.size()>& openings = step_openings();
    for (const Step& step : trace.steps) {
        if ((written++ & 4095) == 0) throw_if_interrupted();  // a trace of millions of steps takes seconds
        if (step.group != group) {
            group = step.group;
            group_chain(trace.groups, group, chain);
            std::size_t common = 0;
            while (common < open.size() && common < chain.size() && open[common] == chain[common]) ++common;
            while (open.size() > common) {
                out += "]}";
                open.pop_back();
                first = false;
            }
            for (std::size_t k = common; k < chain.size(); ++k) {
                const TraceGroup& opened = trace.groups[static_cast<std::size_t>(chain[k])];
                if (!first) out += ',';
                out += "{\"group\":";
                append_string(out, opened.kind);
                out += ",\"index\":";
                append_integer(out, opened.index);
                out += ",\"steps\":[";
                open.push_back(chain[k]);
                first = true;
            }
        }
        if (!first) out += ',';
        first = false;
        out += openings[static_cast<std::size_t>(step.key)];
        std::visit([&out](const auto& value) { append_value(out, value); }, step.value);
        append_real_text(out, step.real_text);
        // The digits its subtraction cancels, to one decimal (trace/digits_lost.hpp);
        // a value that is not finite has no estimate.
        if (!std::isnan(step.digits_lost) && finite_value(step.value)) {
            out += ",\"digits_lost\":";
            json_text::append_tenths(out, rounded_digits(step.digits_lost));
        }
        out += '}';
    }
    for (std::size_t k = 0; k < open.size(); ++k) out += "]}";
    out += ']';
}

// ,"samples":{"centre":3,"branches":{"miss":2,"lit":2},"agree":false}
void append_samples(std::string& out, const SampleSummary& samples) {
    out += ",\"samples\":{\"centre\":";
    append_integer(out, samples.centre);
    out += ",\"branches\":{";
    bool first = true;
    for (int b = 0; b < branch_count; ++b) {
        const int n = samples.branches[static_cast<std::size_t>(b)];
        if (n == 0) continue;
        if (!first) out += ',';
        first = false;
        append_string(out, branch_name(static_cast<Branch>(b)));
        out += ':';
        append_integer(out, n);
    }
    out += samples.agree() ? "},\"agree\":true}" : "},\"agree\":false}";
}

}  // namespace

void trace_json::append_opening(std::string& out, const TraceHeader& h) {
    out += "{\"schema\":";
    append_integer(out, trace_schema_version);
    out += ",\"promyk\":";
    append_string(out, PROMYK_VERSION);
    out += ",\"scene\":";
    append_string(out, h.scene_name);
    out += ",\"scene_hash\":";
    append_string(out, h.scene_hash);
    out += ",\"scene_file\":";
    append_string(out, h.scene_file);
    if (!h.scene_content.empty()) {
        out += ",\"scene_content\":";
        out += h.scene_content;  // already JSON
    }
    out += ",\"w\":";
    append_integer(out, h.w);
    out += ",\"z_E\":";
    append_number(out, h.z_E);
}

void trace_json::append_pixel(std::string& out, const TraceHeader& h) {
    out += ",\"pixel\":{\"i\":";
    append_integer(out, h.i);
    out += ",\"j\":";
    append_integer(out, h.j);
    out += "},\"numeric\":{\"real\":";
    append_string(out, h.real);
    out += ",\"formula\":";
    append_string(out, h.formula);
    out += ",\"spp\":";
    append_integer(out, h.spp);
    out += '}';
}

void trace_json::append_stages(std::string& out, const TraceHeader& h) {
    out += ",\"effects\":[";
    for (std::size_t k = 0; k < h.effects.size(); ++k) {
        if (k) out += ',';
        append_string(out, h.effects[k]);
    }
    out += ']';
    if (h.skipped.empty()) return;
    out += ",\"skipped\":[";
    for (std::size_t k = 0; k < h.skipped.size(); ++k) {
        if (k) out += ',';
        out += "{\"stage\":";
        append_string(out, h.skipped[k].first);
        out += ",\"why\":";
        append_string(out, message(Language::en, h.skipped[k].second));
        out += '}';
    }
    out += ']';
}

void trace_json::append_body(std::string& out, const PixelTrace& trace) {
    append_steps(out, trace);
    if (trace.first_non_finite) {
        const std::size_t k = *trace.first_non_finite;
        out += ",\"first_non_finite\":{\"index\":";
        append_integer(out, static_cast<long long>(k));
        out += ",\"key\":";
        append_string(out, k < trace.steps.size() ? key_name(trace.steps[k].key) : "");
        out += '}';
    }
    out += ",\"branch\":";
    append_string(out, branch_name(trace.branch));
    // Which sample's branch is the pixel's, and how the samples went.
    if (trace.samples) append_samples(out, *trace.samples);
    if (!trace.hit_object.empty()) {
        out += ",\"hit\":";
        append_string(out, trace.hit_object);
    }
    if (trace.result_rgb) {
        // A coloured scene: [r, g, b], with text beside non-finite channels.
        out += ",\"result\":";
        append_vector(out, *trace.result_rgb, ",\"result_text\":");
        append_real_text(out, trace.result_real_text, ",\"result_real_text\":");
        out += ",\"rgb\":[";
        append_integer(out, trace.rgb[0]);
        out += ',';
        append_integer(out, trace.rgb[1]);
        out += ',';
        append_integer(out, trace.rgb[2]);
        out += "]}";
        return;
    }
    out += ",\"result\":";
    append_number(out, trace.result);
    if (!std::isfinite(trace.result)) {
        out += ",\"result_text\":";
        append_string(out, non_finite_text(trace.result));
    }
    append_real_text(out, trace.result_real_text, ",\"result_real_text\":");
    out += ",\"grey\":";
    append_integer(out, trace.grey);
    out += '}';
}

void append_trace_json(std::string& out, const PixelTrace& trace) {
    trace_json::append_opening(out, trace.header);
    trace_json::append_pixel(out, trace.header);
    trace_json::append_stages(out, trace.header);
    trace_json::append_body(out, trace);
}

std::optional<std::size_t> first_non_finite_step(const std::vector<Step>& steps) {
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const bool ok = std::visit(
            [](const auto& v) {
                using V = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<V, double>)
                    return std::isfinite(v);
                else if constexpr (std::is_same_v<V, Vec3d>)
                    return finite(v);
                else
                    return true;  // a word
            },
            steps[k].value);
        if (!ok) return k;
    }
    return std::nullopt;
}

}  // namespace promyk
