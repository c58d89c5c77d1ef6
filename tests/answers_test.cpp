// Checking a student's numbers: kept as typed, compared exactly in decimal
// to the trace's value rounded half up to the digits the student wrote.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "lesson/answers.hpp"
#include "lesson/lesson_render.hpp"
#include "render/trace_pixel.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

std::vector<PixelTrace> article_traces() {
    const Scene scene = article_scene();
    std::vector<PixelTrace> traces;
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}}) traces.push_back(trace_pixel(scene, 8, i, j));
    return traces;
}

Verdict verdict_of(double reference, const std::string& typed) {
    const std::optional<TypedNumber> number = parse_typed_number(typed);
    REQUIRE(number);
    TypedNumber expected;
    return compare_number(reference, *number, expected);
}

std::vector<AnswerCheck> check_text(const std::string& text, Language language = Language::en) {
    const std::vector<PixelTrace> traces = article_traces();
    return check_answers(parse_answers(text, "a.txt", builtin_vocabulary(), language, {0, 0}, 8), traces);
}

// The line of the fault parse_answers reports, or "" when it accepts the file.
std::string fault_of(const std::string& text) {
    try {
        parse_answers(text, "a.txt", builtin_vocabulary(), Language::en, {0, 0}, 8);
    } catch (const InputError& error) {
        CHECK(error.file == "a.txt");
        return error.where.empty() ? "(no line)" : error.where;
    }
    return "";
}

// A number rounded to `decimals` as a student would write it: fmt's rounding,
// independent of the checker's (the article's pixels have no exact tie at the
// decimals used here, where fmt's halves-to-even would differ).
std::string answers_written(double value, int decimals, Language language) {
    std::string text = fmt::format("{:.{}f}", value, decimals);
    if (language == Language::pl) {
        if (text.front() == '-') text.replace(0, 1, "\u2212");
        for (char& c : text)
            if (c == '.') c = ',';
    }
    return text;
}

// An answer file with every number of the three pixels, rounded to `decimals`.
std::string answer_file(const std::vector<PixelTrace>& traces, int decimals, Language language) {
    std::string out = "# every number, rounded\n";
    for (const PixelTrace& trace : traces) {
        out += fmt::format("[{},{}]\n", trace.header.i, trace.header.j);
        for (const Step& step : trace.steps) {
            std::string value;
            if (const Vec3d* v = std::get_if<Vec3d>(&step.value)) {
                const char* separator = language == Language::pl ? "; " : ", ";
                value = "(" + answers_written(v->x, decimals, language) + separator + answers_written(v->y, decimals, language) + separator +
                        answers_written(v->z, decimals, language) + ")";
            } else {
                value = answers_written(std::get<double>(step.value), decimals, language);
            }
            out += fmt::format("{} = {}   # step\n", key_name(step.key), value);
        }
        out += "I_P = " + answers_written(trace.result, decimals, language) + "\n\n";
    }
    return out;
}

}  // namespace

TEST_CASE("numbers are read as typed, in either language's style", "[answers]") {
    const std::optional<TypedNumber> comma = parse_typed_number("6,40");
    REQUIRE(comma);
    CHECK(comma->digits == "640");
    CHECK(comma->scale == 2);
    CHECK_FALSE(comma->negative);
    const std::optional<TypedNumber> minus = parse_typed_number("\u22124.5e-3");  // the Polish minus sign
    REQUIRE(minus);
    CHECK(minus->negative);
    CHECK(minus->digits == "45");
    CHECK(minus->scale == 4);
    CHECK(parse_typed_number("-0.5")->negative);
    CHECK(parse_typed_number("1e3")->scale == -3);
    CHECK(parse_typed_number(",5")->scale == 1);
    for (const char* bad : {"", "-", "abc", "1,2,3", "1.", "--1", "1 000", "1e", "6,4x", "0x10", "inf", "1e-9999"}) {
        INFO(bad);
        CHECK_FALSE(parse_typed_number(bad));
    }
    CHECK(typed_number_text(*parse_typed_number("-04,50"), Language::pl) == "\u22124,50");
    CHECK(typed_number_text(*parse_typed_number("-0.000"), Language::en) == "0.000");
    CHECK(typed_number_text(*parse_typed_number("1.5e3"), Language::en) == "1500");
}

