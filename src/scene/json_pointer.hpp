// JSON pointers (RFC 6901) as the scene loader names the field of a fault,
// and keys as a message shows them.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "util/printable.hpp"

namespace promyk::scene_detail {

// One reference token: '~' -> "~0", '/' -> "~1".
inline std::string pointer_token(std::string_view token) {
    std::string out;
    out.reserve(token.size());
    for (const char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

inline std::string child(const std::string& pointer, std::string_view key) { return pointer + "/" + pointer_token(key); }
inline std::string child(const std::string& pointer, std::size_t index) { return pointer + "/" + std::to_string(index); }

// A key as shown inside a message: JSON string escapes, without the quotes,
// and printable() for what JSON leaves raw (DEL, C1 controls, ...).
inline std::string shown_key(const std::string& key) {
    const std::string quoted = nlohmann::json(key).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return printable(std::string_view(quoted).substr(1, quoted.size() - 2));
}

}  // namespace promyk::scene_detail
