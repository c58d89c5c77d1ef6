#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "article_literal.hpp"
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
    // The program's steps by key, against the literal program's locals
    // (tests/article_literal.hpp), not against the engine.
    std::map<std::string, json> by_key;
    for (const json& step : trace["steps"]) by_key.emplace(step["key"].get<std::string>(), step["value"]);
    promyk_literal::LiteralLocals v;
    const double I_P = promyk_literal::literal_intensity(0.125, 0.125, 2, promyk_literal::LiteralScene{}, &v);
    CHECK(by_key["E"] == json{0.125, 0.125, 2.0});
    CHECK(by_key["EE"] == v.E);
    CHECK(by_key["SS"] == v.S);
    CHECK(by_key["SS"].get<double>() == 3.2 * 3.2);
    CHECK(by_key["C"] == v.C);
    CHECK(by_key["delta"] == v.Delta);
    CHECK(by_key["t"] == v.t);
    CHECK(by_key["P"] == json{v.x_P, v.y_P, v.z_P});
    CHECK(by_key["N"] == json{v.x_N, v.y_N, v.z_N});
    CHECK(by_key["K"] == json{v.x_K, v.y_K, v.z_K});
    CHECK(by_key["KK"] == v.K);
    CHECK(by_key["D"] == v.D);
    CHECK(trace["result"] == I_P);
    CHECK(trace["steps"][0] == json{{"key", "E"}, {"value", {0.125, 0.125, 2.0}}});
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

TEST_CASE("strings escape every control character JSON forbids raw (U+0000 to U+001F)", "[trace-json]") {
    // RFC 8259, section 7: all of U+0000..U+001F must be escaped. A scene's
    // name or file path may hold any of them.
    const auto text_of = [](std::string_view text) {
        std::string out;
        json_text::append_string(out, text);
        return out;
    };
    for (int c = 0; c < 0x20; ++c) {
        const std::string raw = "a" + std::string(1, static_cast<char>(c)) + "b";
        const std::string written = text_of(raw);
        INFO("control character " << c);
        for (const char byte : written) CHECK(static_cast<unsigned char>(byte) >= 0x20);
        const std::string expected = c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t"
                                     : std::string("\\u00") + "0123456789abcdef"[c >> 4] + "0123456789abcdef"[c & 0xF];
        CHECK(written == "\"a" + expected + "b\"");
        CHECK(json::parse(written).get<std::string>() == raw);
    }
    CHECK(text_of(" ~\"\\\x7f") == "\" ~\\\"\\\\\x7f\"");  // from the space up only " and \ are escaped
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
    // The steps by key, not by position.
    const auto index_of = [&](Key key) {
        for (std::size_t k = 0; k < trace.steps.size(); ++k)
            if (trace.steps[k].key == key) return k;
        FAIL("no step " << key_name(key));
        return std::size_t{0};
    };
    const std::size_t t = index_of(Key::t), P = index_of(Key::P);
    trace.steps[t].value = nan;
    trace.steps[P].value = Vec3d{1, -inf, 2};
    trace.result = inf;
    const json parsed = to_json(trace);
    CHECK(parsed["steps"][t] == json{{"key", "t"}, {"value", nullptr}, {"text", "nan"}});
    CHECK(parsed["steps"][P]["value"] == json{1.0, nullptr, 2.0});
    CHECK(parsed["steps"][P]["text"] == json{nullptr, "-inf", nullptr});
    CHECK(parsed["result"] == nullptr);
    CHECK(parsed["result_text"] == "inf");
}

TEST_CASE("scene names are escaped", "[trace-json]") {
    Scene scene = article_scene();
    scene.name = "quote \" back \\ tab \t ctl \x01 zażółć";
    const json parsed = to_json(trace_pixel(scene, 8, 0, 0));
    CHECK(parsed["scene"] == scene.name);
}

TEST_CASE("a trace names its first non-finite step in JSON, and only then", "[trace-json]") {
    Scene far = article_scene();
    far.z_E = 1e200;  // |E|² overflows: the second step
    const json overflow = to_json(trace_pixel(far, 8, 3, 4));
    CHECK(overflow["first_non_finite"] == json{{"index", 1}, {"key", "EE"}});
    CHECK(overflow["steps"][1]["value"].is_null());
    CHECK(overflow["steps"][1]["text"] == "inf");
    CHECK(overflow["branch"] == "non-finite");
    CHECK(overflow["grey"] == 0);
    const json fine = to_json(trace_pixel(article_scene(), 8, 3, 4));
    CHECK_FALSE(fine.contains("first_non_finite"));
    CHECK(fine["grey"] == 177);  // round(0.6957365143147741 · 255) = round(177.41)
}
