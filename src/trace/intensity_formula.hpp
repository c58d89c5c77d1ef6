// The formula of I_P a scene's effects call for: the article's Lambert term,
// or a combination of a sum over lights, shadows, the material's weights
// (k_a, k_d), Phong's highlight and colour. One formula per effect set, in
// lessons/vocabulary.json ("intensity_formulas"), used by the trace's steps,
// branch line and footer, the lessons, the answers report and the page.
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"
#include "trace/keys.hpp"
#include "trace/number_text.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

struct PixelTrace;

struct IntensityFormula {
    std::string effects;  // lambert, or flags joined by '+': lights+shadows+phong+colour
    std::string formula;  // plain Unicode text
    std::string formula_latex;
    std::string pl, en;  // what its letters mean, when the article did not say (may be empty)
    // One light's contribution in that effect set; empty: the vocabulary's
    // own (the full one, with colour).
    std::string contribution, contribution_latex;
};

// The effect set of a scene: the flags it uses, in this order, joined by
// '+': lights (more than one), shadows, phong (a material with k_s > 0) or
// else weights (an object's material with k_a > 0 or k_d != 1), colour (a
// colour reaches a pixel); "lambert" when it uses none (the article's).
std::string effect_set(const Scene& scene);

// The same, for the scene a trace's header carries (parsed once a scene);
// lambert when the trace carries none.
std::string effect_set(const PixelTrace& trace);

// The vocabulary's formula for an effect set (never null: lambert's for an unknown set).
const IntensityFormula& intensity_formula(std::string_view effects);

// The formula's text, with its note in the language after a semicolon.
std::string intensity_formula_text(std::string_view effects, Language language);

// A step's formula as shown in a scene of those effects: I_P's and a
// light's contribution's are the effect set's; every other key's is the
// vocabulary entry's own (empty without an entry).
std::string step_formula(const VocabularyEntry* entry, std::string_view key, std::string_view effects, bool latex = false);

// The vocabulary's words for a branch in a scene of those effects: its
// "{formula}" is the effect set's formula of I_P.
std::string branch_about(const Vocabulary& vocabulary, Branch branch, std::string_view effects, Language language);

// The branch as every output names it: its short name, then what it means,
// "lit side — the point faces a light (D > 0): I·D / (r·√|K|²)". The
// vocabulary's words say why (they never repeat the name); the name alone
// for a branch the vocabulary lacks.
std::string branch_named(const Vocabulary& vocabulary, Branch branch, std::string_view effects, Language language);

}  // namespace promyk
