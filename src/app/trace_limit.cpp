#include "app/trace_limit.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <fmt/format.h>

#include "render/trace_size.hpp"
#include "trace/byte_size_text.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk::app {

namespace {

// SIZE as bytes: a positive number with an optional unit (k, M, G, T, as
// powers of 1000, with Ki, Mi, Gi, Ti as powers of 1024, and an optional B);
// nothing else.
std::optional<double> parse_size(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) return std::nullopt;
    std::string unit(end);
    if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
    double scale = 1;
    const bool binary = unit.size() == 2 && unit[1] == 'i';
    if (unit.size() == 1 || binary) {
        const double base = binary ? 1024.0 : 1000.0;
        switch (std::tolower(static_cast<unsigned char>(unit[0]))) {
            case 'k': scale = base; break;
            case 'm': scale = base * base; break;
            case 'g': scale = base * base * base; break;
            case 't': scale = base * base * base * base; break;
            default: return std::nullopt;
        }
    } else if (!unit.empty()) {
        return std::nullopt;
    }
    const double bytes = number * scale;
    if (!std::isfinite(bytes) || !(bytes >= 1)) return std::nullopt;
    return bytes;
}

}  // namespace

CLI::Option* add_max_trace_size_option(CLI::App& cmd, std::string& size) {
    return cmd
        .add_option("--max-trace-size", size,
                    "The largest trace to build, estimated from the scene before tracing (default 250MB):\n"
                    "bytes, or with a unit (500MB, 2GB, 3GiB)")
        ->type_name("SIZE")
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_size(text) ? std::string()
                                        : ui_message("limit_size_not_a_size", {{"option", "--max-trace-size"}, {"value", text}});
            },
            "", ""));
}

double trace_size_limit(const std::string& size) {
    if (size.empty()) return default_max_trace_size;
    return parse_size(size).value_or(default_max_trace_size);
}

double trace_cost_bytes(const TraceCost& cost) {
    const double one = pixel_trace_bytes(*cost.scene, cost.real, cost.spp) * (cost.text ? text_trace_factor : 1.0);
    return one * static_cast<double>(cost.traces);
}

void require_trace_size(const TraceCost& cost, const std::string& size_option) {
    const double limit = trace_size_limit(size_option);
    const double estimate = trace_cost_bytes(cost);
    if (estimate <= limit) return;
    const Scene& scene = *cost.scene;
    // A limit that lets it through, rounded up to a whole unit of the estimate's size.
    const double magnitude = std::pow(10.0, std::floor(std::log10(estimate)));
    const double enough = std::ceil(estimate / magnitude) * magnitude;
    throw UsageError(ui_message(
        "limit_trace_too_large",
        {{"estimate", byte_size_text(estimate)},
         {"spheres", std::to_string(scene.spheres.size())},
         {"planes", std::to_string(scene.planes.size())},
         {"lights", std::to_string(scene.lights.size())},
         {"shadows", ui_message(scene.shadows ? "limit_with_shadows" : "limit_without_shadows")},
         {"spp", std::to_string(cost.spp)},
         {"limit", byte_size_text(limit)},
         {"enough", fmt::format("{:.0f}", enough)}}));
}

}  // namespace promyk::app
