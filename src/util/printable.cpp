#include "util/printable.hpp"

#include <cstddef>
#include <cstdint>

namespace promyk {

namespace {

constexpr char hex_digits[] = "0123456789abcdef";

// The length of the well-formed UTF-8 sequence at the start of `text` (the
// Unicode standard's table 3-7), or 0 if it does not start with one; the code
// point in `code`.
std::size_t utf8_sequence(std::string_view text, std::uint32_t& code) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80u) {
        code = lead;
        return 1;
    }
    std::size_t length = 0;
    unsigned char low = 0x80u;  // the allowed range of the second byte
    unsigned char high = 0xBFu;
    if (lead >= 0xC2u && lead <= 0xDFu) {
        length = 2;
        code = lead & 0x1Fu;
    } else if (lead >= 0xE0u && lead <= 0xEFu) {
        length = 3;
        code = lead & 0x0Fu;
        if (lead == 0xE0u) low = 0xA0u;   // no overlong forms
        if (lead == 0xEDu) high = 0x9Fu;  // no surrogates
    } else if (lead >= 0xF0u && lead <= 0xF4u) {
        length = 4;
        code = lead & 0x07u;
        if (lead == 0xF0u) low = 0x90u;   // no overlong forms
        if (lead == 0xF4u) high = 0x8Fu;  // nothing above U+10FFFF
    } else {
        return 0;  // a continuation byte, C0, C1 or F5–FF
    }
    if (text.size() < length) return 0;
    if (byte(1) < low || byte(1) > high) return 0;
    code = (code << 6) | (byte(1) & 0x3Fu);
    for (std::size_t k = 2; k < length; ++k) {
        if ((byte(k) & 0xC0u) != 0x80u) return 0;
        code = (code << 6) | (byte(k) & 0x3Fu);
    }
    return length;
}

bool needs_escape(std::uint32_t code) {
    return code < 0x20u || (code >= 0x7Fu && code <= 0x9Fu)  // C0, DEL, C1
           || code == 0x061Cu                                // Arabic letter mark
           || code == 0x200Eu || code == 0x200Fu             // left-to-right, right-to-left marks
           || (code >= 0x2028u && code <= 0x202Eu)           // separators, embeddings, overrides
           || (code >= 0x2066u && code <= 0x2069u)           // isolates
           || code == 0xFEFFu;                               // byte order mark
}

}  // namespace

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        std::uint32_t code = 0;
        const std::size_t length = utf8_sequence(text, code);
        if (length == 0) {
            const auto byte = static_cast<unsigned char>(text[0]);
            out += "\\x";
            out += hex_digits[byte >> 4];
            out += hex_digits[byte & 0xFu];
            text.remove_prefix(1);
            continue;
        }
        if (!needs_escape(code)) {
            out.append(text.data(), length);
        } else if (code == '\n') {
            out += "\\n";
        } else if (code == '\r') {
            out += "\\r";
        } else if (code == '\t') {
            out += "\\t";
        } else {
            out += "\\u";
            for (int shift = 12; shift >= 0; shift -= 4) out += hex_digits[(code >> shift) & 0xFu];
        }
        text.remove_prefix(length);
    }
    return out;
}

}  // namespace promyk
