// The answer checker as a pupil uses it: a bad line is one unreadable
// answer (the rest are checked), fractions are numbers, and a value typed
// with more digits than the run's type holds is judged by its distance to
// the exact value (the same pixel and formula in quad).
#include <catch2/catch.hpp>

#include <cstdint>
#include <quadmath.h>

#include <fmt/format.h>

#include "lesson/answers.hpp"
#include "lesson/lesson_render.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "trace/keys.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

const std::vector<std::string> lesson_keys_for_test = {"EE", "C", "delta", "t", "P"};

AnswerLimits forgiving(int w = 8) {
    AnswerLimits limits;
    limits.w = w;
    limits.settings = true;
    limits.forgiving = true;
    limits.keys = lesson_keys_for_test;
    return limits;
}

std::vector<PixelAnswers> read(const std::string& text, Language language = Language::en, int w = 8) {
    return read_answers(text, "a.txt", builtin_vocabulary(), language, {3, 4}, forgiving(w)).pixels;
}

// The traces of the pixels the answers name, in double, and the same pixels in quad (the exact values).
struct ForgivingTraced {
    std::vector<PixelTrace> traces, exact;
};

ForgivingTraced traced(const std::vector<PixelAnswers>& answers, int w = 8) {
    const Scene scene = article_scene();
    const TraceHeader header = trace_header(scene, w);
    const std::unique_ptr<Kernel> quad_kernel = make_kernel(scene, RealType::quad_, Formula::article, 1);
    ForgivingTraced out;
    for (const PixelAnswers& pixel : answers) {
        out.traces.push_back(trace_pixel(scene, w, pixel.pixel.i, pixel.pixel.j));
        out.exact.push_back(quad_kernel->trace(header, pixel.pixel.i, pixel.pixel.j));
    }
    return out;
}

std::vector<AnswerCheck> check_forgiving(const std::string& text, Language language = Language::en, int w = 8) {
    const std::vector<PixelAnswers> answers = read(text, language, w);
    const ForgivingTraced t = traced(answers, w);
    return check_answers(answers, t.traces, t.exact);
}

Verdict forgiving_verdict_of(const std::vector<AnswerCheck>& checks, int line) {
    for (const AnswerCheck& c : checks)
        if (c.answer.line == line) return c.verdict;
    FAIL("no answer at line " << line);
    return Verdict::right;
}

bool right(Verdict v) { return v == Verdict::right || v == Verdict::right_more_digits || v == Verdict::right_nearer; }

// The fault a forgiving read still refuses the file for, or "" when it reads it.
std::string refused(const std::string& text) {
    try {
        read(text);
    } catch (const InputError& error) {
        return error.where.empty() ? "(no line)" : error.where;
    }
    return "";
}

std::string report_of(const std::string& text, Language language) {
    const std::vector<PixelAnswers> answers = read(text, language);
    const ForgivingTraced t = traced(answers);
    std::string report = answers_report(check_answers(answers, t.traces, t.exact), t.traces, builtin_vocabulary(), language, t.exact);
    // An unreadable answer's lines fit 80 columns; a long one goes on, indented, on the next.
    std::size_t start = 0;
    for (std::size_t end; (end = report.find('\n', start)) != std::string::npos; start = end + 1) {
        const std::string line = report.substr(start, end - start);
        if (line.find("unreadable") == std::string::npos && line.find("nieczytelne") == std::string::npos &&
            line.rfind("    ", 0) != 0)
            continue;
        std::size_t width = 0;
        for (const char c : line) width += (static_cast<unsigned char>(c) & 0xC0u) != 0x80u;
        CHECK(width <= 80);
    }
    for (std::size_t at; (at = report.find("\n    ")) != std::string::npos;) report.replace(at, 5, " ");
    return report;
}

// ±1 in the last digit of a decimal text ("-0.0120" -> "-0.0121" or "-0.0119").
std::string nudged(const std::string& text, int by) {
    const bool negative = text.front() == '-';
    std::string digits = text.substr(negative ? 1 : 0);
    const std::size_t point = digits.find('.');
    const std::size_t decimals = point == std::string::npos ? 0 : digits.size() - point - 1;
    if (point != std::string::npos) digits.erase(point, 1);
    std::int64_t magnitude = std::stoll(digits) + (negative ? -by : by);
    const bool flipped = magnitude < 0;
    if (flipped) magnitude = -magnitude;
    std::string out = std::to_string(magnitude);
    if (out.size() < decimals + 1) out.insert(0, decimals + 1 - out.size(), '0');
    if (decimals > 0) out.insert(out.size() - decimals, ".");
    return ((negative != flipped) && magnitude != 0 ? "-" : "") + out;
}

