// Worksheets in HTML (`promyk lesson NAME --worksheet --format html` and the
// web page's worksheet): one labelled <input> a blank, every text escaped,
// well formed, in both languages; the answer file the page saves is the one
// `promyk lesson --answers` reads, and its marks are the checker's.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lesson/answers.hpp"
#include "lesson/answers_run.hpp"
#include "html_check.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_run.hpp"
#include "lesson/worksheet.hpp"
#include "scene/scene_json.hpp"

using namespace promyk;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t k = text.find(what); k != std::string::npos; k = text.find(what, k + 1)) ++n;
    return n;
}

LessonRunOptions html_options(const Lesson& lesson, std::vector<LessonPixel> pixels, LessonFormat format = LessonFormat::html) {
    LessonRunOptions options;
    options.scene_file = lesson.header.scene;
    options.w = lesson.header.w;
    options.pixels = std::move(pixels);
    options.real = lesson_real(lesson);
    options.formula = lesson_formula(lesson);
    options.spp = lesson.header.spp;
    options.digits = lesson.header.digits;
    options.format = format;
    return options;
}

// The worksheet as `lesson --worksheet --format html` prints it: title, intro, steps, form.
std::string worksheet_html(LessonRun& run, Worksheet& worksheet) {
    LessonView& view = run.view();
    std::string out = render_lesson_title(view) + worksheet.intro();
    for (std::size_t k = 0; k < view.lesson.steps.size(); ++k) out += "\n" + worksheet.fields(render_step(view, k));
    return out + worksheet.answer_template() + worksheet.answer_key();
}

const char* const worksheet_hostile_lesson = R"(---
name: hostile
title: <script>alert("t")</script> & 'co'
summary: A & B <b>bold?</b> "quoted"
---

## [first] <img src=x onerror=alert(1)> first

Prose with <script>alert(1)</script>, a & b.

::: dark lit
hit at ({i}, {j}) <iframe> $t = {t}$ and P = {P}, {t} again
:::

= t delta
)";

}  // namespace

TEST_CASE("an HTML worksheet has one labelled input a blank, well formed, in every lesson and both languages",
          "[worksheet][html]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    REQUIRE(problems.empty());
    std::set<Language> languages;
    std::size_t inputs = 0;
    for (const Lesson& lesson : lessons) {
        const Scene scene = library.scene(lesson.header.scene);
        LessonRun run(lesson, scene, html_options(lesson, lesson.header.pixels));
        Worksheet worksheet(run.view());
        const std::string html = worksheet_html(run, worksheet);
        INFO(lesson.file);
        CHECK(html_fault(html) == "");
        // No blank's mark is left, and no formula is left empty by a field taken out of it.
        CHECK(html.find("\xEE\x80\x80") == std::string::npos);
        CHECK(html.find("<span class=\"math\"></span>") == std::string::npos);
        // One field a blank, each with an id of its own and a label for it.
        const std::size_t blanks = worksheet.blanks().size();
        CHECK(count(html, "<input ") == blanks);
        for (const WorksheetBlank& blank : worksheet.blanks()) {
            const std::string id = "blank-" + std::to_string(blank.number);
            CHECK(count(html, "id=\"" + id + "\"") == 1);
            CHECK(count(html, "<label for=\"" + id + "\">") == 1);
        }
        // The label names the place in the lesson's language.
        if (blanks > 0) CHECK(html.find(lesson.language == Language::pl ? ">miejsce 1: " : ">blank 1: ") != std::string::npos);
        // No answer of the lesson is given away.
        CHECK(html.find("<details class=\"answer\"") == std::string::npos);
        inputs += blanks;
        languages.insert(lesson.language);
    }
    CHECK(languages.size() == 2);
    CHECK(inputs > 100);
}

TEST_CASE("a hostile lesson and scene in an HTML worksheet stay text, and a blank in a formula leaves it", "[worksheet][html]") {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(worksheet_hostile_lesson, "en/hostile.md", Language::en, problems);
    REQUIRE(problems.empty());
    const Scene scene = load_scene_text(
        R"({"name": "<script>alert('s')</script> & \"x\"", "z_E": 2, "spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [1.5, 1, 1], "I": 1}]})",
        "evil.json");
    LessonRunOptions options = html_options(lesson, {{3, 4}, {0, 0}});
    options.scene_file = "evil.json";
    LessonRun run(lesson, scene, options);
    Worksheet worksheet(run.view());
    const std::string html = worksheet_html(run, worksheet);
    INFO(html);
    CHECK(html_fault(html) == "");
    for (const char* markup : {"<script", "<img", "<iframe", "<b>"}) CHECK(html.find(markup) == std::string::npos);
    CHECK(html.find("&lt;script&gt;alert(&#39;s&#39;)&lt;/script&gt; &amp; &quot;x&quot;") != std::string::npos);
    // "$t = {t}$": the formula closes before the field and nothing empty is left after it.
    CHECK(html.find("<span class=\"math\">t = </span><span class=\"blank\" data-blank=\"1\"><input ") != std::string::npos);
    // {t} again: the same blank's number, no second field.
    CHECK(count(html, "id=\"blank-1\"") == 1);
    CHECK(html.find("<span class=\"blank-copy\" data-blank=\"1\">..........(1)</span>") != std::string::npos);
    // A point's field says so (three numbers).
    CHECK(html.find("data-kind=\"point\"") != std::string::npos);
}

