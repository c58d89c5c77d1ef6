// Each step's formula with the pixel's numbers put in: the right-hand side of
// the vocabulary's formula (formula_latex) with every quantity it names
// replaced by that quantity's shown value, as TeX. The web page typesets it
// under the formula (promyk_view's "numbers_tex"); one implementation, so the
// page has no second guess in JavaScript.
//
// A symbol means the value in scope at that step: the pane's i, j, w; the
// scene's given values (inside an object's or a light's group, that object's
// or light's; after the objects, the hit object's); the steps already done.
#pragma once
#include <string>
#include <vector>

#include "trace/messages.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

// One TeX text per step of `trace` (in its order): the formula's right-hand
// side with numbers put in, or "" when the step has no formula, nothing to
// put in, or no single number per symbol (a minimum over a set, a sum over
// samples). Numbers are shown with `digits` significant digits in
// `language` (trace/number_text.hpp), each as \text{...}. The header's given
// values must be filled (trace_header) for the scene's quantities to appear.
std::vector<std::string> formulas_with_numbers(const PixelTrace& trace, const Vocabulary& vocabulary,
                                               Language language, int digits);

// A shown number or vector as TeX: \text{...} with TeX's specials escaped,
// in \left( \right) unless it is a plain unsigned number or bracketed.
std::string tex_number(const std::string& shown);

}  // namespace promyk
