// The glyphs, drawn for promyk (no font data copied): each a code point and
// its rows 1-7 ('#' ink, '.' paper), optionally rows 8-9 below the baseline.
// The Polish letters are their base letter with a mark added (acute, dot,
// ogonek), except ł and Ł, whose stroke crosses the stem.
#include "image/bitmap_font.hpp"

#include <array>
#include <cstdint>
#include <map>

namespace promyk {
namespace {

using Glyph = std::array<std::uint8_t, font::glyph_height>;  // a row a byte, bit 4 leftmost

struct Drawn {
    char32_t code;
    const char* body;   // rows 1-7: seven groups of five, space-separated
    const char* below;  // rows 8-9, or ""
};

const Drawn drawn[] = {
    {U' ', "..... ..... ..... ..... ..... ..... .....", ""},
    {U'0', ".###. #...# #..## #.#.# ##..# #...# .###.", ""},
    {U'1', "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###.", ""},
    {U'2', ".###. #...# ....# ...#. ..#.. .#... #####", ""},
    {U'3', "##### ...#. ..#.. ...#. ....# #...# .###.", ""},
    {U'4', "...#. ..##. .#.#. #..#. ##### ...#. ...#.", ""},
    {U'5', "##### #.... ####. ....# ....# #...# .###.", ""},
    {U'6', "..##. .#... #.... ####. #...# #...# .###.", ""},
    {U'7', "##### ....# ...#. ..#.. .#... .#... .#...", ""},
    {U'8', ".###. #...# #...# .###. #...# #...# .###.", ""},
    {U'9', ".###. #...# #...# .#### ....# ...#. .##..", ""},
    {U'A', ".###. #...# #...# ##### #...# #...# #...#", ""},
    {U'B', "####. #...# #...# ####. #...# #...# ####.", ""},
    {U'C', ".###. #...# #.... #.... #.... #...# .###.", ""},
    {U'D', "####. #...# #...# #...# #...# #...# ####.", ""},
    {U'E', "##### #.... #.... ####. #.... #.... #####", ""},
    {U'F', "##### #.... #.... ####. #.... #.... #....", ""},
    {U'G', ".###. #...# #.... #.### #...# #...# .####", ""},
    {U'H', "#...# #...# #...# ##### #...# #...# #...#", ""},
    {U'I', ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###.", ""},
    {U'J', "..### ...#. ...#. ...#. ...#. #..#. .##..", ""},
    {U'K', "#...# #..#. #.#.. ##... #.#.. #..#. #...#", ""},
    {U'L', "#.... #.... #.... #.... #.... #.... #####", ""},
    {U'M', "#...# ##.## #.#.# #.#.# #...# #...# #...#", ""},
    {U'N', "#...# #...# ##..# #.#.# #..## #...# #...#", ""},
    {U'O', ".###. #...# #...# #...# #...# #...# .###.", ""},
    {U'P', "####. #...# #...# ####. #.... #.... #....", ""},
    {U'Q', ".###. #...# #...# #...# #.#.# #..#. .##.#", ""},
    {U'R', "####. #...# #...# ####. #.#.. #..#. #...#", ""},
    {U'S', ".#### #.... #.... .###. ....# ....# ####.", ""},
    {U'T', "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#..", ""},
    {U'U', "#...# #...# #...# #...# #...# #...# .###.", ""},
    {U'V', "#...# #...# #...# #...# #...# .#.#. ..#..", ""},
    {U'W', "#...# #...# #...# #.#.# #.#.# #.#.# .#.#.", ""},
    {U'X', "#...# #...# .#.#. ..#.. .#.#. #...# #...#", ""},
    {U'Y', "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#..", ""},
    {U'Z', "##### ....# ...#. ..#.. .#... #.... #####", ""},
    {U'a', "..... ..... .###. ....# .#### #...# .####", ""},
    {U'b', "#.... #.... ####. #...# #...# #...# ####.", ""},
    {U'c', "..... ..... .#### #.... #.... #.... .####", ""},
    {U'd', "....# ....# .#### #...# #...# #...# .####", ""},
    {U'e', "..... ..... .###. #...# ##### #.... .###.", ""},
    {U'f', "..##. .#..# .#... ###.. .#... .#... .#...", ""},
    {U'g', "..... ..... .#### #...# #...# #...# .####", "....# .###."},
    {U'h', "#.... #.... #.##. ##..# #...# #...# #...#", ""},
    {U'i', "..#.. ..... .##.. ..#.. ..#.. ..#.. .###.", ""},
    {U'j', "...#. ..... ..##. ...#. ...#. ...#. ...#.", "#..#. .##.."},
    {U'k', "#.... #.... #..#. #.#.. ##... #.#.. #..#.", ""},
    {U'l', ".##.. ..#.. ..#.. ..#.. ..#.. ..#.. .###.", ""},
    {U'm', "..... ..... ##.#. #.#.# #.#.# #.#.# #.#.#", ""},
    {U'n', "..... ..... #.##. ##..# #...# #...# #...#", ""},
    {U'o', "..... ..... .###. #...# #...# #...# .###.", ""},
    {U'p', "..... ..... ####. #...# #...# #...# ####.", "#.... #...."},
    {U'q', "..... ..... .#### #...# #...# #...# .####", "....# ....#"},
    {U'r', "..... ..... #.##. ##..# #.... #.... #....", ""},
    {U's', "..... ..... .#### #.... .###. ....# ####.", ""},
    {U't', ".#... .#... ####. .#... .#... .#..# ..##.", ""},
    {U'u', "..... ..... #...# #...# #...# #..## .##.#", ""},
    {U'v', "..... ..... #...# #...# #...# .#.#. ..#..", ""},
    {U'w', "..... ..... #...# #...# #.#.# #.#.# .#.#.", ""},
    {U'x', "..... ..... #...# .#.#. ..#.. .#.#. #...#", ""},
    {U'y', "..... ..... #...# #...# #...# #...# .####", "....# .###."},
    {U'z', "..... ..... ##### ...#. ..#.. .#... #####", ""},
    {U'ł', ".##.. ..#.. ..##. .##.. ..#.. ..#.. .###.", ""},
    {U'Ł', ".#... .#... .#.#. .##.. ##... .#... .####", ""},
    {U'.', "..... ..... ..... ..... ..... ..... ..#..", ""},
    {U',', "..... ..... ..... ..... ..... ..#.. ..#..", ".#... ....."},
    {U':', "..... ..... ..#.. ..... ..... ..#.. .....", ""},
    {U';', "..... ..... ..#.. ..... ..... ..#.. ..#..", ".#... ....."},
    {U'-', "..... ..... ..... .###. ..... ..... .....", ""},
    {U'\u2212', "..... ..... ..... ##### ..... ..... .....", ""},  // minus sign
    {U'+', "..... ..#.. ..#.. ##### ..#.. ..#.. .....", ""},
    {U'=', "..... ..... ##### ..... ##### ..... .....", ""},
    {U'<', "..... ...#. ..#.. .#... ..#.. ...#. .....", ""},
    {U'>', "..... .#... ..#.. ...#. ..#.. .#... .....", ""},
    {U'\u2264', "...#. ..#.. .#... ..#.. ...#. ..... #####", ""},  // ≤
    {U'\u2265', ".#... ..#.. ...#. ..#.. .#... ..... #####", ""},  // ≥
    {U'\u00D7', "..... #...# .#.#. ..#.. .#.#. #...# .....", ""},  // ×
    {U'\u00B7', "..... ..... ..... ..#.. ..... ..... .....", ""},  // ·
    {U'\u2026', "..... ..... ..... ..... ..... ..... #.#.#", ""},  // …
    {U'(', "...#. ..#.. .#... .#... .#... ..#.. ...#.", ""},
    {U')', ".#... ..#.. ...#. ...#. ...#. ..#.. .#...", ""},
    {U'[', ".###. .#... .#... .#... .#... .#... .###.", ""},
    {U']', ".###. ...#. ...#. ...#. ...#. ...#. .###.", ""},
    {U'/', "....# ....# ...#. ..#.. .#... #.... #....", ""},
    {U'|', "..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#..", "..#.. ....."},
    {U'_', "..... ..... ..... ..... ..... ..... .....", "##### ....."},
    {U'%', "##..# ##..# ...#. ..#.. .#... #..## #..##", ""},
    {U'\'', "..#.. ..#.. ..... ..... ..... ..... .....", ""},
    {U'"', ".#.#. .#.#. ..... ..... ..... ..... .....", ""},
    {U'\u201E', "..... ..... ..... ..... ..... .#.#. .#.#.", "#.#.. ....."},  // „
    {U'\u201D', ".#.#. .#.#. #.#.. ..... ..... ..... .....", ""},  // ”
    {U'!', "..#.. ..#.. ..#.. ..#.. ..#.. ..... ..#..", ""},
    {U'?', ".###. #...# ...#. ..#.. ..#.. ..... ..#..", ""},
};

// A letter with a mark: the base letter's rows, the mark's rows over them.
enum class Mark { acute_small, dot_small, acute_capital, dot_capital, ogonek };

struct Marked {
    char32_t code;
    char32_t base;
    Mark mark;
};

const Marked marked[] = {
    {U'ą', U'a', Mark::ogonek},        {U'ć', U'c', Mark::acute_small},   {U'ę', U'e', Mark::ogonek},
    {U'ń', U'n', Mark::acute_small},   {U'ó', U'o', Mark::acute_small},   {U'ś', U's', Mark::acute_small},
    {U'ź', U'z', Mark::acute_small},   {U'ż', U'z', Mark::dot_small},     {U'Ą', U'A', Mark::ogonek},
    {U'Ć', U'C', Mark::acute_capital}, {U'Ę', U'E', Mark::ogonek},        {U'Ń', U'N', Mark::acute_capital},
    {U'Ó', U'O', Mark::acute_capital}, {U'Ś', U'S', Mark::acute_capital}, {U'Ź', U'Z', Mark::acute_capital},
    {U'Ż', U'Z', Mark::dot_capital},
};

std::uint8_t row_bits(const char* five) {
    std::uint8_t bits = 0;
    for (int k = 0; k < font::glyph_width; ++k) bits = static_cast<std::uint8_t>(bits << 1 | (five[k] == '#'));
    return bits;
}

// Fills rows first, first + 1, ... from "xxxxx xxxxx ...".
void read_rows(Glyph& glyph, int first, const char* groups) {
    for (int row = first; *groups; ++row) {
        glyph[static_cast<std::size_t>(row)] = row_bits(groups);
        groups += font::glyph_width;
        if (*groups == ' ') ++groups;
    }
}

std::map<char32_t, Glyph> make_glyphs() {
    std::map<char32_t, Glyph> glyphs;
    for (const Drawn& d : drawn) {
        Glyph glyph{};
        read_rows(glyph, font::ink_top, d.body);
        read_rows(glyph, font::ink_bottom + 1, d.below);
        glyphs[d.code] = glyph;
    }
    for (const Marked& m : marked) {
        Glyph glyph = glyphs.at(m.base);
        switch (m.mark) {
            case Mark::acute_small:  // rows 1-2, above the x-height
                glyph[1] |= row_bits("...#."), glyph[2] |= row_bits("..#..");
                break;
            case Mark::dot_small:
                glyph[1] |= row_bits("..#..");
                break;
            case Mark::acute_capital:  // row 0, above the capital
                glyph[0] |= row_bits("..##.");
                break;
            case Mark::dot_capital:
                glyph[0] |= row_bits("..#..");
                break;
            case Mark::ogonek:  // hangs from the right of the bowl or the stem's foot
                glyph[8] |= row_bits("...#."), glyph[9] |= row_bits("...##");
                break;
        }
        glyphs[m.code] = glyph;
    }
    return glyphs;
}

const std::map<char32_t, Glyph>& glyphs() {
    static const std::map<char32_t, Glyph> table = make_glyphs();
    return table;
}

// What a code point without a glyph draws: a hollow box the height of a capital.
Glyph unknown_box() {
    Glyph glyph{};
    read_rows(glyph, font::ink_top, "##### #...# #...# #...# #...# #...# #####");
    return glyph;
}

}  // namespace

std::u32string utf8_code_points(std::string_view text) {
    std::u32string out;
    std::size_t k = 0;
    while (k < text.size()) {
        const auto c = static_cast<unsigned char>(text[k]);
        int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
        char32_t code = extra == 0 ? c : extra == 1 ? c & 0x1F : extra == 2 ? c & 0x0F : c & 0x07;
        bool ok = extra >= 0 && k + static_cast<std::size_t>(extra) < text.size() + (extra == 0 ? 1 : 0);
        for (int e = 1; ok && e <= extra; ++e) {
            const auto next = static_cast<unsigned char>(text[k + static_cast<std::size_t>(e)]);
            if ((next >> 6) != 0x2) ok = false;
            code = code << 6 | (next & 0x3F);
        }
        if (!ok) {
            out.push_back(U'\uFFFD');
            ++k;
            continue;
        }
        out.push_back(code);
        k += 1 + static_cast<std::size_t>(extra);
    }
    return out;
}

bool has_glyph(char32_t code_point) { return glyphs().count(code_point) > 0; }

int text_width(std::string_view text, int size) {
    const auto count = static_cast<int>(utf8_code_points(text).size());
    return count == 0 ? 0 : (count * font::advance - (font::advance - font::glyph_width)) * size;
}

int draw_text(Canvas& canvas, int x, int y, std::string_view text, int size, Paint ink) {
    static const Glyph box = unknown_box();
    int unknown = 0;
    for (const char32_t code : utf8_code_points(text)) {
        const auto found = glyphs().find(code);
        const Glyph& glyph = found == glyphs().end() ? box : found->second;
        unknown += found == glyphs().end();
        for (int row = 0; row < font::glyph_height; ++row)
            for (int col = 0; col < font::glyph_width; ++col)
                if (glyph[static_cast<std::size_t>(row)] >> (font::glyph_width - 1 - col) & 1)
                    canvas.fill(x + col * size, y + row * size, size, size, ink);
        x += font::advance * size;
    }
    return unknown;
}

}  // namespace promyk
