// The error and digits-lost maps as the web page overlays them on its image
// (issue 17, the precision lab): each pixel's stored value (render/maps.hpp,
// map_stored_value) coloured by the same definition `render --map` uses, and
// the map's legend (image/map_legend.hpp) as data for the page to draw. One
// definition for the CLI's PNG, `promyk export` and the page's wasm.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/map_colours.hpp"
#include "math/real.hpp"
#include "trace/number_text.hpp"

namespace promyk {

// Colours `count` stored values of a `kind` map computed in `real` into
// `rgb` (3 bytes a pixel, as `render --map` draws them: with `range`, as
// `--range LO,HI` does, else the run's own range) and gives what the page
// needs to draw its legend and say its range:
//   {"kind", "range": [lo, hi], "range_given": bool,
//    "range_text": ["1e−20", "1e−13"], "range_how": "<map_range_of_run|given>",
//    "title", "ramp": ["#440154", ...], "ticks": [{"t", "text"}],
//    "swatches": [{"name", "hex", "stored"}]}   // stored: the value a swatch marks
nlohmann::ordered_json map_overlay(MapKind kind, RealType real, const double* stored, std::size_t count,
                                   std::optional<std::pair<double, double>> range, Language language,
                                   std::vector<std::uint8_t>& rgb);

// A stored value as the page's hover says it: the number (3 significant
// digits, the project's formatter) or the name of its special case.
std::string map_value_text(MapKind kind, double stored, Language language);

}  // namespace promyk
