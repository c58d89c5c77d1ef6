// promyk diff: digits that agree computed exactly, the first divergence,
// tolerances, group paths, missing steps, a student's file.
#include <catch2/catch.hpp>

#include <string>

#include "lesson/trace_diff.hpp"
#include "render/trace_pixel.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

TypedNumber diff_number(const std::string& text) {
    const std::optional<TypedNumber> parsed = parse_typed_number(text);
    REQUIRE(parsed);
    return *parsed;
}

DiffInput input(const std::string& text, const std::string& file = "x") {
    return {file, read_answers(text, file, builtin_vocabulary(), Language::en, diff_first_pixel, AnswerLimits{})};
}

std::string trace_json(RealType real, int i = 3, int j = 4, const Scene& scene = article_scene()) {
    std::string out;
    append_trace_json(out, trace_pixel(scene, 8, i, j, real));
    return out;
}

DiffResult diff(const DiffInput& a, const DiffInput& b, DiffOptions options = {}) {
    return diff_inputs(a, b, builtin_vocabulary(), options, Language::en);
}

const DiffStep& step_of(const DiffResult& result, const std::string& path) {
    for (const DiffStep& step : result.steps)
        if (step.path == path) return step;
    FAIL("no step " << path);
    throw;
}

}  // namespace

TEST_CASE("Digits that agree are computed exactly") {
    CHECK(digits_agreeing(diff_number("3.14159"), diff_number("3.14160")) == 5);
    // float's 0.1 is 0.100000001490116119384765625: its shortest double text agrees to 8 digits.
    CHECK(digits_agreeing(diff_number("0.1"), diff_number("0.10000000149011612")) == 8);
    CHECK(digits_agreeing(diff_number("0.1"), *exact_value_of("0.1", RealType::float_)) == 8);
    CHECK_FALSE(digits_agreeing(diff_number("6.40"), diff_number("6,4")).has_value());  // equal: all digits
    CHECK(digits_agreeing(diff_number("1"), diff_number("-1")) == 0);
    CHECK(digits_agreeing(diff_number("0"), diff_number("1e-17")) == 0);
    CHECK(digits_agreeing(diff_number("999.95"), diff_number("1000.05")) == 4);  // 0.1 apart: within half a unit of the 4th digit (1000)
    CHECK(digits_agreeing(diff_number("1.0005"), diff_number("1.0000")) == 4);   // exactly half a unit of the 4th digit
}

TEST_CASE("Exact values of the real types") {
    CHECK(typed_number_text(*exact_value_of("0.1", RealType::float_), Language::en) == "0.100000001490116119384765625");
    CHECK(typed_number_text(*exact_value_of("0.5", RealType::quad_), Language::en) == "0.5");
    CHECK(strip_zeros(exact_value_of("6.400000000000000355271367880050093", RealType::quad_)->digits).size() > 34);
    CHECK_FALSE(exact_value_of("nan", RealType::double_));
    CHECK_FALSE(exact_value_of("1x", RealType::double_));
    CHECK(real_type_bits("float") == 24);
    CHECK(real_type_bits("quad") == 113);
}

TEST_CASE("Identical traces agree at every step") {
    const DiffInput a = input(trace_json(RealType::double_));
    const DiffResult result = diff(a, a);
    CHECK_FALSE(result.first);
    CHECK(result.common == result.steps.size());
    for (const DiffStep& step : result.steps) {
        CHECK(step.status == DiffStatus::agree);
        for (const DiffComponent& c : step.components) CHECK_FALSE(c.digits);
    }
}

TEST_CASE("Float against quad: the first step beyond float's precision is named") {
    const DiffResult result = diff(input(trace_json(RealType::float_)), input(trace_json(RealType::quad_)));
    REQUIRE(result.first);
    // 3.2 is not a float: S·S in float is 10.24000072479248046875, 7.1e-8 off
    // relative, more than one rounding (2^-24 ≈ 6.0e-8) can make.
    const DiffStep& first = result.steps[*result.first];
    CHECK(first.path == "SS");
    REQUIRE(first.components.size() == 1);
    const DiffComponent& c = first.components[0];
    CHECK(c.a.text == "10.240001");
    CHECK(typed_number_text(c.a.exact, Language::en) == "10.24000072479248046875");
    CHECK(c.digits == 7);
    CHECK(c.relative == Approx(7.078e-8).epsilon(1e-3));
    CHECK(c.tolerance == std::ldexp(1.0, -24));
    CHECK_FALSE(c.within);
    CHECK(step_of(result, "E").status == DiffStatus::agree);
    CHECK(step_of(result, "C").status == DiffStatus::agree);
}

