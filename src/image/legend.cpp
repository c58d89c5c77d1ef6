#include "image/legend.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/bitmap_font.hpp"

namespace promyk {
namespace {

constexpr Paint legend_ink = Paint::grey(0);
constexpr Paint legend_paper = Paint::grey(255);

int cap(int s) { return (font::ink_bottom - font::ink_top + 1) * s; }
int pad(int s) { return 2 * s; }
int swatch_width(const LegendSwatch& swatch, int s) { return cap(s) + 3 * s + text_width(swatch.name, s); }
int entry_gap(int s) { return 6 * s; }
int bar_height(int s) { return 6 * s; }
int line(int s) { return font::line_height * s; }

// The width every piece needs at size s (without the pads), and which piece.
LegendNeed need_at(const Legend& legend, int s) {
    LegendNeed need;
    auto consider = [&](int width, const std::string& what) {
        if (width > need.width) need.width = width, need.widest = what;
    };
    if (legend.bar) {
        consider(text_width(legend.bar->title, s), legend.bar->title);
        if (!legend.bar->ticks.empty()) {
            const LegendTick& first = legend.bar->ticks.front();
            const LegendTick& last = legend.bar->ticks.back();
            if (legend.bar->ticks.size() == 1)
                consider(text_width(first.text, s), first.text);
            else
                consider(text_width(first.text, s) + 2 * s + text_width(last.text, s), first.text + " … " + last.text);
        }
    }
    for (const LegendSwatch& swatch : legend.swatches) consider(swatch_width(swatch, s), swatch.name);
    need.width += 2 * pad(s);
    return need;
}

// Lays the legend out at size s in `width`; draws it if `canvas` is given.
// Returns the strip's height.
int lay_out(const Legend& legend, int s, int width, Canvas* canvas, int* unknown) {
    int missing = 0;
    auto text = [&](int x, int y, const std::string& t) {
        if (canvas) missing += draw_text(*canvas, x, y, t, s, legend_ink);
    };
    const int left = pad(s), right = width - pad(s);
    int y = pad(s);
    if (legend.bar) {
        const LegendBar& bar = *legend.bar;
        text(left, y - font::ink_top * s, bar.title);
        y += line(s);
        const int bar_width = right - left;
        if (canvas && !bar.ramp.empty()) {
            for (int x = 0; x < bar_width; ++x) {
                const double t = (x + 0.5) / bar_width;
                const auto k = static_cast<std::size_t>(std::lround(t * static_cast<double>(bar.ramp.size() - 1)));
                canvas->fill(left + x, y, 1, bar_height(s), bar.ramp[k]);
            }
        }
        y += bar_height(s) + s;
        // The ends flush with the bar's ends; a number between where it has room.
        int taken_right = left - 2 * s;
        const int last_left = bar.ticks.empty() ? right : right - text_width(bar.ticks.back().text, s);
        for (std::size_t k = 0; k < bar.ticks.size(); ++k) {
            const LegendTick& tick = bar.ticks[k];
            const int w = text_width(tick.text, s);
            int x = left + static_cast<int>(std::lround(tick.t * bar_width)) - w / 2;
            if (k == 0) x = left;
            if (k + 1 == bar.ticks.size() && k > 0) x = right - w;
            const bool end = k == 0 || k + 1 == bar.ticks.size();
            if (!end && (x < taken_right + 2 * s || x + w + 2 * s > last_left)) continue;
            if (canvas) {
                // A tick mark from the bar down to the number's place.
                const int mark = std::clamp(left + static_cast<int>(std::lround(tick.t * bar_width)), left, right - 1);
                canvas->fill(mark, y - s, 1, s, legend_ink);
            }
            text(x, y, tick.text);
            taken_right = x + w;
        }
        y += line(s) + s;
    }
    int x = left;
    bool row_used = false;
    for (const LegendSwatch& swatch : legend.swatches) {
        const int w = swatch_width(swatch, s);
        if (row_used && x + w > right) {
            x = left;
            y += line(s);
        }
        if (canvas) {
            // The colour square with a thin black border, so white shows on white.
            canvas->fill(x, y, cap(s), cap(s), legend_ink);
            canvas->fill(x + 1, y + 1, cap(s) - 2, cap(s) - 2, swatch.colour);
        }
        text(x + cap(s) + 3 * s, y - font::ink_top * s, swatch.name);
        x += w + entry_gap(s);
        row_used = true;
    }
    if (row_used) y += line(s);
    y += pad(s) - s;
    if (unknown) *unknown = missing;
    return y;
}

}  // namespace

LegendNeed legend_need(const Legend& legend) { return need_at(legend, 1); }

int legend_size(const Legend& legend, int width) {
    for (int s = std::clamp(width / 160, 1, 3); s >= 1; --s)
        if (need_at(legend, s).width <= width) return s;
    return 0;
}

Canvas draw_legend(const Legend& legend, int width, int channels, int* unknown) {
    const int s = legend_size(legend, width);
    if (s == 0) throw std::invalid_argument("legend: the image is too narrow for its legend");
    Canvas canvas(width, lay_out(legend, s, width, nullptr, nullptr), channels, legend_paper);
    lay_out(legend, s, width, &canvas, unknown);
    return canvas;
}

}  // namespace promyk
