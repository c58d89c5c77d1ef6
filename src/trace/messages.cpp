#include "trace/messages.hpp"

#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/embedded_files.hpp"

namespace promyk {

namespace {

using Table = std::map<std::string, std::string, std::less<>>;

const Table& table(Language language) {
    static const std::pair<Table, Table> tables = [] {
        std::string_view text;
        for (const embedded::EmbeddedFile& file : embedded::lesson_files())
            if (file.path == "messages.json") text = file.text;
        const nlohmann::json document = nlohmann::json::parse(text);
        std::pair<Table, Table> parsed;
        for (const auto& [id, value] : document.at("pl").items()) parsed.first[id] = value.get<std::string>();
        for (const auto& [id, value] : document.at("en").items()) parsed.second[id] = value.get<std::string>();
        return parsed;
    }();
    return language == Language::pl ? tables.first : tables.second;
}

}  // namespace

std::string message(Language language, std::string_view id, const MessageArgs& args) {
    const Table& messages = table(language);
    const auto it = messages.find(id);
    if (it == messages.end()) throw std::logic_error("lessons/messages.json has no message " + std::string(id));
    std::string out;
    const std::string& text = it->second;
    for (std::size_t k = 0; k < text.size();) {
        if (text[k] == '{') {
            const std::size_t close = text.find('}', k);
            if (close != std::string::npos) {
                const std::string_view name(text.data() + k + 1, close - k - 1);
                bool replaced = false;
                for (const auto& [arg, value] : args) {
                    if (arg == name) {
                        out += value;
                        replaced = true;
                        break;
                    }
                }
                if (replaced) {
                    k = close + 1;
                    continue;
                }
            }
        }
        out += text[k++];
    }
    return out;
}

std::optional<std::string> optional_message(Language language, std::string_view id) {
    if (table(language).count(id) == 0) return std::nullopt;
    return message(language, id);
}

std::vector<std::string> message_ids(Language language) {
    std::vector<std::string> ids;
    for (const auto& [id, text] : table(language)) ids.push_back(id);
    return ids;
}

std::string group_text(Language language, std::string_view kind, int index) {
    const std::string id = (kind == "light" || kind == "material" || kind == "sample" ? "group_" : "object_") + std::string(kind);
    if (table(language).count(id) == 0) return std::string(kind) + " " + std::to_string(index);
    return message(language, id, {{"index", std::to_string(index)}});
}

std::string word_text(Language language, std::string_view word) {
    for (std::string_view kind : {"sphere", "plane"}) {
        const std::string prefix = std::string(kind) + " ";
        if (word.substr(0, prefix.size()) == prefix) {
            const std::string_view digits = word.substr(prefix.size());
            if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos)
                return group_text(language, kind, std::stoi(std::string(digits)));
        }
    }
    const std::string id = "word_" + std::string(word);
    if (table(language).count(id) == 0) return std::string(word);
    return message(language, id);
}

}  // namespace promyk