TEST_CASE("right means the value rounded half up to the student's digits, exactly", "[answers]") {
    // 4.03125 is exact in binary: at 4 decimals a true tie, which rounds up.
    CHECK(verdict_of(4.03125, "4.0313") == Verdict::right);
    CHECK(verdict_of(4.03125, "4,0313") == Verdict::right);
    CHECK(verdict_of(4.03125, "4.0312") == Verdict::wrong_way);
    CHECK(verdict_of(4.03125, "4.0314") == Verdict::wrong);  // off by one, but no rounding of 4.03125
    CHECK(verdict_of(4.03125, "4.031") == Verdict::right);
    CHECK(verdict_of(4.03125, "4.032") == Verdict::wrong_way);
    CHECK(verdict_of(4.03125, "4.03125000") == Verdict::right);
    CHECK(verdict_of(4.03125, "4.03124") == Verdict::wrong);  // exact at this precision: no other neighbour
    CHECK(verdict_of(4.03125, "4") == Verdict::right);
    CHECK(verdict_of(4.03125, "5") == Verdict::wrong_way);
    // Halves away from zero for negative numbers.
    CHECK(verdict_of(-4.03125, "-4.0313") == Verdict::right);
    CHECK(verdict_of(-4.03125, "\u22124,0313") == Verdict::right);
    CHECK(verdict_of(-4.03125, "-4.0312") == Verdict::wrong_way);
    CHECK(verdict_of(-4.03125, "4.0313") == Verdict::wrong);
    CHECK(verdict_of(0.125, "0.13") == Verdict::right);
    CHECK(verdict_of(2.5, "3") == Verdict::right);
    CHECK(verdict_of(2.5, "2") == Verdict::wrong_way);
    // 0.1 is stored as 0.1000000000000000055511151231257827...: exactness shows at 17 and more decimals.
    CHECK(verdict_of(0.1, "0.1") == Verdict::right);
    CHECK(verdict_of(0.1, "0.10000000000000001") == Verdict::right);
    CHECK(verdict_of(0.1, "0.10000000000000000") == Verdict::wrong_way);
    CHECK(verdict_of(0.1, "0.1000000000000000055511151231257827") == Verdict::right);
    // A tiny value to few decimals is 0, with either sign; exponents count as places.
    CHECK(verdict_of(-1e-9, "0.000") == Verdict::right);
    CHECK(verdict_of(-1e-9, "-0.000") == Verdict::right);
    CHECK(verdict_of(1234.5, "1.2e3") == Verdict::right);
    CHECK(verdict_of(1234.5, "1.3e3") == Verdict::wrong_way);
    TypedNumber expected;
    CHECK(compare_number(4.557812500000004, *parse_typed_number("4,5600"), expected) == Verdict::wrong);
    CHECK(typed_number_text(expected, Language::pl) == "4,5578");
    CHECK(typed_number_text(round_exactly(-8.987187499999997, 2), Language::en) == "-8.99");
}

TEST_CASE("a correct answer file is accepted, in Polish and in English", "[answers]") {
    const std::vector<PixelTrace> traces = article_traces();
    for (const Language language : {Language::pl, Language::en})
        for (const int decimals : {1, 3, 6, 12}) {  // not 2 or 4: 0.125 and 4.03125 would be ties
            const std::string file = answer_file(traces, decimals, language);
            INFO(file);
            const std::vector<AnswerCheck> checks = check_text(file, language);
            std::size_t count = 0;
            for (const PixelTrace& trace : traces) count += trace.steps.size() + 1;
            CHECK(checks.size() == count);  // each step and I_P of a miss, a dark and a lit pixel
            CHECK(all_right(checks));
            for (const AnswerCheck& check : checks)
                if (check.verdict != Verdict::right) FAIL_CHECK(check.answer.key << " = " << check.answer.text);
        }
}