TEST_CASE("the page's answer file is read by the checker: a right, a wrongly rounded and a wrong answer", "[worksheet][answers]") {
    const LessonLibrary library;
    for (const Language language : {Language::en, Language::pl}) {
        const std::optional<Lesson> lesson = library.find("sphere", language);
        REQUIRE(lesson);
        const Scene scene = library.scene(lesson->header.scene);
        LessonRun run(*lesson, scene, html_options(*lesson, {{3, 4}}));
        Worksheet worksheet(run.view());
        worksheet_html(run, worksheet);
        // Three scalar blanks whose value lies between two 3-decimal neighbours.
        std::vector<const WorksheetBlank*> picked;
        for (const WorksheetBlank& blank : worksheet.blanks()) {
            const double* value = std::get_if<double>(&blank.value);
            if (value && std::isfinite(*value) && blank.real_text.empty() && std::abs(*value) < 1e6 &&
                std::floor(*value * 1000) != *value * 1000)
                picked.push_back(&blank);
            if (picked.size() == 3) break;
        }
        REQUIRE(picked.size() == 3);
        const auto text = [&](long long thousandths) {
            const std::string plain = fmt::format("{}{}.{:03d}", thousandths < 0 ? "-" : "", std::llabs(thousandths) / 1000,
                                                  static_cast<int>(std::llabs(thousandths) % 1000));
            std::string out = plain;
            if (language == Language::pl) out[out.find('.')] = ',';  // either is read
            return out;
        };
        std::map<int, std::string> typed;
        const auto neighbours = [](double value) {
            const TypedNumber nearest = round_exactly(value, 3);
            const long long n = std::stoll(nearest.digits) * (nearest.negative ? -1 : 1);
            const long long other = static_cast<double>(n) / 1000 < value ? n + 1 : n - 1;
            return std::make_pair(n, other);
        };
        const auto [right, right_other] = neighbours(std::get<double>(picked[0]->value));
        const auto [near, way] = neighbours(std::get<double>(picked[1]->value));
        const auto [third, third_other] = neighbours(std::get<double>(picked[2]->value));
        typed[picked[0]->number] = text(right);
        typed[picked[1]->number] = text(way);
        typed[picked[2]->number] = text(third + 7);
        typed[picked[2]->number].insert(0, "  ");  // spaces around are trimmed
        const std::string file = "# a comment\n" + worksheet.answer_lines(typed);
        INFO(file);
        // Every blank has a line; the typed ones carry their text.
        CHECK(count(file, " = ") == worksheet.blanks().size());
        CHECK(file.find(" = " + text(right) + " ") != std::string::npos);
        const std::vector<AnswerCheck> checks = check_lesson_answers(run, file, "ANSWERS.txt");
        std::map<std::string, Verdict> verdicts;
        for (const AnswerCheck& check : checks) verdicts[qualified_path(check.answer.key, check.answer.component, "")] = check.verdict;
        const auto verdict_of = [&](const WorksheetBlank* blank) { return verdicts.at(qualified_path(blank->key, blank->component, "")); };
        CHECK(verdict_of(picked[0]) == Verdict::right);
        CHECK(verdict_of(picked[1]) == Verdict::wrong_way);
        CHECK(verdict_of(picked[2]) == Verdict::wrong);
        std::size_t blank = 0;
        for (const AnswerCheck& check : checks) blank += check.verdict == Verdict::blank ? 1 : 0;
        CHECK(blank + 3 == worksheet.blanks().size());
        // The marks' words are the report's lines.
        const std::string report = answers_report(checks, run.view().traces, run.view().vocabulary, language, run.view().others);
        for (const AnswerCheck& check : checks) {
            const AnswerMark mark = answer_mark(check, &run.view().traces.front(), run.view().vocabulary, language);
            CHECK(report.find(mark.text) != std::string::npos);
            if (check.verdict == Verdict::wrong_way) CHECK(mark.id == "answers_wrong_way");
        }
        (void)right_other;
        (void)near;
        (void)third_other;
    }
}
