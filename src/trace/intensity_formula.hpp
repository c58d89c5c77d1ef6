// The formula of I_P a scene's effects call for: the article's Lambert term;
// a sum over lights; with shadows; with Phong's highlight and ambient light;
// with colour. One formula per effect set, in lessons/vocabulary.json
// ("intensity_formulas"), used by the trace's footer and the lessons.
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"
#include "trace/number_text.hpp"

namespace promyk {

struct PixelTrace;

struct IntensityFormula {
    std::string effects;  // lambert, lights, shadows, phong, colour
    std::string formula;  // plain Unicode text
    std::string formula_latex;
    std::string pl, en;  // what its letters mean, when the article did not say (may be empty)
    // One light's contribution in that effect set; empty: the vocabulary's
    // own (the full one, with colour).
    std::string contribution, contribution_latex;
};

// The effect set of a scene: colour when a colour reaches a pixel, else
// phong when a material has a highlight or ambient light, else shadows when
// the scene casts them, else lights with more than one light, else lambert.
std::string effect_set(const Scene& scene);

// The same, for the scene a trace's header carries (parsed once a scene);
// lambert when the trace carries none.
std::string effect_set(const PixelTrace& trace);

// The vocabulary's formula for an effect set (never null: lambert's for an unknown set).
const IntensityFormula& intensity_formula(std::string_view effects);

// The formula's text, with its note in the language after a semicolon.
std::string intensity_formula_text(std::string_view effects, Language language);

}  // namespace promyk