TEST_CASE("A relative tolerance replaces the sides' precision") {
    const DiffInput a = input(trace_json(RealType::float_)), b = input(trace_json(RealType::quad_));
    DiffOptions loose;
    loose.relative_tolerance = 1e-6;
    CHECK_FALSE(diff(a, b, loose).first);
    DiffOptions tight;
    tight.relative_tolerance = 0;
    CHECK(diff(a, b, tight).steps[*diff(a, b, tight).first].path == "SS");
}

TEST_CASE("A student's numbers: as typed, to the digits typed, with a decimal comma") {
    const DiffInput trace = input(trace_json(RealType::double_), "t.json");
    // C = 6.4000000000000004, t = 1.0580085…, P = (0.13225…, 0.13225…, 2.11601…)
    const DiffResult right = diff(trace, input("C = 6,4\nt = 1,06\nP.z = 2,116\n", "s.txt"));
    CHECK_FALSE(right.first);
    CHECK(right.common == 3);
    CHECK(step_of(right, "t").components[0].digits == 3);
    CHECK(step_of(right, "P").components.size() == 1);
    CHECK(step_of(right, "P").components[0].component == 'z');
    CHECK(step_of(right, "EE").status == DiffStatus::only_a);  // a step the student skipped

    // t = 1,05 is off by more than half a unit in its last digit.
    const DiffResult wrong = diff(input("C = 6,4\nt = 1,05\nK_len = 2,0\n", "s.txt"), trace);
    REQUIRE(wrong.first);
    CHECK(wrong.steps[*wrong.first].path == "t");
    CHECK(wrong.steps[*wrong.first].components[0].a.text == "1.05");
    CHECK(step_of(wrong, "K_len").status == DiffStatus::agree);
    // The trace's order leads: its steps, then where it has them, the student's.
    CHECK(wrong.steps.front().path == "E");
}

TEST_CASE("Shapes, group paths and a branch that the other side missed") {
    const DiffInput trace = input(trace_json(RealType::double_));
    CHECK(step_of(diff(trace, input("P = 0,13\n")), "P").status == DiffStatus::shape);

    // A student's numbers for a scene with groups: paths such as sphere[1].t.
    const DiffResult groups = diff(input(R"({"sphere[0].t": "1.5", "light[0].D": "0.25"})"),
                                   input("sphere[0].t = 1,5\nlight[0].D = 0,4\n"));
    REQUIRE(groups.first);
    CHECK(groups.steps[*groups.first].path == "light[0].D");
    CHECK(step_of(groups, "sphere[0].t").status == DiffStatus::agree);

    // A miss against a hit: the hit's steps are only in its trace.
    const DiffResult branches = diff(input(trace_json(RealType::double_, 0, 0)), input(trace_json(RealType::double_, 0, 0)));
    CHECK_FALSE(branches.first);
    const DiffResult miss_hit = diff(input("t = 1\n"), input(R"({"C": "6.4"})"));
    CHECK(step_of(miss_hit, "t").status == DiffStatus::only_a);
    CHECK(step_of(miss_hit, "C").status == DiffStatus::only_b);
    CHECK(miss_hit.common == 0);
    CHECK_FALSE(miss_hit.first);
}

TEST_CASE("Two students' files must each name one pixel") {
    const DiffInput several = input("[3,4]\nC = 6,4\n[0,0]\nC = 5,7\n");
    CHECK_THROWS_AS(diff(several, input("C = 6,4\n")), InputError);
    // Against a trace the trace's pixel is taken.
    const DiffResult result = diff(input(trace_json(RealType::double_)), several);
    CHECK(result.common == 1);
    CHECK_FALSE(result.first);
}

TEST_CASE("The report and the JSON name the first divergence") {
    const DiffInput a = input(trace_json(RealType::float_), "a.json"), b = input(trace_json(RealType::quad_), "b.json");
    const DiffResult result = diff(a, b);
    const std::string en = diff_report(result, a, b, {}, builtin_vocabulary(), Language::en);
    CHECK_THAT(en, Catch::Contains("First divergence: SS (|S|²): A 10.240001, B 10.240000000000001136868377216160329"));
    CHECK_THAT(en, Catch::Contains("7 significant digits agree"));
    const std::string pl = diff_report(result, a, b, {}, builtin_vocabulary(), Language::pl);
    CHECK_THAT(pl, Catch::Contains("Pierwsza rozbieżność: SS (|S|²): A 10,240001"));
    const std::string json_text = diff_json(result, a, b, {});
    CHECK_THAT(json_text, Catch::Contains("\"first_divergence\":\"SS\""));
    CHECK_THAT(json_text, Catch::Contains("\"agree\":false"));
}
