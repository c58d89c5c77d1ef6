// For tests of messages: does a text hold a byte a terminal acts on?
#pragma once

#include <string>

namespace promyk::testing {

// C0 controls, DEL, or the UTF-8 form of a C1 control (C2 80 – C2 9F).
inline bool has_terminal_control(const std::string& text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto c = static_cast<unsigned char>(text[k]);
        if (c < 0x20u || c == 0x7Fu) return true;
        if (c == 0xC2u && k + 1 < text.size()) {
            const auto next = static_cast<unsigned char>(text[k + 1]);
            if (next >= 0x80u && next <= 0x9Fu) return true;
        }
    }
    return false;
}

}  // namespace promyk::testing
