// The legend of a map (render --map ... --legend), in the run's language:
// the branch map's seven categories by name (lessons/messages_words.json);
// the error and digits-lost maps' colour bar with its numbers and their
// special colours (lessons/messages_maps.json).
#pragma once

#include <string>

#include "image/legend.hpp"
#include "image/map_colours.hpp"
#include "trace/number_text.hpp"

namespace promyk {

// `scale`: the scalar map's scale, or nullptr before a deferred error map
// knows it (the bar's numbers are then the widest a run's decades can be,
// for legend_need).
Legend map_legend(MapKind kind, const ColourScale* scale, Language language);

// A scale's end or step as the legend writes it: the shortest text that
// reads back to it, without an exponent's leading zeros (1e-16, 2.5e-7,
// 0.001), in Polish with a decimal comma and a minus sign (1e−16).
std::string legend_number(double value, Language language);

}  // namespace promyk