int significant(const std::string& text) {
    std::string digits;
    for (const char c : text)
        if (c >= '0' && c <= '9') digits += c;
    const std::size_t first = digits.find_first_not_of('0');
    return first == std::string::npos ? 0 : static_cast<int>(digits.size() - first);
}

}  // namespace

TEST_CASE("a bad line is one unreadable answer: the rest are checked", "[answers][forgiving]") {
    // Line 2 right, line 3 an unknown key, lines 4 and 5 the same key twice, line 6 wrong.
    const std::string text = "[3,4]\nC = 6,40\ndetla = 4,5\nEE = 4,03125\nEE = 4.03\nt = 9\n";
    const std::vector<AnswerCheck> checks = check_forgiving(text);
    REQUIRE(checks.size() == 5);
    CHECK(forgiving_verdict_of(checks, 2) == Verdict::right);
    CHECK(forgiving_verdict_of(checks, 3) == Verdict::unreadable);
    CHECK(forgiving_verdict_of(checks, 4) == Verdict::unreadable);  // right, but which of the two counts?
    CHECK(forgiving_verdict_of(checks, 5) == Verdict::unreadable);
    CHECK(forgiving_verdict_of(checks, 6) == Verdict::wrong);
    CHECK_FALSE(all_right(checks));
    const std::string en = report_of(text, Language::en);
    INFO(en);
    CHECK(en.find("✓ E·S (C) = 6,40: right") != std::string::npos);
    CHECK(en.find("✗ line 3: detla = 4,5: unreadable: unknown key 'detla'; did you mean 'delta'? "
                  "This lesson's keys: EE, C, delta, t, P\n") != std::string::npos);
    CHECK(en.find("✗ line 4: EE = 4,03125: unreadable: \"EE\" for pixel (3, 4) is given more than once (lines 4, 5)") !=
          std::string::npos);
    CHECK(en.find("✗ line 5: EE = 4.03: unreadable: \"EE\" for pixel (3, 4) is given more than once (lines 4, 5)") !=
          std::string::npos);
    CHECK(en.find("✗ t = 9: wrong") != std::string::npos);
    CHECK(en.find("Right: 1 of 5; wrong: 1; left blank: 0. Unreadable: 3.") != std::string::npos);
    const std::string pl = report_of(text, Language::pl);
    INFO(pl);
    CHECK(pl.find("✗ linia 3: detla = 4,5: nieczytelne: nieznany klucz „detla”; czy chodziło o „delta”?") != std::string::npos);
    CHECK(pl.find("podano więcej niż raz (linie 4, 5)") != std::string::npos);
    CHECK(pl.find("Nieczytelne: 3.") != std::string::npos);
    // Every kind of bad line is unreadable, not the file's end.
    for (const char* bad : {"C 6,4", "C = six", "[3;4]", "[8,0]", "P = (0,1, 0,2, 3)", "C.x = 6,4", "nearest = sphere 0",
                                   "C = 1/0", "delta@double,double = 1"}) {
        const std::vector<AnswerCheck> some = check_forgiving(std::string("t = 9\n") + bad + "\nC = 6,4\n");
        INFO(bad);
        CHECK(forgiving_verdict_of(some, 2) == Verdict::unreadable);
        CHECK(forgiving_verdict_of(some, 1) == Verdict::wrong);
    }
    // Under an unreadable heading, each line says so (it would be checked against the wrong pixel).
    const std::vector<AnswerCheck> under = check_forgiving("C = 6,4\n[3;5]\nt = 1\n");
    CHECK(forgiving_verdict_of(under, 3) == Verdict::unreadable);
    CHECK(under.back().answer.unreadable.find("heading of line 2") != std::string::npos);
}

