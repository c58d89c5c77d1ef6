#include <iterator>
#include <type_traits>

#include <fmt/format.h>

#include "util/interrupt.hpp"
#include "trace/json_text.hpp"
#include "trace/messages.hpp"
#include "trace/trace.hpp"

namespace promyk {

namespace {

using json_text::append_number;
using json_text::append_string;
using json_text::non_finite_text;

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite_value(const StepValue& value) {
    if (const double* number = std::get_if<double>(&value)) return std::isfinite(*number);
    if (const Vec3d* vector = std::get_if<Vec3d>(&value)) return finite(*vector);
    return true;
}

void append_value(std::string& out, double value) {
    out += "\"value\":";
    append_number(out, value);
    if (!std::isfinite(value)) {
        out += ",\"text\":";
        append_string(out, non_finite_text(value));
    }
}

void append_value(std::string& out, const Vec3d& value) {
    out += "\"value\":[";
    append_number(out, value.x);
    out += ',';
    append_number(out, value.y);
    out += ',';
    append_number(out, value.z);
    out += ']';
    if (!finite(value)) {
        // Text beside each component: null where the number stands as it is.
        out += ",\"text\":[";
        const double components[3] = {value.x, value.y, value.z};
        for (int k = 0; k < 3; ++k) {
            if (k) out += ',';
            if (std::isfinite(components[k]))
                out += "null";
            else
                append_string(out, non_finite_text(components[k]));
        }
        out += ']';
    }
}

void append_value(std::string& out, const std::string& word) {
    out += "\"value\":";
    append_string(out, word);
}

void append_header(std::string& out, const TraceHeader& h) {
    fmt::format_to(std::back_inserter(out), "{{\"schema\":{},\"promyk\":", trace_schema_version);
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
    fmt::format_to(std::back_inserter(out), ",\"w\":{},\"z_E\":", h.w);
    append_number(out, h.z_E);
    fmt::format_to(std::back_inserter(out), ",\"pixel\":{{\"i\":{},\"j\":{}}},\"numeric\":{{\"real\":", h.i, h.j);
    append_string(out, h.real);
    out += ",\"formula\":";
    append_string(out, h.formula);
    fmt::format_to(std::back_inserter(out), ",\"spp\":{}}},\"effects\":[", h.spp);
    for (std::size_t k = 0; k < h.effects.size(); ++k) {
        if (k) out += ',';
        append_string(out, h.effects[k]);
    }
    out += ']';
    if (!h.skipped.empty()) {
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
}

// A non-double value's exact text in its own type: "real_text": "0.1" for a
// number, ["0.1", "0.2", "3"] for a vector.
void append_real_text(std::string& out, const std::vector<std::string>& texts, const char* name = "real_text") {
    if (texts.empty()) return;
    fmt::format_to(std::back_inserter(out), ",\"{}\":", name);
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
std::vector<int> group_chain(const std::vector<TraceGroup>& groups, int group) {
    std::vector<int> chain;
    for (int g = group; g >= 0; g = groups[static_cast<std::size_t>(g)].parent) chain.insert(chain.begin(), g);
    return chain;
}

// Steps in order, nested in their groups: a group's steps are recorded
// together, so opening and closing groups as the chain changes rebuilds the
// tree ({"group": "sphere", "index": 0, "steps": [...]}).
void append_steps(std::string& out, const PixelTrace& trace) {
    out += ",\"steps\":[";
    std::vector<int> open;   // the groups open now, outermost first
    bool first = true;       // no element yet in the innermost open array
    std::size_t written = 0;
    for (const Step& step : trace.steps) {
        if ((written++ & 4095) == 0) throw_if_interrupted();  // a trace of millions of steps takes seconds
        const std::vector<int> chain = group_chain(trace.groups, step.group);
        std::size_t common = 0;
        while (common < open.size() && common < chain.size() && open[common] == chain[common]) ++common;
        while (open.size() > common) {
            out += "]}";
            open.pop_back();
            first = false;
        }
        for (std::size_t k = common; k < chain.size(); ++k) {
            const TraceGroup& group = trace.groups[static_cast<std::size_t>(chain[k])];
            if (!first) out += ',';
            out += "{\"group\":";
            append_string(out, group.kind);
            fmt::format_to(std::back_inserter(out), ",\"index\":{},\"steps\":[", group.index);
            open.push_back(chain[k]);
            first = true;
        }
        if (!first) out += ',';
        first = false;
        out += "{\"key\":";
        append_string(out, key_name(step.key));
        out += ',';
        std::visit([&out](const auto& value) { append_value(out, value); }, step.value);
        append_real_text(out, step.real_text);
        // The digits its subtraction cancels, to one decimal (trace/digits_lost.hpp);
        // a value that is not finite has no estimate.
        if (!std::isnan(step.digits_lost) && finite_value(step.value))
            fmt::format_to(std::back_inserter(out), ",\"digits_lost\":{:.1f}", rounded_digits(step.digits_lost));
        out += '}';
    }
    for (std::size_t k = 0; k < open.size(); ++k) out += "]}";
    out += ']';
}

}  // namespace

void append_trace_json(std::string& out, const PixelTrace& trace) {
    append_header(out, trace.header);
    append_steps(out, trace);
    if (trace.first_non_finite) {
        const std::size_t k = *trace.first_non_finite;
        fmt::format_to(std::back_inserter(out), ",\"first_non_finite\":{{\"index\":{},\"key\":", k);
        append_string(out, k < trace.steps.size() ? key_name(trace.steps[k].key) : "");
        out += '}';
    }
    out += ",\"branch\":";
    append_string(out, branch_name(trace.branch));
    if (trace.samples) {
        // Which sample's branch is the pixel's, and how the samples went.
        fmt::format_to(std::back_inserter(out), ",\"samples\":{{\"centre\":{},\"branches\":{{", trace.samples->centre);
        bool first = true;
        for (int b = 0; b < branch_count; ++b) {
            const int n = trace.samples->branches[static_cast<std::size_t>(b)];
            if (n == 0) continue;
            if (!first) out += ',';
            first = false;
            append_string(out, branch_name(static_cast<Branch>(b)));
            fmt::format_to(std::back_inserter(out), ":{}", n);
        }
        fmt::format_to(std::back_inserter(out), "}},\"agree\":{}}}", trace.samples->agree() ? "true" : "false");
    }
    if (!trace.hit_object.empty()) {
        out += ",\"hit\":";
        append_string(out, trace.hit_object);
    }
    if (trace.result_rgb) {
        // A coloured scene: [r, g, b], with text beside non-finite channels.
        out += ",\"result\":[";
        const Vec3d& c = *trace.result_rgb;
        append_number(out, c.x);
        out += ',';
        append_number(out, c.y);
        out += ',';
        append_number(out, c.z);
        out += ']';
        if (!finite(c)) {
            out += ",\"result_text\":[";
            const double channels[3] = {c.x, c.y, c.z};
            for (int k = 0; k < 3; ++k) {
                if (k) out += ',';
                if (std::isfinite(channels[k]))
                    out += "null";
                else
                    append_string(out, non_finite_text(channels[k]));
            }
            out += ']';
        }
        append_real_text(out, trace.result_real_text, "result_real_text");
        fmt::format_to(std::back_inserter(out), ",\"rgb\":[{},{},{}]}}", trace.rgb[0], trace.rgb[1], trace.rgb[2]);
        return;
    }
    out += ",\"result\":";
    append_number(out, trace.result);
    if (!std::isfinite(trace.result)) {
        out += ",\"result_text\":";
        append_string(out, non_finite_text(trace.result));
    }
    append_real_text(out, trace.result_real_text, "result_real_text");
    fmt::format_to(std::back_inserter(out), ",\"grey\":{}}}", trace.grey);
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
