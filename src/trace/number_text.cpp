#include "trace/number_text.hpp"
#include "trace/messages.hpp"
#include "math/decimal.hpp"

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
    if (std::isinf(value)) return value > 0 ? "inf" : "−inf";
    return local_number_text(decimals < 0 ? fmt::format("{}", value) : fmt::format("{:.{}f}", value, decimals), language);
}

namespace {

std::optional<int>& digits_choice() {
    static std::optional<int> chosen;
    return chosen;
}

// `exact` rounded to `digits` significant digits, halves away from zero,
// as %g would lay it out (trailing zeros dropped).
// The significant digits of a number's text ("3.2" 2, "0.0125" 3, "1e-07" 1).
int significant_digits_of(std::string_view text) {
    const std::string_view mantissa = text.substr(0, text.find_first_of("eE"));
    std::string digits;
    for (const char c : mantissa)
        if (c >= '0' && c <= '9') digits += c;
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return 1;
    return static_cast<int>(digits.find_last_not_of('0') - first + 1);
}

// `short_text`: the value's shortest round-trip text in its type has at
// most `digits` significant digits, so the value is, as far as its type can
// tell, that short decimal (3.2, 0.5, 10000): shown without trailing zeros.
std::string significant_text(const TypedNumber& exact, int digits, bool short_text) {
    std::string d = strip_zeros(exact.digits);
    if (d == "0") return "0";
    // value = 0.d × 10^(point): `point` digits stand before the decimal point.
    int point = static_cast<int>(d.size()) - exact.scale;
    const std::size_t keep = static_cast<std::size_t>(digits);
    // Exact: nothing but zeros is dropped (10000 at 4 digits is 10000).
    const bool exact_value = short_text;
    if (d.size() > keep) {
        const bool up = d[keep] >= '5';
        d.resize(keep);
        if (up) {
            std::size_t k = keep;
            while (k > 0 && d[k - 1] == '9') d[--k] = '0';
            if (k == 0) {
                d.insert(0, "1");
                d.pop_back();
                ++point;
            } else {
                ++d[k - 1];
            }
        }
    }
    // Trailing zeros say "rounded to this digit": a rounded value keeps them
    // (4.2698 is 4.270), a short one drops them (0.5, not 0.5000; 3.2, not
    // 3.200, though the double 3.2 is 3.20000000000000017...).
    if (exact_value)
        while (d.size() > 1 && d.back() == '0') d.pop_back();
    const int e = point - 1;  // the first digit's power of ten
    std::string out = exact.negative ? "-" : "";
    // %g's layout, except that a whole number shown exactly keeps its
    // digits (z_E = 10000, not 1e+04) below 10^15.
    if (e < -4 || (e >= digits && !(exact_value && e < 15))) {
        out += d.substr(0, 1);
        if (d.size() > 1) out += "." + d.substr(1);
        out += fmt::format("e{}{:02}", e < 0 ? '-' : '+', e < 0 ? -e : e);
    } else if (e < 0) {
        out += "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + d;
    } else {
        const std::size_t whole = static_cast<std::size_t>(e) + 1;
        if (d.size() <= whole) {
            out += d + std::string(whole - d.size(), '0');
        } else {
            out += d.substr(0, whole) + "." + d.substr(whole);
        }
    }
    return out;
}

}  // namespace

std::optional<int> chosen_digits() { return digits_choice(); }

void set_chosen_digits(int digits) { digits_choice() = digits; }

int shown_digits(int default_digits) { return digits_choice().value_or(default_digits); }

std::string shown_number(double value, Language language, int digits) {
    if (value == 0) return "0";
    if (!std::isfinite(value) || digits <= 0) return number_text(value, language);
    const bool short_text = significant_digits_of(fmt::format("{}", value)) <= digits;
    return local_number_text(significant_text(exact_decimal(value), digits, short_text), language);
}

std::string shown_real_text(const std::string& text, RealType type, Language language, int digits) {
    const std::optional<TypedNumber> exact = exact_value_of(text, type);
    if (!exact) return local_number_text(text, language);  // inf, nan
    if (is_zero(*exact)) return "0";
    if (digits <= 0) return local_number_text(text, language);
    return local_number_text(significant_text(*exact, digits, significant_digits_of(text) <= digits), language);
}

std::string local_number_text(std::string_view text, Language language) {
    // One minus sign in every text for people: U+2212, as the formulas write
    // it ("N = P − S"), in both languages; JSON keeps the ASCII hyphen.
    std::string local;
    for (const char c : text) {
        if (c == '.' && language == Language::pl)
            local += ',';
        else if (c == '-')
            local += "−";
        else
            local += c;
    }
    return local;
}

std::string point_text(const Vec3d& point, Language language) { return value_text(point, "point", language); }

std::string value_text(const StepValue& value, const std::string& kind, Language language, int decimals) {
    if (const double* number = std::get_if<double>(&value)) return number_text(*number, language, decimals);
    if (const std::string* word = std::get_if<std::string>(&value)) return word_text(language, *word);
    const Vec3d& v = std::get<Vec3d>(value);
    const char* open = kind == "vector" || kind == "colour" ? "[" : "(";
    const char* close = kind == "vector" || kind == "colour" ? "]" : ")";
    const char* separator = coordinate_separator(language);
    return fmt::format("{}{}{}{}{}{}{}", open, number_text(v.x, language, decimals), separator,
                       number_text(v.y, language, decimals), separator, number_text(v.z, language, decimals), close);
}

}  // namespace promyk

namespace promyk {

std::string shown_value_text(const StepValue& value, const std::string& kind, Language language, int digits) {
    if (const double* number = std::get_if<double>(&value)) return shown_number(*number, language, digits);
    if (const std::string* word = std::get_if<std::string>(&value)) return word_text(language, *word);
    const Vec3d& v = std::get<Vec3d>(value);
    const bool bracket = kind == "vector" || kind == "colour";
    const char* separator = coordinate_separator(language);
    return std::string(bracket ? "[" : "(") + shown_number(v.x, language, digits) + separator +
           shown_number(v.y, language, digits) + separator + shown_number(v.z, language, digits) + (bracket ? "]" : ")");
}

std::string typed_number_text(const TypedNumber& number, Language language) {
    std::string digits = strip_zeros(number.digits);
    std::string text;
    if (number.scale <= 0) {
        text = digits == "0" ? digits : digits + std::string(static_cast<std::size_t>(-number.scale), '0');
    } else {
        const std::size_t scale = static_cast<std::size_t>(number.scale);
        if (digits.size() < scale + 1) digits.insert(0, scale + 1 - digits.size(), '0');
        text = digits.substr(0, digits.size() - scale) + (language == Language::pl ? "," : ".") + digits.substr(digits.size() - scale);
    }
    if (number.negative && strip_zeros(number.digits) != "0") text = (language == Language::pl ? "\u2212" : "-") + text;
    return text;
}

}  // namespace promyk