TEST_CASE("a forgiving read still refuses a file with nothing to read: not UTF-8, too large, broken JSON, no readable line",
          "[answers][forgiving]") {
    CHECK(refused("C = 6,4\nt = 9\n").empty());
    CHECK(refused("C = 6,4\n# caf\xE9\n") == "line 2");         // Latin-1, not UTF-8
    CHECK(refused("C = 6,4\n# \xC0\xAF overlong\n") == "line 2");
    CHECK(refused("C = 6,4\n# \xED\xA0\x80 surrogate\n") == "line 2");
    CHECK(refused("# zażółć − ok\nC = 6,4\n").empty());        // Polish letters and U+2212 are UTF-8
    CHECK(refused("C = 6,4\n" + std::string(max_answer_bytes, '#')) == "(no line)");
    CHECK(refused("{\"C\": 6.4,\n \"EE\": }\n") == "line 2");
    CHECK(refused("detla = 4,5\nX = 1\n") == "line 1");           // nothing readable: refused at the first bad line
    CHECK(refused("C =\n") == "(no line)");
    CHECK(refused("# nothing\n") == "(no line)");
    try {
        read("detla = 4,5\n");
        FAIL("accepted");
    } catch (const InputError& error) {
        CHECK(std::string(error.what()).find("did you mean 'delta'?") != std::string::npos);
        CHECK(std::string(error.what()).find("no answer in the file can be read") != std::string::npos);
    }
}

TEST_CASE("JSON answers forgive too: a key given twice, an unknown key, a fraction", "[answers][forgiving]") {
    const std::vector<PixelAnswers> answers = read(R"({"C": 6.4, "C": 6.5, "detla": 1, "EE": "129/32", "t": 1.06})");
    REQUIRE(answers.size() == 1);
    const ForgivingTraced t = traced(answers);
    const std::vector<AnswerCheck> checks = check_answers(answers, t.traces, t.exact);
    REQUIRE(checks.size() == 4);
    const auto of = [&](const std::string& pointer) {
        for (const AnswerCheck& c : checks)
            if (c.answer.pointer == pointer) return c;
        FAIL("no answer at " << pointer);
        return checks[0];
    };
    CHECK(of("/C").verdict == Verdict::unreadable);
    CHECK(of("/C").answer.unreadable == "\"C\" appears more than once; none of its values is checked");
    CHECK(of("/detla").verdict == Verdict::unreadable);
    CHECK(of("/EE").verdict == Verdict::right);  // 129/32 = 4.03125
    CHECK(of("/t").verdict == Verdict::right);
}

TEST_CASE("fractions are numbers: 1/2, −3/4 with U+2212, inside points with a decimal comma", "[answers][forgiving]") {
    const std::vector<PixelAnswers> answers = read("E.x = \u22123/4\nE = (1/8; \u22120,875; 4/2)\nE.y = [-3, 4]\n");
    REQUIRE(answers.size() == 1);
    REQUIRE(answers[0].answers.size() == 3);
    const Answer& x = answers[0].answers[0];
    REQUIRE(x.over.size() == 1);
    CHECK(x.numbers[0].negative);
    CHECK(x.numbers[0].digits == "3");
    CHECK(x.over[0].digits == "4");
    const Answer& e = answers[0].answers[1];
    REQUIRE(e.numbers.size() == 3);
    REQUIRE(e.over.size() == 3);
    CHECK(e.over[0].digits == "8");
    CHECK(e.over[1].digits.empty());  // 0,875 is no fraction
    CHECK(e.numbers[1].digits == "0875");
    CHECK(e.numbers[1].scale == 3);
    CHECK(e.numbers[1].negative);
    CHECK(answers[0].answers[2].unreadable.size() > 0);  // [-3, 4] is no number
    // Strict reading (promyk diff) knows no fractions.
    CHECK_THROWS_AS(parse_answers("E.x = 1/8\n", "a.txt", builtin_vocabulary(), Language::en, {3, 4}, 8), InputError);

    // E at (3,4) of the 8 × 8 pane is ((2j+1)/w − 1, −(2i+1)/w + 1, 2) = (1/8, 1/8, 2), 0.125 exactly in double.
    const std::vector<AnswerCheck> at34 =
        check_forgiving("[3,4]\nE.x = 1/8\nE = (1/8; 0,125; 4/2)\nE.y = 2/16\nE.z = 2/1\nEE = 1/8\nE.x = 1/7\n");
    CHECK(forgiving_verdict_of(at34, 2) == Verdict::unreadable);  // E.x twice (lines 2 and 7)
    CHECK(forgiving_verdict_of(at34, 3) == Verdict::right);
    CHECK(forgiving_verdict_of(at34, 4) == Verdict::right);
    CHECK(forgiving_verdict_of(at34, 5) == Verdict::right);
    CHECK(forgiving_verdict_of(at34, 6) == Verdict::wrong);
    const std::vector<AnswerCheck> x34 = check_forgiving("[3,4]\nE.x = 1/8\nE.y = 1/7\nEE = 129/32\n");
    CHECK(forgiving_verdict_of(x34, 2) == Verdict::right);
    CHECK(forgiving_verdict_of(x34, 3) == Verdict::wrong);
    CHECK(forgiving_verdict_of(x34, 4) == Verdict::right);  // |E|² = 1/64 + 1/64 + 4
    // −3/4 is x_E of column 0 in a 4 × 4 pane: (2·0+1)/4 − 1.
    const std::vector<AnswerCheck> w4 = check_forgiving("[1,0]\nE.x = \u22123/4\nE.y = \u20133/4\nE = (\u22123/4; 1/4; 2)\n", Language::pl, 4);
    CHECK(forgiving_verdict_of(w4, 2) == Verdict::right);
    CHECK(forgiving_verdict_of(w4, 3) == Verdict::wrong);  // y_E = −3/4 + 1 = 1/4
    CHECK(forgiving_verdict_of(w4, 4) == Verdict::right);
    const std::string pl = report_of("[3,4]\nE.y = 1/7\n", Language::pl);
    INFO(pl);
    CHECK(pl.find("✗ E.y = 1/7: źle; obliczona wartość to 0,125\n") != std::string::npos);
}

