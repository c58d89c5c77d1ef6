// The values of the command line (src/app/cli_values.*): a pixel outside the
// pane names the smallest --w that holds it; numbers beyond the largest pane
// are a usage error with the range, never an overflow.
#include <catch2/catch.hpp>

#include <random>
#include <regex>
#include <string>

#include "app/cli_values.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace {

std::string usage_error(const std::string& text, int w) {
    try {
        promyk::cli::parse_pixel(text, "--pixel", w);
    } catch (const promyk::UsageError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a pixel outside the pane names the smallest w that holds it", "[cli]") {
    promyk::set_ui_language(promyk::Language::en);
    std::mt19937 random(14);
    std::uniform_int_distribution<int> side(1, promyk::cli::max_w);
    for (int k = 0; k < 2000; ++k) {
        const int w = side(random);
        std::uniform_int_distribution<int> coordinate(0, promyk::cli::max_w - 1);
        const int i = coordinate(random), j = coordinate(random);
        const std::string text = std::to_string(i) + "," + std::to_string(j);
        const std::string message = usage_error(text, w);
        INFO("pixel " << text << ", w " << w << ": " << message);
        if (i < w && j < w) {
            CHECK(message.empty());
            continue;
        }
        std::smatch match;
        REQUIRE(std::regex_search(message, match, std::regex("w ≥ ([0-9]+): add (--w 512 \\(render's default\\) or )?--w ([0-9]+)$")));
        const int named = std::stoi(match[1]);
        CHECK(std::stoi(match[3]) == named);
        // The named w holds the pixel; w - 1 does not.
        CHECK((i < named && j < named));
        CHECK(!(i < named - 1 && j < named - 1));
        CHECK(usage_error(text, named).empty());
        // render's default is offered when it holds the pixel and is not the pane already.
        CHECK(match[2].matched == (named <= promyk::cli::render_default_w && w != promyk::cli::render_default_w));
    }
}

TEST_CASE("pixel numbers beyond the largest pane are refused with the range", "[cli]") {
    promyk::set_ui_language(promyk::Language::en);
    for (const char* text : {"2147483648,0", "0,2147483648", "99999999999999999999,1", "32768,0", "-2147483649,0"}) {
        INFO(text);
        const std::string message = usage_error(text, 8);
        CHECK_THAT(message, Catch::Matchers::Contains("numbers from 0 to 32767"));
    }
    CHECK_THROWS_AS(promyk::cli::parse_region("0,0,1,2147483648", "--trace-region", 8), promyk::UsageError);
    CHECK_THAT(usage_error("32767,0", 8), Catch::Matchers::Contains("w ≥ 32768: add --w 32768"));
    CHECK_THAT(usage_error("-1,0", 8), Catch::Matchers::Contains("i and j go from 0 to 7"));
}

TEST_CASE("an unknown value gets the name probably meant", "[cli]") {
    promyk::set_ui_language(promyk::Language::en);
    const std::vector<std::string> reals = {"float", "double", "long-double", "quad"};
    CHECK(promyk::cli::choice_problem("float", "--real", reals).empty());
    CHECK(promyk::cli::choice_problem("flaot", "--real", reals) ==
          "unknown value 'flaot' for --real; did you mean 'float'? (float, double, long-double, quad)");
    CHECK(promyk::cli::choice_problem("DOUBLE", "--real", reals) ==
          "unknown value 'DOUBLE' for --real; did you mean 'double'? (float, double, long-double, quad)");
    CHECK(promyk::cli::choice_problem("0", "--real", reals) ==
          "unknown value '0' for --real; the values are float, double, long-double, quad");
}