TEST_CASE("a wrong number is pinpointed: which key, which pixel, what was expected at the student's precision", "[answers]") {
    const std::vector<PixelTrace> traces = article_traces();
    const std::string file = "EE = 5,53\n[3,4]\nC = 6,4\ndelta = 4.5600   # a slip\nP = (0.132, 0.132, 2.116)\n[5,1]\nD = -1,98\n";
    const std::vector<AnswerCheck> checks = check_text(file);
    CHECK_FALSE(all_right(checks));
    std::vector<const AnswerCheck*> wrong;
    for (const AnswerCheck& check : checks)
        if (check.verdict != Verdict::right) wrong.push_back(&check);
    REQUIRE(wrong.size() == 1);
    CHECK(wrong[0]->pixel.i == 3);
    CHECK(wrong[0]->pixel.j == 4);
    CHECK(wrong[0]->answer.key == "delta");
    CHECK(wrong[0]->answer.line == 4);
    CHECK(wrong[0]->verdict == Verdict::wrong);
    REQUIRE(wrong[0]->expected.size() == 1);
    CHECK(typed_number_text(wrong[0]->expected[0], Language::en) == "4.5578");
    const std::string en = answers_report(checks, traces, builtin_vocabulary(), Language::en);
    INFO(en);
    CHECK(en.find("pixel (3, 4)") != std::string::npos);
    CHECK(en.find("✗ Δ/4 (delta) = 4.5600: wrong; rounded to as many decimals, it is 4.5578") != std::string::npos);
    CHECK(en.find("✓ |E|² (EE) = 5,53: right") != std::string::npos);
    CHECK(en.find("Right: 4 of 5; wrong: 1") != std::string::npos);
    const std::string pl = answers_report(checks, traces, builtin_vocabulary(), Language::pl);
    INFO(pl);
    CHECK(pl.find("✗ Δ/4 (delta) = 4.5600: źle; z tą samą liczbą cyfr po przecinku powinno być 4,5578") != std::string::npos);
}

TEST_CASE("rounding the wrong way, a value the pixel never reached, the wrong shape, a blank", "[answers]") {
    const std::vector<PixelTrace> traces = article_traces();
    const std::vector<AnswerCheck> checks =
        check_text("[3,4]\nEE = 4,0312\ndelta = 4.5579\nt = 1\nK = 3\nP.x = 0,132\n[0,0]\nt = 1,2\nE = 1\n[5,1]\nD =\n");
    REQUIRE(checks.size() == 8);
    // In derivation order within each pixel, the pixels in the file's order.
    const auto verdict = [&](int i, const std::string& key) {
        for (const AnswerCheck& check : checks)
            if (check.pixel.i == i && check.answer.key == key) return check.verdict;
        FAIL("no check of " << key);
        return Verdict::right;
    };
    CHECK(checks[0].answer.key == "EE");
    CHECK(checks[0].pixel.i == 3);
    CHECK(verdict(3, "EE") == Verdict::wrong_way);  // 4.03125: a tie, rounds up to 4.0313
    CHECK(verdict(3, "delta") == Verdict::wrong_way);  // 4.5578125...: rounds down to 4.5578
    CHECK(verdict(3, "t") == Verdict::right);          // 1.058... to no decimals
    CHECK(verdict(3, "K") == Verdict::wrong_shape);
    CHECK(verdict(3, "P") == Verdict::right);  // P.x
    CHECK(verdict(0, "t") == Verdict::not_reached);
    CHECK(verdict(0, "E") == Verdict::wrong_shape);
    CHECK(verdict(5, "D") == Verdict::blank);
    CHECK_FALSE(all_right(checks));
    const std::string report = answers_report(checks, traces, builtin_vocabulary(), Language::en);
    INFO(report);
    CHECK(report.find("✗ |E|² (EE) = 4,0312: rounded the wrong way; 4.03125 rounds to 4.0313 (halves up)") != std::string::npos);
    CHECK(report.find("✗ t = 1,2: pixel (0, 0) has no such value") != std::string::npos);
    CHECK(report.find("· N·K (D): left blank") != std::string::npos);
    const std::string polish = answers_report(checks, traces, builtin_vocabulary(), Language::pl);
    CHECK(polish.find("źle zaokrąglone; 4,03125 zaokrągla się do 4,0313") != std::string::npos);
    CHECK(all_right(check_text("[5,1]\nD =\nC = 6,4\n")));  // blanks are not wrong
}

