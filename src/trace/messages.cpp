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
        // messages.json holds the words of traces and lessons; each
        // messages_TOPIC.json beside it the words of one part of promyk
        // (the answer checker, the maps, the command line). An id is defined
        // once across all of them.
        std::pair<Table, Table> parsed;
        for (const embedded::EmbeddedFile& file : embedded::lesson_files()) {
            const std::string_view path = file.path;
            if (path.find('/') != std::string_view::npos || path.substr(0, 8) != "messages" ||
                path.size() < 13 || path.substr(path.size() - 5) != ".json")
                continue;
            const nlohmann::json document = nlohmann::json::parse(file.text);
            for (const auto& [id, value] : document.at("pl").items())
                if (!parsed.first.emplace(id, value.get<std::string>()).second)
                    throw std::logic_error("message " + id + " is defined twice (lessons/messages*.json)");
            for (const auto& [id, value] : document.at("en").items())
                if (!parsed.second.emplace(id, value.get<std::string>()).second)
                    throw std::logic_error("message " + id + " is defined twice (lessons/messages*.json)");
        }
        return parsed;
    }();
    return language == Language::pl ? tables.first : tables.second;
}

std::optional<Language>& chosen_language() {
    static std::optional<Language> chosen;
    return chosen;
}

}  // namespace

Language ui_language() {
    std::optional<Language>& chosen = chosen_language();
    if (!chosen) chosen = language_from_environment();
    return *chosen;
}

void set_ui_language(Language language) { chosen_language() = language; }

std::string ui_message(std::string_view id, const MessageArgs& args) { return message(ui_language(), id, args); }

std::string counted(long long n, std::string_view id) {
    const long long last = n % 10, tens = n % 100;
    const char* form = n == 1 ? "_one" : (last >= 2 && last <= 4 && !(tens >= 12 && tens <= 14)) ? "_few" : "_many";
    return ui_message(std::string(id) + form, {{"n", std::to_string(n)}});
}

std::string message(Language language, std::string_view id, const MessageArgs& args) {
    const Table& messages = table(language);
    const auto it = messages.find(id);
    if (it == messages.end()) throw std::logic_error("lessons/messages*.json has no message " + std::string(id));
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
