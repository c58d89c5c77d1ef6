#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "render/trace_pixel.hpp"
#include "trace/json_text.hpp"

using namespace promyk;
using nlohmann::json;

namespace {

json to_json(const PixelTrace& trace) {
    std::string text;
    append_trace_json(text, trace);
    REQUIRE(text.find('\n') == std::string::npos);  // one line: a JSON Lines record
    return json::parse(text);
}

}  // namespace

TEST_CASE("a trace's JSON carries the header, the steps and the result", "[trace-json]") {
    const json trace = to_json(trace_pixel(article_scene(), 8, 3, 4));
    CHECK(trace["schema"] == 1);
    CHECK(trace["promyk"] == PROMYK_VERSION);
    CHECK(trace["scene"] == "article");
    CHECK(trace["scene_hash"].get<std::string>().rfind("fnv1a64:", 0) == 0);
    CHECK(trace["w"] == 8);
    CHECK(trace["z_E"] == 2.0);
    CHECK(trace["pixel"] == json{{"i", 3}, {"j", 4}});
    CHECK(trace["numeric"] == json{{"real", "double"}, {"formula", "article"}, {"spp", 1}});
    CHECK(trace["effects"] == json::array({"lambert"}));
    CHECK(trace["branch"] == "lit");
    REQUIRE(trace["steps"].size() == 11);
    CHECK(trace["steps"][0] == json{{"key", "E"}, {"value", {0.125, 0.125, 2.0}}});
    CHECK(trace["steps"][2]["key"] == "SS");
    CHECK(trace["steps"][2]["value"].get<double>() == 3.2 * 3.2);
}

TEST_CASE("numbers are written as the shortest text that reads back to the same double", "[trace-json]") {
    const auto text_of = [](double v) {
        std::string out;
        json_text::append_number(out, v);
        return out;
    };
    CHECK(text_of(0.1) == "0.1");
    CHECK(text_of(3.2 * 3.2) == "10.240000000000002");
    CHECK(text_of(2.0) == "2");
    CHECK(text_of(-0.0) == "-0");
    CHECK(text_of(5e-324) == "5e-324");
    CHECK(std::stod(text_of(1.0 / 3)) == 1.0 / 3);
    CHECK(text_of(std::numeric_limits<double>::infinity()) == "null");
}

TEST_CASE("every traced double reads back exactly", "[trace-json]") {
    const PixelTrace trace = trace_pixel(article_scene(), 101, 37, 60);
    const json parsed = to_json(trace);
    REQUIRE(parsed["steps"].size() == trace.steps.size());
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        if (const double* v = std::get_if<double>(&trace.steps[k].value)) {
            CHECK(parsed["steps"][k]["value"].get<double>() == *v);
        } else {
            const Vec3d& u = std::get<Vec3d>(trace.steps[k].value);
            CHECK(parsed["steps"][k]["value"] == json{u.x, u.y, u.z});
        }
    }
    CHECK(parsed["result"].get<double>() == trace.result);
}

TEST_CASE("non-finite numbers are null with their text beside them", "[trace-json]") {
    PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    trace.steps[5].value = nan;                // t
    trace.steps[6].value = Vec3d{1, -inf, 2};  // P
    trace.result = inf;
    const json parsed = to_json(trace);
    CHECK(parsed["steps"][5] == json{{"key", "t"}, {"value", nullptr}, {"text", "nan"}});
    CHECK(parsed["steps"][6]["value"] == json{1.0, nullptr, 2.0});
    CHECK(parsed["steps"][6]["text"] == json{nullptr, "-inf", nullptr});
    CHECK(parsed["result"] == nullptr);
    CHECK(parsed["result_text"] == "inf");
}

TEST_CASE("scene names are escaped", "[trace-json]") {
    Scene scene = article_scene();
    scene.name = "quote \" back \\ tab \t ctl \x01 zażółć";
    const json parsed = to_json(trace_pixel(scene, 8, 0, 0));
    CHECK(parsed["scene"] == scene.name);
}