TEST_CASE("a malformed answer file is refused with its line", "[answers]") {
    CHECK(fault_of("C = 6,4\n# fine\n\nP = (0,1, 0,2, 3)\n") == "line 4");  // decimal commas need semicolons
    CHECK(fault_of("C = 6,4\nX = 3\n") == "line 2");                       // unknown key
    CHECK(fault_of("\n\nC 6,4\n") == "line 3");                             // no =
    CHECK(fault_of("C = six\n") == "line 1");
    CHECK(fault_of("C = 6,4\n[3;4]\n") == "line 2");                        // a heading reads [i,j]
    CHECK(fault_of("[8,0]\nC = 6,4\n") == "line 1");                        // outside the 8 × 8 pane
    CHECK(fault_of("C = 6,4\nC = 6,40\n") == "line 2");                     // twice for one pixel
    CHECK(fault_of("# nothing\n\n") == "(no line)");                        // no answer at all
    CHECK(fault_of("C = \nEE =\n") == "(no line)");
    CHECK(fault_of("{\"C\": 6.4,\n \"EE\": }\n") == "line 2");              // JSON syntax
    CHECK(fault_of("C.x = 6,4\n") == "line 1");                            // C is one number: no component
    CHECK(fault_of("{\"C\": true}") == "/C");
    CHECK(fault_of("{\"Cee\": 6.4}") == "/Cee");
    CHECK(fault_of("[3,4]\nC = 6,4\r\nEE = (1; 2; 3)\n# comment\n").empty());  // CRLF, and EE's shape is checked later
    try {
        parse_answers("C = 6,4\nX = 3\n", "a.txt", builtin_vocabulary(), Language::pl, {0, 0}, 8);
        FAIL("accepted");
    } catch (const InputError& error) {
        CHECK(error.where == "linia 2");
        CHECK(std::string(error.what()).find("nieznany klucz „X”") != std::string::npos);
    }
}

TEST_CASE("JSON answers: a flat object with numbers as typed, and a whole trace", "[answers]") {
    const std::vector<PixelTrace> traces = article_traces();
    const std::vector<PixelAnswers> flat = parse_answers(R"({"C": 6.40, "delta": "4,5578", "P": [0.132, "0,132", 2.116], "EE": 4})",
                                                         "a.json", builtin_vocabulary(), Language::en, {3, 4}, 8);
    REQUIRE(flat.size() == 1);
    CHECK(flat[0].pixel.i == 3);
    REQUIRE(flat[0].answers.size() == 4);
    CHECK(flat[0].answers[0].text == "6.40");  // as typed: two decimals
    CHECK(flat[0].answers[0].numbers[0].scale == 2);
    CHECK(all_right(check_answers(flat, traces)));
    for (const PixelTrace& trace : traces) {
        std::string json_text;
        append_trace_json(json_text, trace);
        const std::vector<PixelAnswers> whole = parse_answers(json_text, "t.json", builtin_vocabulary(), Language::pl, {0, 0}, 8);
        REQUIRE(whole.size() == 1);
        CHECK(whole[0].pixel.i == trace.header.i);
        CHECK(whole[0].pixel.j == trace.header.j);
        CHECK(whole[0].answers.size() == trace.steps.size() + 1);  // and the result, I_P
        const std::vector<AnswerCheck> checks = check_answers(whole, traces);
        CHECK(all_right(checks));
        CHECK(std::all_of(checks.begin(), checks.end(), [](const AnswerCheck& c) { return c.verdict == Verdict::right; }));
    }
    // Another pane's trace is not this lesson's.
    std::string json_text;
    append_trace_json(json_text, trace_pixel(article_scene(), 16, 3, 4));
    CHECK(fault_of(json_text) == "/w");
}

