// printable(): text from outside made safe for a terminal.

#include <cstdint>
#include <iterator>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "terminal_control.hpp"

#include "util/printable.hpp"

namespace {

using promyk::printable;

// The UTF-8 bytes of one code point (no validity checks: tests build invalid
// forms on purpose elsewhere).
std::string utf8(std::uint32_t code) {
    std::string out;
    if (code < 0x80u) {
        out += static_cast<char>(code);
    } else if (code < 0x800u) {
        out += static_cast<char>(0xC0u | (code >> 6));
        out += static_cast<char>(0x80u | (code & 0x3Fu));
    } else if (code < 0x10000u) {
        out += static_cast<char>(0xE0u | (code >> 12));
        out += static_cast<char>(0x80u | ((code >> 6) & 0x3Fu));
        out += static_cast<char>(0x80u | (code & 0x3Fu));
    } else {
        out += static_cast<char>(0xF0u | (code >> 18));
        out += static_cast<char>(0x80u | ((code >> 12) & 0x3Fu));
        out += static_cast<char>(0x80u | ((code >> 6) & 0x3Fu));
        out += static_cast<char>(0x80u | (code & 0x3Fu));
    }
    return out;
}

using promyk::testing::has_terminal_control;

}  // namespace

TEST_CASE("printable keeps ordinary text, backslashes and Polish letters", "[printable]") {
    CHECK(printable("") == "");
    CHECK(printable("article.json: /spheres/0/r") == "article.json: /spheres/0/r");
    CHECK(printable("Śledzenie promieni: zażółć gęślą jaźń") == "Śledzenie promieni: zażółć gęślą jaźń");
    CHECK(printable("|S|² − r² <= 0") == "|S|² − r² <= 0");
    CHECK(printable("a\\b \\n \\u001b \\x41") == "a\\b \\n \\u001b \\x41");
    CHECK(printable("'\"~/{}[]") == "'\"~/{}[]");
    CHECK(printable("☀ " + utf8(0x1F600) + " " + utf8(0x10FFFF)) == "☀ " + utf8(0x1F600) + " " + utf8(0x10FFFF));
    CHECK(printable(utf8(0xA0) + utf8(0xFFFD)) == utf8(0xA0) + utf8(0xFFFD));  // no-break space, replacement
}

TEST_CASE("printable escapes C0 controls, DEL and C1 controls", "[printable]") {
    CHECK(printable("two\nlines") == "two\\nlines");
    CHECK(printable("a\tb\rc") == "a\\tb\\rc");
    CHECK(printable("\x1b[31mEVIL\x1b[0m") == "\\u001b[31mEVIL\\u001b[0m");
    CHECK(printable(std::string("nul\0here", 8)) == "nul\\u0000here");
    CHECK(printable("\x07\x08\x0b\x0c\x1f") == "\\u0007\\u0008\\u000b\\u000c\\u001f");
    CHECK(printable("del\x7f") == "del\\u007f");
    CHECK(printable(utf8(0x80) + utf8(0x85) + utf8(0x9B) + utf8(0x9F)) == "\\u0080\\u0085\\u009b\\u009f");
    for (std::uint32_t code = 0; code < 0x20u; ++code) {
        INFO("U+" << code);
        CHECK(!has_terminal_control(printable(utf8(code))));
    }
    for (std::uint32_t code = 0x7Fu; code <= 0x9Fu; ++code) {
        INFO("U+" << code);
        CHECK(printable(utf8(code)).substr(0, 2) == "\\u");
    }
}

TEST_CASE("printable escapes characters that reorder or hide text", "[printable]") {
    CHECK(printable("abc" + utf8(0x202E) + "fdp.exe") == "abc\\u202efdp.exe");  // right-to-left override
    CHECK(printable(utf8(0x2066) + utf8(0x2069)) == "\\u2066\\u2069");
    CHECK(printable(utf8(0x200E) + utf8(0x200F) + utf8(0x061C)) == "\\u200e\\u200f\\u061c");
    CHECK(printable(utf8(0x2028) + utf8(0x2029)) == "\\u2028\\u2029");
    CHECK(printable("\xEF\xBB\xBF{}") == "\\ufeff{}");  // a byte order mark
    CHECK(printable(utf8(0x2027) + utf8(0x202F) + utf8(0x2065) + utf8(0x206A)) ==
          utf8(0x2027) + utf8(0x202F) + utf8(0x2065) + utf8(0x206A));  // their neighbours are kept
}

TEST_CASE("printable writes each byte of invalid UTF-8 as a backslash, x and two hex digits", "[printable]") {
    CHECK(printable("\xff") == "\\xff");
    CHECK(printable("a\x80z") == "a\\x80z");                         // a stray continuation byte
    CHECK(printable("\xC5") == "\\xc5");                             // truncated at the end
    CHECK(printable("\xC5z") == "\\xc5z");                           // truncated before ASCII
    CHECK(printable("\xE2\x82") == "\\xe2\\x82");                    // truncated three-byte form
    CHECK(printable("\xC0\x80") == "\\xc0\\x80");                    // overlong NUL
    CHECK(printable("\xC1\xBF") == "\\xc1\\xbf");                    // overlong DEL
    CHECK(printable("\xE0\x80\xAF") == "\\xe0\\x80\\xaf");           // overlong '/'
    CHECK(printable("\xF0\x80\x80\xAF") == "\\xf0\\x80\\x80\\xaf");  // overlong '/'
    CHECK(printable("\xED\xA0\x80") == "\\xed\\xa0\\x80");           // a surrogate, U+D800
    CHECK(printable("\xF4\x90\x80\x80") == "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
    CHECK(printable("\xF5\xF8\xFE") == "\\xf5\\xf8\\xfe");
    CHECK(printable("\xC5\x9B\xff\xC5\x9B") == "ś\\xffś");  // resynchronises after a bad byte
    CHECK(printable("\xC2\x1b") == "\\xc2\\u001b");         // a bad lead byte hides no ESC
}

TEST_CASE("printable output is valid, control-free and stable under a second application", "[printable]") {
    std::mt19937 random(20261129);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> length(0, 40);
    const std::string pieces[] = {"\x1b", "\n", "\\", "ś", "\xC2\x85", "\xEF\xBB\xBF", "\xE2\x80\xAE", "\xED\xA0\x80"};
    for (int n = 0; n < 2000; ++n) {
        std::string text;
        const int size = length(random);
        for (int k = 0; k < size; ++k) {
            if (byte(random) < 64)
                text += pieces[static_cast<std::size_t>(byte(random)) % std::size(pieces)];
            else
                text += static_cast<char>(byte(random));
        }
        const std::string once = printable(text);
        INFO("text: " << once);
        CHECK(!has_terminal_control(once));
        CHECK(once.find("\xE2\x80\xAE") == std::string::npos);
        CHECK(printable(once) == once);
    }
}