TEST_CASE("more digits than a double holds: right when at least as near the exact t as double's t", "[answers][forgiving]") {
    // Pixel (5,1) of the article's 8 × 8 pane: E = (−5/8, −3/8, 2), S = (0, 0, 3.2), r = 1.1 (both as doubles).
    // The true t, independently: the smaller root of |E|²t² − 2(E·S)t + |S|² − r² = 0 in quad from the
    // doubles' exact values: |E|² = 4.53125, E·S = 2·S_z, so t = (2S_z − √(4.53125·r² − 0.53125·S_z²)) / 4.53125.
    const __float128 Sz = 3.2, r = 1.1, EE = 4.53125, a = 0.53125;  // each double's exact value
    const __float128 true_t = (2 * Sz - sqrtq(EE * r * r - a * Sz * Sz)) / EE;
    const PixelTrace double_trace = trace_pixel(article_scene(), 8, 5, 1);
    const double t_double = std::get<double>(*lesson_value(double_trace, "t"));
    CHECK(fmt::format("{}", t_double) == "1.3667504955662138");
    const __float128 nearer = strtoflt128("1.3667504955662156", nullptr), farther = strtoflt128("1.3667504955662120", nullptr);
    REQUIRE(fabsq(nearer - true_t) < fabsq(static_cast<__float128>(t_double) - true_t));
    REQUIRE(fabsq(farther - true_t) > fabsq(static_cast<__float128>(t_double) - true_t));

    const std::vector<AnswerCheck> checks =
        check_forgiving("[5,1]\nt = 1.3667504955662156\nC = 6.4000000000000004\nEE = 4.53125000000000000001\n"
              "delta = 0,042812500000003695\n[5,1]\n");
    CHECK(forgiving_verdict_of(checks, 2) == Verdict::right_more_digits);
    CHECK(forgiving_verdict_of(checks, 5) == Verdict::right);  // double's own digits, rounded as typed
    CHECK(forgiving_verdict_of(checks, 4) == Verdict::wrong);  // |E|² is exactly 4.53125
    CHECK(forgiving_verdict_of(check_forgiving("[5,1]\nt = 1.3667504955662120\n"), 2) == Verdict::wrong);
    CHECK(forgiving_verdict_of(check_forgiving("[5,1]\nt = 1.3667504955662138\n"), 2) == Verdict::right);
    // No more digits than a double holds (15): rounded as before (double's t rounds down to ...621).
    CHECK(forgiving_verdict_of(check_forgiving("[5,1]\nt = 1.36675049556622\n"), 2) == Verdict::wrong_way);
    // 16 digits, nearer the true t: more than a double holds.
    CHECK(forgiving_verdict_of(check_forgiving("[5,1]\nt = 1.366750495566216\n"), 2) == Verdict::right_more_digits);
    // A fraction nearer the true t than double's t, but not double's t: right.
    CHECK(forgiving_verdict_of(check_forgiving("[5,1]\nt = 13667504955662155/10000000000000000\n"), 2) == Verdict::right_nearer);
    // Without the quad trace the 17 digits are wrong against double's t alone, and the check says it needs the exact value.
    const std::vector<PixelAnswers> alone = read("[5,1]\nt = 1.3667504955662156\nC = 6.40000000000000035527\nt_hit = 2\n");
    const std::vector<AnswerCheck> without = check_answers(alone, traced(alone).traces);
    REQUIRE(without.size() == 3);
    CHECK(forgiving_verdict_of(without, 3) == Verdict::right);  // C: double's 6.4 to 20 decimals
    CHECK(forgiving_verdict_of(without, 2) == Verdict::wrong);
    for (const AnswerCheck& c : without) CHECK(c.needs_exact == (c.answer.line == 2));  // t_hit = 2: one digit, rounded
    const std::string en = report_of("[5,1]\nt = 1.3667504955662156\n", Language::en);
    CHECK(en.find("✓ t = 1.3667504955662156: right, and more digits than a double holds") != std::string::npos);
    const std::string pl = report_of("[5,1]\nt = 1,3667504955662156\n", Language::pl);
    CHECK(pl.find("✓ t = 1,3667504955662156: dobrze, i to z większą liczbą cyfr, niż mieści typ double") != std::string::npos);
}

