// The digits rule: numbers shown to people are rounded to N significant
// digits, halves away from zero, zero is "0". Expected texts are worked by
// hand from the values' exact binary expansions.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "trace/number_text.hpp"
#include "sweep_size.hpp"

using promyk::Language;
using promyk::shown_number;

TEST_CASE("shown_number rounds to significant digits, halves up", "[digits]") {
    CHECK(shown_number(4.557812500000004, Language::en, 4) == "4.558");
    CHECK(shown_number(10.240000000000002, Language::en, 4) == "10.24");
    CHECK(shown_number(0.125, Language::en, 2) == "0.13");   // exact tie: away from zero, not to even
    CHECK(shown_number(-0.125, Language::en, 2) == "−0.13");  // U+2212 in both languages
    CHECK(shown_number(0.5, Language::en, 4) == "0.5");      // exact: trailing zeros dropped
    CHECK(shown_number(2.0, Language::en, 4) == "2");
    CHECK(shown_number(9.99995, Language::en, 4) == "10.00");  // carries into a new digit; rounded: zeros kept
    CHECK(shown_number(4.269806787197755, Language::en, 4) == "4.270");
    CHECK(shown_number(0.6957365143147741, Language::en, 4) == "0.6957");
    CHECK(shown_number(1.058008460502604, Language::en, 4) == "1.058");
    CHECK(shown_number(1234.5, Language::en, 4) == "1235");  // 1234.5 is exact: a tie, up
    CHECK(shown_number(12345.0, Language::en, 4) == "1.235e+04");
    CHECK(shown_number(10000.0, Language::en, 4) == "10000");  // exact: stays whole
    CHECK(shown_number(1e15, Language::en, 4) == "1e+15");
    CHECK(shown_number(123000000.0, Language::en, 4) == "123000000");
    CHECK(shown_number(94906265.0, Language::en, 4) == "9.491e+07");
    CHECK(shown_number(0.0001234567, Language::en, 4) == "0.0001235");
    CHECK(shown_number(0.00001234567, Language::en, 4) == "1.235e−05");
    CHECK(shown_number(1e-300, Language::en, 4) == "1e−300");  // the shortest text is 1e-300
    CHECK(shown_number(3.0000000000000004, Language::en, 4) == "3.000");  // rounded, not exact
    CHECK(shown_number(0.125, Language::en, 4) == "0.125");              // exact: no zeros added
    CHECK(shown_number(3.2, Language::en, 4) == "3.2");                  // the double 3.2000000000000001776: shortest 3.2
    CHECK(shown_number(-0.2, Language::en, 4) == "−0.2");
}

TEST_CASE("zero shows as 0 whatever its sign and digits", "[digits]") {
    for (int digits : {0, 1, 4, 17}) {
        CHECK(shown_number(0.0, Language::en, digits) == "0");
        CHECK(shown_number(-0.0, Language::en, digits) == "0");
        CHECK(shown_number(-0.0, Language::pl, digits) == "0");
    }
}

TEST_CASE("shown_number in Polish: decimal comma and a true minus", "[digits]") {
    CHECK(shown_number(-0.125, Language::pl, 2) == "−0,13");
    CHECK(shown_number(0.00001234567, Language::pl, 4) == "1,235e−05");
    CHECK(shown_number(4.557812500000004, Language::pl, 0) == "4,557812500000004");
}

TEST_CASE("shown_number at 0 digits is the shortest round-trip text", "[digits]") {
    CHECK(shown_number(10.240000000000002, Language::en, 0) == "10.240000000000002");
    CHECK(shown_number(std::nan(""), Language::en, 4) == "nan");
    CHECK(shown_number(-INFINITY, Language::en, 4) == "−inf");
}

// Property: for random doubles over the whole range and every digit count,
// the shown text has at most N significant digits and lies within half a
// unit of its last digit of the value (checked in long double, whose
// 64-bit significand holds every double and the rounding of the text).
TEST_CASE("shown_number is within half a unit in the last shown digit", "[digits]") {
    std::mt19937_64 random(20261201);
    std::uniform_real_distribution<double> significand(-10, 10);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int k = 0; k < sweep_size(20000, 2000); ++k) {
        const double value = std::ldexp(significand(random), exponent(random));
        if (value == 0) continue;
        for (int digits = 1; digits <= 17; ++digits) {
            std::string text = shown_number(value, Language::en, digits);
            for (std::size_t at; (at = text.find("−")) != std::string::npos;) text.replace(at, 3, "-");
            int significant = 0;
            bool seen = false;
            // a whole number shown exactly keeps its trailing zeros: they hold no digit
            std::string mantissa = text.substr(0, text.find('e'));
            if (mantissa.find('.') == std::string::npos && text.find('e') == std::string::npos)
                while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
            for (char c : mantissa) {
                if (c == 'e') break;
                if (c >= '1' && c <= '9') seen = true;
                if (seen && c >= '0' && c <= '9') ++significant;
            }
            INFO(value << " at " << digits << " digits: " << text);
            REQUIRE(significant <= digits);
            const long double back = std::strtold(text.c_str(), nullptr);
            const long double unit = std::pow(10.0L, std::floor(std::log10(std::fabs(static_cast<long double>(value)))) - digits + 1);
            // the shown value may have gained a digit (9.9996 -> 10): allow a unit of the next decade
            REQUIRE(std::fabs(back - value) <= unit * 0.5000001L + std::fabs(value) * 1e-18L);
        }
    }
}
