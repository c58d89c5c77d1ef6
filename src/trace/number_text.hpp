// Numbers and vectors as a reader of a given language writes them. English:
// 0.25, (0.25, -0.75, 2). Polish: a decimal comma, a true minus sign and
// semicolons between components, 0,25, (0,25; −0,75; 2). Points stand in
// parentheses and vectors in square brackets, as in the article.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "math/decimal.hpp"
#include "math/real.hpp"
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

// What stands between a point's coordinates: with the Polish decimal comma,
// a semicolon.
inline const char* coordinate_separator(Language language) { return language == Language::pl ? "; " : ", "; }

// A point of the scene as the trace's "given" line writes it: the shortest
// texts that read back, "(1.5, 1, 1)", in Polish "(1,5; 1; 1)".
std::string point_text(const Vec3d& point, Language language);

// The significant digits this run shows (--digits N), if the command line
// chose them; otherwise each output keeps its own default (trace: every
// digit; lessons, worksheets and the page: 4).
std::optional<int> chosen_digits();
void set_chosen_digits(int digits);

// The digits an output shows: --digits when given, else `default_digits`
// (0: every digit).
int shown_digits(int default_digits);

// A number as people read it: rounded to `digits` significant digits, halves
// away from zero (as a pupil rounds: 0.125 to 2 digits is 0.13); a rounded
// value keeps its trailing zeros (4.2698 is 4.270), a value whose shortest
// text is that short drops them (0.5, not 0.5000; 3.2, not 3.200); in the style of printf's %g (an exponent below 1e-4 or from
// 10^digits up: 1.235e+04; but a short whole value stays whole below 10^15:
// 10000), written the language's way. `digits` 0 shows
// every digit: the shortest text that reads back to the same double. Zero
// is "0" whatever its sign; "nan", "inf", "-inf" as number_text.
std::string shown_number(double value, Language language, int digits);

// The same for a value of another real type given as its exact shortest
// text in that type (a trace's real_text): rounded from the type's own
// binary value, not from the double beside it.
std::string shown_real_text(const std::string& text, RealType type, Language language, int digits);

// A number's text ("-1.5e-3") written the language's way: the minus sign
// U+2212 in both languages, and in Polish a decimal comma ("−1,5e−3";
// English "−1.5e−3").
std::string local_number_text(std::string_view text, Language language);

// The number as text in a language's style (decimal comma and '−' in Polish).
std::string typed_number_text(const TypedNumber& number, Language language);

// A step's value as shown_number shows its numbers (`digits` 0: every digit).
std::string shown_value_text(const StepValue& value, const std::string& kind, Language language, int digits);

// A step's value; `kind` is the vocabulary's ("scalar", "point", "vector").
std::string value_text(const StepValue& value, const std::string& kind, Language language, int decimals = -1);

}  // namespace promyk
