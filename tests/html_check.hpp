// Why a text is not well-formed HTML of the kind the lesson runner and the
// worksheet write (elements that nest and close, <input> the one void
// element, quoted attributes, no bare < > or &), or "". Shared by the lesson
// and worksheet HTML tests.
#pragma once

#include <regex>
#include <string>
#include <vector>

inline std::string html_fault(const std::string& html) {
    static const std::regex tag(R"(<(/?)([a-z][a-z0-9]*)((?: [a-z-]+="[^"<>]*")*)>)");
    static const std::regex entity(R"(&(amp|lt|gt|quot|#39);)");
    std::vector<std::string> open;
    std::size_t at = 0;
    const auto text_fault = [&](const std::string& text) -> std::string {
        if (text.find('<') != std::string::npos || text.find('>') != std::string::npos) return "a bare < or > in: " + text;
        for (std::size_t amp = text.find('&'); amp != std::string::npos; amp = text.find('&', amp + 1))
            if (!std::regex_search(text.substr(amp, 6), entity, std::regex_constants::match_continuous))
                return "a bare & in: " + text;
        return "";
    };
    for (std::sregex_iterator it(html.begin(), html.end(), tag), end; it != end; ++it) {
        if (std::string fault = text_fault(html.substr(at, static_cast<std::size_t>(it->position()) - at)); !fault.empty())
            return fault;
        at = static_cast<std::size_t>(it->position() + it->length());
        const std::string name = (*it)[2];
        if (name == "input") {
            if ((*it)[1].length() != 0) return "</input>";
            continue;
        }
        if ((*it)[1].length() == 0) {
            open.push_back(name);
        } else {
            if (open.empty() || open.back() != name) return "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
            open.pop_back();
        }
    }
    if (std::string fault = text_fault(html.substr(at)); !fault.empty()) return fault;
    return open.empty() ? "" : "<" + open.back() + "> left open";
}
