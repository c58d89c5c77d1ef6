#include "trace/json_text.hpp"

#include <cstring>

#include <fmt/compile.h>
#include <fmt/format.h>

namespace promyk::json_text {

namespace {

// The escape of a character JSON forbids raw in a string.
void append_escape(std::string& out, char c) {
    switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default: {  // the other controls, U+0000 to U+001F
            char text[8];
            const char* end = fmt::format_to(text, FMT_COMPILE("\\u{:04x}"), static_cast<unsigned>(c));
            out.append(text, static_cast<std::size_t>(end - text));
        }
    }
}

bool needs_escape(char c) { return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20; }

}  // namespace

void append_string(std::string& out, std::string_view text) {
    out += '"';
    // Runs of characters that need no escape are copied whole.
    std::size_t run = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (!needs_escape(text[k])) continue;
        out.append(text.data() + run, k - run);
        append_escape(out, text[k]);
        run = k + 1;
    }
    out.append(text.data() + run, text.size() - run);
    out += '"';
}

void append_number(std::string& out, double value) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    // The shortest digits that read back to the value (Dragonbox, as fmt's
    // "{}" finds them), laid out as "{}" lays them out: 1234e-2 is 12.34,
    // 1234e-6 is 0.001234, 1234e5 is 123400000; below 1e-4 or from 1e16 on,
    // 1.234e-05 and 1.234e+16. Laid out here rather than by fmt's general
    // float writer, which costs as much again as finding the digits
    // (tests/trace_json_test.cpp checks the text equals fmt's, on random doubles).
    const auto decimal = fmt::detail::dragonbox::to_decimal(std::fabs(value));
    const fmt::format_int digits(decimal.significand);
    const char* d = digits.data();
    const int n = static_cast<int>(digits.size());
    const int exponent = decimal.exponent;    // value = digits * 10^exponent
    const int scientific = exponent + n - 1;  // value = d.ddd * 10^scientific
    // Composed here, then appended in one piece: at most 24 characters
    // (-2.2250738585072014e-308, -0.00012345678901234567).
    char text[32];
    char* p = text;
    const auto copy = [&p](const char* from, int count) {
        std::memcpy(p, from, static_cast<std::size_t>(count));
        p += count;
    };
    const auto zeros = [&p](int count) {
        std::memset(p, '0', static_cast<std::size_t>(count));
        p += count;
    };
    if (std::signbit(value)) *p++ = '-';
    if (scientific < -4 || scientific >= 16) {
        *p++ = d[0];
        if (n > 1) {
            *p++ = '.';
            copy(d + 1, n - 1);
        }
        *p++ = 'e';
        *p++ = scientific < 0 ? '-' : '+';
        const fmt::format_int power(scientific < 0 ? -scientific : scientific);
        if (power.size() < 2) *p++ = '0';
        copy(power.data(), static_cast<int>(power.size()));
    } else if (exponent >= 0) {  // 1234e5: 123400000
        copy(d, n);
        zeros(exponent);
    } else if (exponent + n > 0) {  // 1234e-2: 12.34
        copy(d, exponent + n);
        *p++ = '.';
        copy(d + exponent + n, -exponent);
    } else {  // 1234e-6: 0.001234
        *p++ = '0';
        *p++ = '.';
        zeros(-(exponent + n));
        copy(d, n);
    }
    out.append(text, static_cast<std::size_t>(p - text));
}

void append_integer(std::string& out, long long value) {
    const fmt::format_int text(value);
    out.append(text.data(), text.size());
}

void append_tenths(std::string& out, double value) {
    // value is k/10 for a whole k: its one-decimal text is k's digits with a
    // point before the last, exactly what fmt's "{:.1f}" writes.
    const double tenths = value * 10;
    if (!std::isfinite(value) || std::fabs(tenths) >= 1e15 || tenths != std::round(tenths)) {
        char text[32];
        const auto written = fmt::format_to_n(text, sizeof text, FMT_COMPILE("{:.1f}"), value);
        if (written.size <= sizeof text) {
            out.append(text, written.size);
            return;
        }
        out += fmt::format(FMT_COMPILE("{:.1f}"), value);  // a long number: as many digits as it takes
        return;
    }
    const long long k = std::llround(std::fabs(tenths));
    if (std::signbit(value)) out += '-';
    append_integer(out, k / 10);
    out += '.';
    out += static_cast<char>('0' + k % 10);
}

std::string_view non_finite_text(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return {};
}

}  // namespace promyk::json_text
