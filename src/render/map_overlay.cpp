#include "render/map_overlay.hpp"

#include <cstdio>

#include "image/map_legend.hpp"
#include "render/maps.hpp"
#include "trace/messages.hpp"

namespace promyk {

namespace {

std::string hex(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02X%02X%02X", r, g, b);
    return text;
}

}  // namespace

nlohmann::ordered_json map_overlay(MapKind kind, RealType real, const double* stored, std::size_t count,
                                   std::optional<std::pair<double, double>> range, Language language,
                                   std::vector<std::uint8_t>& rgb) {
    const ColourScale scale = range && kind == MapKind::error ? error_scale(range->first, range->second)
                                                              : scalar_map_scale(kind, real, stored, count);
    rgb.resize(3 * count);
    for (std::size_t p = 0; p < count; ++p) {
        const Rgb8 c = scalar_map_colour(kind, scale, stored[p]);
        rgb[3 * p] = c.r, rgb[3 * p + 1] = c.g, rgb[3 * p + 2] = c.b;
    }
    const Legend legend = map_legend(kind, &scale, language);
    nlohmann::ordered_json out;
    out["kind"] = std::string(map_name(kind));
    out["range"] = {scale.low(), scale.high()};
    out["range_given"] = range.has_value() && kind == MapKind::error;
    out["range_text"] = {legend_number(scale.low(), language), legend_number(scale.high(), language)};
    out["range_how"] = kind != MapKind::error ? std::string()
                       : message(language, range ? "lab_range_fixed" : "map_range_of_run");
    out["title"] = legend.bar ? legend.bar->title : std::string();
    nlohmann::ordered_json ramp = nlohmann::ordered_json::array(), ticks = nlohmann::ordered_json::array();
    if (legend.bar) {
        for (const Paint& p : legend.bar->ramp) ramp.push_back(hex(p.r, p.g, p.b));
        for (const LegendTick& tick : legend.bar->ticks) ticks.push_back({{"t", tick.t}, {"text", tick.text}});
    }
    out["ramp"] = ramp;
    out["ticks"] = ticks;
    // The swatches in map_legend's order: the zero case, [branch differs,] non-finite.
    const std::vector<double> marks = kind == MapKind::error
                                          ? std::vector<double>{map_stored_value::zero, map_stored_value::branch_differs,
                                                                map_stored_value::non_finite}
                                          : std::vector<double>{map_stored_value::zero, map_stored_value::non_finite};
    nlohmann::ordered_json swatches = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < legend.swatches.size(); ++k) {
        const Paint& p = legend.swatches[k].colour;
        swatches.push_back({{"name", legend.swatches[k].name},
                            {"hex", hex(p.r, p.g, p.b)},
                            {"stored", k < marks.size() ? marks[k] : map_stored_value::non_finite}});
    }
    out["swatches"] = swatches;
    return out;
}

std::string map_value_text(MapKind kind, double stored, Language language) {
    if (stored > 0) return shown_number(stored, language, 3);
    if (stored == map_stored_value::zero)
        return message(language, kind == MapKind::error ? "map_legend_exact" : "map_legend_none_lost");
    if (stored == map_stored_value::branch_differs) return message(language, "map_legend_branch_differs");
    return message(language, "branch_name_non-finite");
}

}  // namespace promyk
