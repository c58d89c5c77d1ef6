#include "image/map_legend.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "trace/messages.hpp"

namespace promyk {
namespace {

Paint colour(Rgb8 c) { return {c.r, c.g, c.b}; }

std::vector<Paint> ramp() {
    std::vector<Paint> colours;
    for (int k = 0; k <= 255; ++k) colours.push_back(colour(ColourScale::ramp(k / 255.0)));
    return colours;
}

}  // namespace

std::string legend_number(double value, Language language) {
    std::string text = fmt::format("{}", value);
    const auto e = text.find('e');
    if (e != std::string::npos) {
        std::string exponent = text.substr(e + 1);
        const bool negative = !exponent.empty() && exponent[0] == '-';
        if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) exponent.erase(0, 1);
        while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
        text = text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
    }
    return local_number_text(text, language);
}

Legend map_legend(MapKind kind, const ColourScale* scale, Language language) {
    Legend legend;
    if (kind == MapKind::branch) {
        for (int k = 0; k < branch_category_count; ++k) {
            const auto category = static_cast<BranchCategory>(k);
            legend.swatches.push_back({colour(branch_colour(category).rgb), message(language, branch_category_message(category))});
        }
        return legend;
    }
    LegendBar bar;
    bar.ramp = ramp();
    if (kind == MapKind::error) {
        bar.title = message(language, "map_legend_error_title");
        if (!scale) {
            // The widest ends a run's decades can have: 1e-300 and 1e-300.
            bar.ticks = {{0, legend_number(1e-300, language)}, {1, legend_number(1e-300, language)}};
        } else {
            // The ends, and each whole decade between them.
            const double span = std::log10(scale->high() / scale->low());
            bar.ticks.push_back({0, legend_number(scale->low(), language)});
            for (int k = static_cast<int>(std::ceil(std::log10(scale->low()) + 1e-9));
                 k < std::log10(scale->high()) - 1e-9; ++k) {
                const double value = std::strtod(fmt::format("1e{}", k).c_str(), nullptr);
                bar.ticks.push_back({std::log10(value / scale->low()) / span, legend_number(value, language)});
            }
            bar.ticks.push_back({1, legend_number(scale->high(), language)});
        }
        legend.bar = bar;
        legend.swatches.push_back({colour(exact_colour().rgb), message(language, "map_legend_exact")});
        legend.swatches.push_back(
            {colour(branch_differs_colour().rgb), message(language, "map_legend_branch_differs")});
        legend.swatches.push_back(
            {colour(non_finite_error_colour().rgb), message(language, "branch_name_non-finite")});
        return legend;
    }
    // digits-lost: a tick a digit, 0 to the type's digits.
    bar.title = message(language, "map_legend_digits_title");
    const int digits = scale ? static_cast<int>(std::lround(scale->high())) : 35;
    for (int d = 0; d <= digits; ++d)
        bar.ticks.push_back({static_cast<double>(d) / digits, legend_number(d, language)});
    legend.bar = bar;
    legend.swatches.push_back({colour(none_lost_colour().rgb), message(language, "map_legend_none_lost")});
    legend.swatches.push_back({colour(non_finite_error_colour().rgb), message(language, "branch_name_non-finite")});
    return legend;
}

}  // namespace promyk