TEST_CASE("answers name values inside groups: sphere[1].t = 1.85, light[0].sphere[0].s_1, and a whole general trace",
          "[answers]") {
    Scene scene;
    scene.name = "shadows";
    scene.spheres = {Sphere{{0, 0, 3.2}, 1.1}, Sphere{{0.9, 0.4, 4.6}, 1.3}};
    scene.planes = {Plane{{0, -1.1, 0}, {0, 1, 0}}};
    scene.lights = {Light{{1.5, 3, 1}, 1}};
    scene.shadows = true;
    const std::vector<PixelTrace> traces = {trace_pixel(scene, 8, 7, 2), trace_pixel(scene, 8, 3, 4)};
    REQUIRE(traces[0].branch == Branch::shadowed);
    const auto value_of = [&](const PixelTrace& trace, const std::string& path) { return std::get<double>(*lesson_value(trace, path)); };
    const double s1 = value_of(traces[0], "light[0].sphere[0].s_1");
    const double t1 = value_of(traces[1], "sphere[1].t");
    const std::string text = fmt::format(
        "[7,2]\nlight[0].sphere[0].s_1 = {}\nplane[0].t_plane = 1,2571\nt_hit = 1.2571\nlight[0].K.y = 4,1\n"
        "[3,4]\nsphere[1].t = {}\nsphere[0].t = 9\nlight[0].plane[0].s =\n",
        answers_written(s1, 4, Language::en), answers_written(t1, 3, Language::pl));
    const std::vector<AnswerCheck> checks =
        check_answers(parse_answers(text, "a.txt", builtin_vocabulary(), Language::en, {7, 2}, 8), traces);
    REQUIRE(checks.size() == 7);
    // In the order of the derivation: the objects' tests, then the nearest, then the light.
    CHECK(checks[0].answer.key == "plane[0].t_plane");
    CHECK(checks[1].answer.key == "t_hit");
    CHECK(checks[2].answer.key == "light[0].K");
    CHECK(checks[2].answer.component == 'y');
    CHECK(checks[3].answer.key == "light[0].sphere[0].s_1");
    for (std::size_t k = 0; k < 4; ++k) CHECK(checks[k].verdict == Verdict::right);
    CHECK(checks[4].answer.key == "sphere[0].t");
    CHECK(checks[4].verdict == Verdict::wrong);
    CHECK(checks[5].answer.key == "sphere[1].t");
    CHECK(checks[5].verdict == Verdict::right);
    CHECK(checks[6].verdict == Verdict::blank);
    const std::string report = answers_report(checks, traces, builtin_vocabulary(), Language::en);
    INFO(report);
    CHECK(report.find("✓ s₁ (light[0].sphere[0].s_1) = " + answers_written(s1, 4, Language::en) + ": right") != std::string::npos);
    // A word is shown filled in: there is nothing to check.
    CHECK(fault_of("nearest = sphere 0\n") == "line 1");
    CHECK(fault_of("cone[0].t = 1\n") == "line 1");
    CHECK(fault_of("sphere[0].D = 1\n") == "line 1");     // a sphere's test has no D
    CHECK(fault_of("{\"sphere[0].t\": 1.06}").empty());
    // A whole trace of a general scene: every number, in its group, is right.
    for (const PixelTrace& trace : traces) {
        std::string json_text;
        append_trace_json(json_text, trace);
        const std::vector<PixelAnswers> whole = parse_answers(json_text, "t.json", builtin_vocabulary(), Language::en, {0, 0}, 8);
        REQUIRE(whole.size() == 1);
        std::size_t numbers = 1;  // and I_P
        for (const Step& step : trace.steps) numbers += std::holds_alternative<std::string>(step.value) ? 0 : 1;
        CHECK(whole[0].answers.size() == numbers);
        const std::vector<AnswerCheck> all = check_answers(whole, traces);
        CHECK(std::all_of(all.begin(), all.end(), [](const AnswerCheck& c) { return c.verdict == Verdict::right; }));
    }
}
