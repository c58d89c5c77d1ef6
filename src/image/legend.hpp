// A map's legend (render --legend): a strip as wide as the image, below it,
// with a colour bar (its title, and numbers under it: both ends always, the
// ones between where they fit) and swatches, each a colour square and its
// name, placed left to right and wrapped into rows as the width allows. The
// names carry the meaning; the colours only point at the map. Black text on
// white, in the bitmap font, at a size that grows with the width (1 font
// pixel an image pixel up to 319 pixels wide, 2 up to 479, then 3) and
// shrinks to fit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "image/canvas.hpp"

namespace promyk {

struct LegendSwatch {
    Paint colour;
    std::string name;
};

struct LegendTick {
    double t = 0;  // where on the bar, 0 (left end) to 1 (right end)
    std::string text;
};

struct LegendBar {
    std::string title;
    std::vector<Paint> ramp;  // the bar's colours from t = 0 to t = 1, evenly spaced
    std::vector<LegendTick> ticks;  // in order of t; the first and the last are always shown
};

struct Legend {
    std::optional<LegendBar> bar;
    std::vector<LegendSwatch> swatches;
};

// The narrowest image whose legend fits (at font size 1), and the widest
// piece that decides it (a name, the title, or the bar's end numbers).
struct LegendNeed {
    int width = 0;
    std::string widest;
};
LegendNeed legend_need(const Legend& legend);

// The font size the strip uses at `width`; 0 if it does not fit.
int legend_size(const Legend& legend, int width);

// The strip, `width` wide (std::invalid_argument if the legend does not fit).
// `unknown`, if given, receives the number of code points drawn as boxes.
Canvas draw_legend(const Legend& legend, int width, int channels, int* unknown = nullptr);

}  // namespace promyk
