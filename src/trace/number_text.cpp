#include "trace/number_text.hpp"
#include "trace/messages.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace promyk {

std::optional<Language> parse_language(std::string_view text) {
    if (text == "pl") return Language::pl;
    if (text == "en") return Language::en;
    return std::nullopt;
}

Language language_from_environment() {
    // The first of these that is set and not empty decides, as in POSIX.
    for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
        const char* value = std::getenv(name);
        if (value != nullptr && *value != '\0') return std::string_view(value).substr(0, 2) == "pl" ? Language::pl : Language::en;
    }
    return Language::en;
}

std::string_view language_code(Language language) { return language == Language::pl ? "pl" : "en"; }

std::string number_text(double value, Language language, int decimals) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : (language == Language::pl ? "−inf" : "-inf");
    return local_number_text(decimals < 0 ? fmt::format("{}", value) : fmt::format("{:.{}f}", value, decimals), language);
}

std::string local_number_text(std::string_view text, Language language) {
    if (language != Language::pl) return std::string(text);
    std::string polish;
    for (const char c : text) {
        if (c == '.')
            polish += ',';
        else if (c == '-')
            polish += "−";  // U+2212, the minus sign of Polish typesetting
        else
            polish += c;
    }
    return polish;
}

std::string value_text(const StepValue& value, const std::string& kind, Language language, int decimals) {
    if (const double* number = std::get_if<double>(&value)) return number_text(*number, language, decimals);
    if (const std::string* word = std::get_if<std::string>(&value)) return word_text(language, *word);
    const Vec3d& v = std::get<Vec3d>(value);
    const char* open = kind == "vector" || kind == "colour" ? "[" : "(";
    const char* close = kind == "vector" || kind == "colour" ? "]" : ")";
    const char* separator = language == Language::pl ? "; " : ", ";
    return fmt::format("{}{}{}{}{}{}{}", open, number_text(v.x, language, decimals), separator,
                       number_text(v.y, language, decimals), separator, number_text(v.z, language, decimals), close);
}

}  // namespace promyk
