// promyk's own pixel font, for labels and legends drawn into images without
// a font library: 5 × 10 glyphs (row 0 for a capital's accent, rows 1-7 the
// capitals and digits, baseline after row 7, rows 8-9 the descenders) on a
// 6-pixel advance, drawn at an integer size (each font pixel size × size
// image pixels). Digits, Latin letters, the Polish letters and the
// punctuation promyk's labels use. Text is UTF-8, one glyph a code point; a
// code point without a glyph (or a byte that is not UTF-8) draws as a hollow
// box, so a missing glyph is seen, and is counted.
#pragma once

#include <string>
#include <string_view>

#include "image/canvas.hpp"

namespace promyk {

namespace font {
constexpr int glyph_width = 5;
constexpr int glyph_height = 10;
constexpr int advance = 6;       // glyph and a column of space
constexpr int line_height = 11;  // glyph and a row of space
constexpr int ink_top = 1;       // the first row of a capital or a digit
constexpr int ink_bottom = 7;    // the last (the baseline row)
}  // namespace font

// The code points of `text`; each ill-formed byte becomes U+FFFD.
std::u32string utf8_code_points(std::string_view text);

bool has_glyph(char32_t code_point);

// The width in pixels `text` takes at `size`: advances, less the space after the last glyph.
int text_width(std::string_view text, int size);

// Draws `text` with its glyphs' top-left corner at (x, y); returns how many
// code points had no glyph (drawn as boxes).
int draw_text(Canvas& canvas, int x, int y, std::string_view text, int size, Paint ink);

}  // namespace promyk
