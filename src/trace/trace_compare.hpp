// `promyk trace --compare float,double,quad`: one pixel traced in several real
// types, printed step by step side by side, each value marked where its
// digits stop agreeing with the most precise type's value.
#pragma once

#include <string>
#include <vector>

#include "trace/number_text.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

// How many significant decimal digits of a value agree with a reference:
// floor(-log10 |value - reference| / |reference|), from 0; -1 when the two
// are equal. Both are exact texts in their real types ("float", "double",
// "long-double", "quad"): a float's shortest text "6.4" stands for
// 6.400000095367431640625, and that is the value compared.
int agreeing_digits(const std::string& value, const std::string& value_type, const std::string& reference,
                    const std::string& reference_type);

// `value` with a '|' after its first `digits` significant digits (nothing
// when every digit agrees): "4.55781|17".
std::string mark_digits(const std::string& value, int digits);

// The traces (one per type, least precise first; the last is the reference)
// as a text table in `language`.
std::string format_comparison(const std::vector<PixelTrace>& traces, const Vocabulary& vocabulary,
                              Language language);

}  // namespace promyk
