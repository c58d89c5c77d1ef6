#include "trace/byte_size_text.hpp"

#include <fmt/format.h>

#include "trace/messages.hpp"

namespace promyk {

std::string byte_size_text(double bytes) {
    std::string text;
    if (bytes < 999.5) {
        text = fmt::format("{:.0f} B", bytes);
    } else {
        const char* units[] = {"kB", "MB", "GB", "TB", "PB", "EB"};
        int unit = 0;
        bytes /= 1000;
        while (bytes >= 999.5 && unit < 5) {  // 999.5 kB would print as 1000 kB
            bytes /= 1000;
            ++unit;
        }
        text = bytes < 99.95 ? fmt::format("{:.1f} {}", bytes, units[unit]) : fmt::format("{:.0f} {}", bytes, units[unit]);
    }
    if (ui_language() == Language::pl)
        for (char& c : text)
            if (c == '.') c = ',';
    return text;
}

}  // namespace promyk
