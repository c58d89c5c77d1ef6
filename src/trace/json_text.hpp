// Small writers for JSON text: strings with escapes, and numbers as the
// shortest text that reads back to the same double (fmt's Dragonbox).
// A non-finite number has no JSON form: it is written as null, and the
// caller adds a "text" field ("inf", "-inf", "nan") beside it.
// Each writes straight into `out` (a full-image trace writes hundreds of
// megabytes through them: no temporary strings, no format string parsed).
#pragma once

#include <cmath>
#include <string>
#include <string_view>

namespace promyk::json_text {

void append_string(std::string& out, std::string_view text);

// Shortest round-trip text of a finite double, or "null".
void append_number(std::string& out, double value);

// An integer in decimal.
void append_integer(std::string& out, long long value);

// A number with one decimal, as fmt's "{:.1f}" writes it; quick for a
// number of tenths (k/10 for a whole k, as digits lost are rounded).
void append_tenths(std::string& out, double value);

// "inf", "-inf" or "nan"; empty for a finite value.
std::string_view non_finite_text(double value);

}  // namespace promyk::json_text
