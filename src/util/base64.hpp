// Base64 (RFC 4648, with padding): how the exported page carries binary data
// (the image, the branch map, a trace file) inside its HTML, where the
// letters A-Z a-z 0-9 + / = can never close a tag or start an entity.
#pragma once

#include <string>
#include <string_view>

namespace promyk {

inline std::string base64(std::string_view bytes) {
    static constexpr char letters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t k = 0;
    for (; k + 3 <= bytes.size(); k += 3) {
        const unsigned v = static_cast<unsigned char>(bytes[k]) << 16 | static_cast<unsigned char>(bytes[k + 1]) << 8 |
                           static_cast<unsigned char>(bytes[k + 2]);
        text += letters[v >> 18];
        text += letters[(v >> 12) & 63];
        text += letters[(v >> 6) & 63];
        text += letters[v & 63];
    }
    if (const std::size_t rest = bytes.size() - k) {
        unsigned v = static_cast<unsigned char>(bytes[k]) << 16;
        if (rest == 2) v |= static_cast<unsigned char>(bytes[k + 1]) << 8;
        text += letters[v >> 18];
        text += letters[(v >> 12) & 63];
        text += rest == 2 ? letters[(v >> 6) & 63] : '=';
        text += '=';
    }
    return text;
}

}  // namespace promyk
