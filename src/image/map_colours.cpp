#include "image/map_colours.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

namespace promyk {

namespace {

// Okabe & Ito, "Color Universal Design" (2008): eight colours told apart
// with every common colour-vision deficiency.
constexpr Rgb8 rgb(std::uint32_t hex) {
    return {static_cast<std::uint8_t>(hex >> 16), static_cast<std::uint8_t>(hex >> 8), static_cast<std::uint8_t>(hex)};
}

// Indexed by BranchCategory. Miss is the light sky blue of a background,
// dark the black of the article's 0, lit the warm orange, shadowed the deep
// blue; the notes take the two colours that stand out most against these.
const std::array<LegendColour, branch_category_count> branch_colours = {{
    {"miss", "sky blue", "#56B4E9", rgb(0x56B4E9)},
    {"dark", "black", "#000000", rgb(0x000000)},
    {"lit", "orange", "#E69F00", rgb(0xE69F00)},
    {"shadowed", "blue", "#0072B2", rgb(0x0072B2)},
    {"non-finite", "reddish purple", "#CC79A7", rgb(0xCC79A7)},
    {"tangent", "yellow", "#F0E442", rgb(0xF0E442)},
    {"behind the eye", "bluish green", "#009E73", rgb(0x009E73)},
}};

const LegendColour exact_white{"exact", "white", "#FFFFFF", rgb(0xFFFFFF)};
const LegendColour none_lost{"none lost", "white", "#FFFFFF", rgb(0xFFFFFF)};
const LegendColour differs_vermillion{"branch differs", "vermillion", "#D55E00", rgb(0xD55E00)};
const LegendColour non_finite_error{"non-finite", "reddish purple", "#CC79A7", rgb(0xCC79A7)};

// Viridis (matplotlib), at t = 0, 1/8, ..., 1.
constexpr std::array<Rgb8, 9> viridis = {rgb(0x440154), rgb(0x472D7B), rgb(0x3B528B), rgb(0x2C728E), rgb(0x21918C),
                                         rgb(0x28AE80), rgb(0x5EC962), rgb(0xADDC30), rgb(0xFDE725)};

}  // namespace

std::string_view map_name(MapKind kind) {
    switch (kind) {
        case MapKind::error:
            return "error";
        case MapKind::digits_lost:
            return "digits-lost";
        case MapKind::branch:
            break;
    }
    return "branch";
}

std::optional<MapKind> parse_map_name(std::string_view name) {
    for (const MapKind kind : map_kinds)
        if (map_name(kind) == name) return kind;
    return std::nullopt;
}

const char* branch_category_message(BranchCategory category) {
    switch (category) {
        case BranchCategory::miss:
            return "branch_name_miss";
        case BranchCategory::dark:
            return "branch_name_dark";
        case BranchCategory::lit:
            return "branch_name_lit";
        case BranchCategory::shadowed:
            return "branch_name_shadowed";
        case BranchCategory::non_finite:
            return "branch_name_non-finite";
        case BranchCategory::tangent:
            return "note_name_tangent";
        case BranchCategory::behind:
            break;
    }
    return "note_name_behind";
}

const LegendColour& branch_colour(BranchCategory category) {
    return branch_colours[static_cast<std::size_t>(category)];
}

Rgb8 ColourScale::ramp(double t) {
    if (!(t > 0)) return viridis.front();
    if (t >= 1) return viridis.back();
    const double x = t * (viridis.size() - 1);
    const auto k = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(k);
    const Rgb8 a = viridis[k], b = viridis[k + 1];
    auto mix = [f](std::uint8_t p, std::uint8_t q) {
        return static_cast<std::uint8_t>(std::lround(p + f * (static_cast<double>(q) - p)));
    };
    return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

Rgb8 ColourScale::operator()(double value) const {
    const double t = log_ ? std::log10(value / low_) / std::log10(high_ / low_) : (value - low_) / (high_ - low_);
    return ramp(t);
}

ColourScale error_scale(double low, double high) { return ColourScale(low, high, true); }

ColourScale fallback_error_scale() { return error_scale(1e-20, 1); }

ColourScale error_scale_of_run(double smallest, double largest) {
    // 10^k read from its decimal text: the double nearest the decade, as a
    // reader types it (1e-17), not pow's rounding of it; 0 below a double's range.
    auto decade = [](int k) { return std::strtod(fmt::format("1e{}", k).c_str(), nullptr); };
    int low = static_cast<int>(std::floor(std::log10(smallest)));
    int high = static_cast<int>(std::ceil(std::log10(largest)));
    while (low > -330 && decade(low) > smallest) --low;  // log10 may round across an edge
    while (high < 308 && decade(high) < largest) ++high;
    if (high <= low) high = low + 1;
    // Below 1e-323 the decade is the smallest double there is.
    const double low_value = decade(low) > 0 ? decade(low) : std::numeric_limits<double>::denorm_min();
    return error_scale(low_value, decade(high));
}

ColourScale digits_lost_scale(RealType real) {
    const int digits = real == RealType::float_         ? 8
                       : real == RealType::long_double ? 20
                       : real == RealType::quad_       ? 35
                                                       : 16;
    return ColourScale(0, digits, false, digits);
}
const LegendColour& none_lost_colour() { return none_lost; }
const LegendColour& exact_colour() { return exact_white; }
const LegendColour& branch_differs_colour() { return differs_vermillion; }
const LegendColour& non_finite_error_colour() { return non_finite_error; }

}  // namespace promyk