TEST_CASE("property: the computed value typed in full is right, one unit off in its last typed digit is wrong",
          "[answers][forgiving]") {
    const Scene scene = article_scene();
    int checked = 0;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const PixelTrace trace = trace_pixel(scene, 8, i, j);
            std::string full = fmt::format("[{},{}]\n", i, j), near = full;
            std::vector<std::string> off(2, full);
            int line = 1;
            for (const Step& step : trace.steps) {
                std::vector<std::pair<std::string, double>> numbers;
                const std::string key(key_name(step.key));
                if (step.group >= 0) continue;
                if (const double* x = std::get_if<double>(&step.value)) numbers.emplace_back(key, *x);
                if (const Vec3d* v = std::get_if<Vec3d>(&step.value))
                    numbers = {{key + ".x", v->x}, {key + ".y", v->y}, {key + ".z", v->z}};
                for (const auto& [name, value] : numbers) {
                    if (!std::isfinite(value)) continue;
                    // In full: every decimal of the double's binary value (fmt prints it exactly).
                    std::string text = fmt::format("{:.1100f}", value);
                    text.erase(text.find_last_not_of('0') + 1);
                    if (text.back() == '.') text.pop_back();
                    full += name + " = " + text + "\n";
                    // Rounded to d decimals (at most 15 significant digits: a double holds them), and one unit off.
                    const int d = 1 + (line * 7 + i + j) % 12;
                    const std::string rounded = fmt::format("{:.{}f}", value, d);
                    ++line;
                    // fmt rounds an exact tie to even, the checker half up: no ties here.
                    const std::size_t point = text.find('.');
                    const bool tie_possible = point != std::string::npos && text.size() - point - 1 == static_cast<std::size_t>(d + 1);
                    if (significant(rounded) > 15 || tie_possible) continue;
                    near += name + " = " + rounded + "\n";
                    for (const int by : {1, -1})
                        if (significant(nudged(rounded, by)) <= 15) off[by > 0 ? 0 : 1] += name + " = " + nudged(rounded, by) + "\n";
                }
            }
            const std::vector<AnswerCheck> all_full = check_forgiving(full), all_near = check_forgiving(near);
            for (const AnswerCheck& c : all_full) {
                INFO(i << "," << j << " " << c.answer.key << c.answer.component << " = " << c.answer.text);
                CHECK(c.verdict == Verdict::right);
            }
            for (const AnswerCheck& c : all_near) {
                INFO(i << "," << j << " " << c.answer.key << c.answer.component << " = " << c.answer.text);
                CHECK(c.verdict == Verdict::right);
            }
            for (const std::string& text : off)
                for (const AnswerCheck& c : check_forgiving(text)) {
                    INFO(i << "," << j << " " << c.answer.key << c.answer.component << " = " << c.answer.text);
                    CHECK_FALSE(right(c.verdict));
                    ++checked;
                }
        }
    }
    CHECK(checked > 1000);
}
