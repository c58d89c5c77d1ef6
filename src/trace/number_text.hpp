// Numbers and vectors as a reader of a given language writes them. English:
// 0.25, (0.25, -0.75, 2). Polish: a decimal comma, a true minus sign and
// semicolons between components, 0,25, (0,25; −0,75; 2). Points stand in
// parentheses and vectors in square brackets, as in the article.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "trace/recorder.hpp"

namespace promyk {

enum class Language { pl, en };

// "pl" or "en"; nothing for anything else.
std::optional<Language> parse_language(std::string_view text);

// Polish when LANG (or LC_ALL, LC_MESSAGES before it) starts with "pl", else English.
Language language_from_environment();

std::string_view language_code(Language language);

// The shortest decimal that reads back to the same double (decimals < 0), or
// the value rounded to `decimals` digits after the point; "nan", "inf", "-inf"
// for non-finite values.
std::string number_text(double value, Language language, int decimals = -1);

// A number's text ("-1.5e-3") written the language's way: in Polish a
// decimal comma and the minus sign U+2212 ("−1,5e−3"); in English as it is.
std::string local_number_text(std::string_view text, Language language);

// A step's value; `kind` is the vocabulary's ("scalar", "point", "vector").
std::string value_text(const StepValue& value, const std::string& kind, Language language, int decimals = -1);

}  // namespace promyk
