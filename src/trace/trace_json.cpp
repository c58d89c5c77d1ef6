#include <iterator>
#include <type_traits>

#include <fmt/format.h>

#include "trace/json_text.hpp"
#include "trace/trace.hpp"

namespace promyk {

namespace {

using json_text::append_number;
using json_text::append_string;
using json_text::non_finite_text;

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

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
}

}  // namespace

void append_trace_json(std::string& out, const PixelTrace& trace) {
    append_header(out, trace.header);
    out += ",\"steps\":[";
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const Step& step = trace.steps[k];
        if (k) out += ',';
        out += "{\"key\":";
        append_string(out, key_name(step.key));
        out += ',';
        std::visit([&out](const auto& value) { append_value(out, value); }, step.value);
        out += '}';
    }
    out += ']';
    if (trace.first_non_finite) {
        const std::size_t k = *trace.first_non_finite;
        fmt::format_to(std::back_inserter(out), ",\"first_non_finite\":{{\"index\":{},\"key\":", k);
        append_string(out, k < trace.steps.size() ? key_name(trace.steps[k].key) : "");
        out += '}';
    }
    out += ",\"branch\":";
    append_string(out, branch_name(trace.branch));
    out += ",\"result\":";
    append_number(out, trace.result);
    if (!std::isfinite(trace.result)) {
        out += ",\"result_text\":";
        append_string(out, non_finite_text(trace.result));
    }
    fmt::format_to(std::back_inserter(out), ",\"grey\":{}}}", trace.grey);
}

std::optional<std::size_t> first_non_finite_step(const std::vector<Step>& steps) {
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const bool ok = std::visit(
            [](const auto& v) {
                if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>)
                    return std::isfinite(v);
                else
                    return finite(v);
            },
            steps[k].value);
        if (!ok) return k;
    }
    return std::nullopt;
}

}  // namespace promyk
