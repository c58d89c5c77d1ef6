// Lessons: reading the format, checking it, and the numbers a lesson prints.
#include <catch2/catch.hpp>

#include <regex>

#include <fmt/format.h>
#include <set>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/messages.hpp"
#include "render/trace_pixel.hpp"

using namespace promyk;

namespace {

const char* const good_lesson = R"(---
name: demo
title: A demo
summary: One line.
w: 8
pixels: 0,0 5,1 3,4
---

## [first] The first step

S = {S}, r = {r}, the pane has {w} × {w} squares; $\sqrt{x^{2}}$ and {{braces}}.

= EE C delta t

::: miss
miss {delta} at ({i}, {j})
:::

::: dark lit
hit {t:6} {P.x:3}
:::

## [exercise] Exercise

Find {symbol:delta}.

::: answer
{delta:2}
:::
)";

std::vector<LessonProblem> problems_of(const std::string& text, Language language = Language::en) {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(text, "x.md", language, problems);
    check_lesson(lesson, builtin_vocabulary(), problems);
    return problems;
}

// The first problem's line, or 0.
int first_line(const std::string& text) {
    const std::vector<LessonProblem> problems = problems_of(text);
    return problems.empty() ? 0 : problems.front().line;
}

std::string with_body(const std::string& body) {
    return "---\nname: demo\ntitle: T\nsummary: S\n---\n" + body;
}

// Reads back a number as a lesson prints it, in either language.
double read_number(std::string text) {
    const std::string minus = "−";
    for (std::size_t at = text.find(minus); at != std::string::npos; at = text.find(minus)) text.replace(at, minus.size(), "-");
    for (char& c : text)
        if (c == ',') c = '.';
    return std::stod(text);
}

}  // namespace

TEST_CASE("a lesson file is read into its header and steps", "[lesson]") {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(good_lesson, "x.md", Language::en, problems);
    CHECK(problems.empty());
    CHECK(lesson.header.name == "demo");
    CHECK(lesson.header.w == 8);
    REQUIRE(lesson.header.pixels.size() == 3);
    CHECK(lesson.header.pixels[1].i == 5);
    CHECK(lesson.header.pixels[1].j == 1);
    REQUIRE(lesson.steps.size() == 2);
    CHECK(lesson.steps[0].id == "first");
    CHECK(lesson.steps[0].line == 9);
    const std::vector<LessonPart>& parts = lesson.steps[0].parts;
    REQUIRE(parts.size() == 4);
    CHECK(parts[0].kind == PartKind::prose);
    CHECK(parts[0].line == 11);
    CHECK(parts[1].kind == PartKind::values);
    CHECK(parts[1].keys == std::vector<std::string>{"EE", "C", "delta", "t"});
    CHECK(parts[2].kind == PartKind::block);
    CHECK(parts[2].branches == std::vector<std::string>{"miss"});
    CHECK(parts[3].branches == std::vector<std::string>{"dark", "lit"});
    CHECK(lesson.steps[1].parts.back().kind == PartKind::answer);
    CHECK(has_answers(lesson.steps[1]));
}

TEST_CASE("placeholders: keys, components, decimals, symbols; LaTeX braces are not placeholders", "[lesson]") {
    const std::vector<Placeholder> found = find_placeholders(R"(a {t} b {P.x:3} {symbol:delta} $\frac{a}{b}$ x^{2} {{t}} {delta:18} {t)");
    REQUIRE(found.size() == 5);
    CHECK(found[0].name == "t");
    CHECK(found[0].decimals == -1);
    CHECK(found[1].name == "P");
    CHECK(found[1].component == 'x');
    CHECK(found[1].decimals == 3);
    CHECK(found[2].symbol);
    CHECK(found[2].name == "delta");
    CHECK_FALSE(found[3].valid);  // 18 decimals: more than a double has
    CHECK_FALSE(found[4].valid);  // not closed
}

TEST_CASE("every kind of broken lesson is reported at its line", "[lesson]") {
    CHECK(first_line("no header\n") == 1);
    CHECK(first_line("---\nname: demo\ntitle: T\n") == 1);                        // header not closed
    CHECK(first_line("---\nname: demo\ntitle: T\ncolour: red\nsummary: S\n---\n## [a] A\n") == 4);
    CHECK(first_line("---\nname: demo\ntitle: T\n---\n## [a] A\n") == 4);          // summary missing
    CHECK(first_line("---\nname: demo\ntitle: T\nsummary: S\nw: 010\n---\n## [a] A\n") == 5);
    CHECK(first_line("---\nname: demo\ntitle: T\nsummary: S\npixels: 3;4\n---\n## [a] A\n") == 5);
    CHECK(first_line("---\nname: demo\ntitle: T\nsummary: S\ncolumns: double/magic\n---\n## [a] A\n") == 5);
    CHECK(first_line("---\nname: demo\ntitle: T\nsummary: S\ncolumns: float/article double/stable\n---\n## [a] A\n") == 0);
    CHECK(first_line(with_body("intro\n## [a] A\n")) == 6);                         // text before the first step
    CHECK(first_line(with_body("## A without an id\n")) == 6);
    CHECK(first_line(with_body("## [a] A\n## [a] B\n")) == 7);                      // the same id twice
    CHECK(first_line(with_body("## [a] A\n\n::: lit\ntext\n")) == 8);              // not closed: where it opened
    CHECK(first_line(with_body("## [a] A\n:::\n")) == 7);                           // closes nothing
    CHECK(first_line(with_body("## [a] A\n::: lit\n::: dark\n:::\n")) == 8);        // nested
    CHECK(first_line(with_body("## [a] A\n= EE nope\n")) == 7);                     // unknown key in a table
    CHECK(first_line(with_body("## [a] A\n\nline\n{nope} here\n")) == 9);           // unknown key in prose
    CHECK(first_line(with_body("## [a] A\n::: lit shaded\n{t}\n:::\n")) == 7);      // unknown branch
    CHECK(first_line(with_body("## [a] A\n\nt is {t}\n")) == 8);                     // a pixel's value outside a block
    CHECK(first_line(with_body("## [a] A\n\n{i}\n")) == 8);
    CHECK(first_line(with_body("## [a] A\n::: pixel\n{t:99}\n:::\n")) == 8);        // malformed placeholder
    CHECK(first_line(with_body("")) != 0);                                          // no step at all
    CHECK(first_line(with_body("## [a] A\n\nS = {S}, w = {w}, {symbol:t}\n::: pixel\n{t} {i} {branch}\n:::\n")) == 0);
}

TEST_CASE("problems are worded in the lesson's language", "[lesson]") {
    const std::string broken = with_body("## [a] A\n= nope\n");
    const std::vector<LessonProblem> pl = problems_of(broken, Language::pl);
    const std::vector<LessonProblem> en = problems_of(broken, Language::en);
    REQUIRE(pl.size() == 1);
    REQUIRE(en.size() == 1);
    CHECK(pl[0].message.find("nieznany klucz „nope”") != std::string::npos);
    CHECK(en[0].message.find("unknown key \"nope\"") != std::string::npos);
}

TEST_CASE("a lesson missing in a language, or with other steps there, is reported", "[lesson]") {
    std::vector<LessonProblem> problems;
    std::vector<Lesson> lessons;
    lessons.push_back(parse_lesson(with_body("## [a] A\n## [b] B\n"), "pl/x.md", Language::pl, problems));
    lessons.push_back(parse_lesson(with_body("## [a] A\n## [c] C\n"), "en/x.md", Language::en, problems));
    lessons.push_back(parse_lesson("---\nname: lonely\ntitle: T\nsummary: S\n---\n## [a] A\n", "pl/y.md", Language::pl, problems));
    REQUIRE(problems.empty());
    check_translations(lessons, problems);
    REQUIRE(problems.size() == 3);
    std::set<std::string> files;
    for (const LessonProblem& problem : problems) files.insert(problem.file);
    CHECK(files == std::set<std::string>{"pl/x.md", "en/x.md", "pl/y.md"});
}

TEST_CASE("the numbers a lesson prints are the trace's, in both languages", "[lesson]") {
    for (const Language language : {Language::en, Language::pl}) {
        std::vector<LessonProblem> problems;
        const Lesson lesson = parse_lesson(with_body("## [a] A\n::: pixel\n<{i},{j}> delta={delta} t={t} D={D:5}\n:::\n"),
                                           "x.md", language, problems);
        REQUIRE(problems.empty());
        const Scene scene = article_scene();
        LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
        for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}})
            view.traces.push_back(trace_pixel(scene, 8, i, j));
        const std::string text = render_step(view, 0);
        INFO(text);
        CHECK(text.find('{') == std::string::npos);
        static const std::regex row(R"(<(\d),(\d)>\s+delta=(\S+)\s+t=(\S+)\s+D=(\S+))");
        int rows = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
            const PixelTrace& trace = view.traces.at(static_cast<std::size_t>(rows));
            CHECK(std::stoi((*it)[1]) == trace.header.i);
            CHECK(read_number((*it)[3]) == std::get<double>(*lesson_value(trace, "delta")));
            if (trace.branch == Branch::miss) {
                CHECK((*it)[4] == "—");
            } else {
                CHECK(read_number((*it)[4]) == std::get<double>(*lesson_value(trace, "t")));
                const double D = std::get<double>(*lesson_value(trace, "D"));
                CHECK(std::abs(read_number((*it)[5]) - D) <= 0.5e-5);
            }
        }
        CHECK(rows == 3);
    }
}

TEST_CASE("every message exists in every language", "[lesson]") {
    CHECK(message_ids(Language::pl) == message_ids(Language::en));
    CHECK(message(Language::en, "pixel_label", {{"i", "3"}, {"j", "4"}}) == "pixel (3, 4)");
    CHECK(message(Language::pl, "pixel_label", {{"i", "3"}, {"j", "4"}}) == "piksel (3, 4)");
}

TEST_CASE("the built-in lessons pass the check and run for a miss, a dark and a lit pixel", "[lesson]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    for (const Lesson& lesson : lessons) check_lesson(lesson, builtin_vocabulary(), problems);
    check_translations(lessons, problems);
    for (const LessonProblem& problem : problems) FAIL_CHECK(problem.file << ":" << problem.line << ": " << problem.message);
    for (const Lesson& lesson : lessons) {
        const Scene scene = library.scene(lesson.header.scene);
        for (const LessonFormat format : {LessonFormat::text, LessonFormat::markdown}) {
            LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
            view.format = format;
            for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}})
                view.traces.push_back(trace_pixel(scene, 8, i, j));
            std::string out = render_lesson_title(view);
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) out += render_step(view, k) + render_answers(view, k);
            INFO(lesson.file);
            // No placeholder is left unresolved (LaTeX braces follow a letter, ^, _ or \).
            for (const Placeholder& placeholder : find_placeholders(out)) FAIL_CHECK("left in the output: " << placeholder.name);
        }
    }
}

TEST_CASE("the built-in lessons name every quantity of the vocabulary, and each explains its pixels' branches",
          "[lesson]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    for (const Language language : {Language::pl, Language::en}) {
        std::set<std::string> named;
        for (const Lesson& lesson : library.lessons(problems)) {
            if (lesson.language != language) continue;
            std::set<std::string> branches;
            bool every_pixel = false;
            for (const LessonStep& step : lesson.steps) {
                for (const LessonPart& part : step.parts) {
                    for (const std::string& key : part.keys) named.insert(key);
                    for (const Placeholder& placeholder : find_placeholders(part.text)) named.insert(placeholder.name);
                    if (part.kind == PartKind::block && part.branches.empty()) every_pixel = true;
                    branches.insert(part.branches.begin(), part.branches.end());
                }
            }
            // A lesson that tells pixels apart tells every branch its pixels take.
            if (branches.empty() && !every_pixel) continue;
            const Scene scene = library.scene(lesson.header.scene);
            for (const LessonPixel& pixel : lesson.header.pixels) {
                const std::string branch(branch_name(trace_pixel(scene, lesson.header.w, pixel.i, pixel.j).branch));
                INFO(lesson.file << ": pixel (" << pixel.i << ", " << pixel.j << ") is " << branch);
                CHECK((every_pixel || branches.count(branch) == 1));
            }
        }
        for (const VocabularyEntry& entry : builtin_vocabulary().keys) {
            INFO("language " << language_code(language) << ", key " << entry.key);
            CHECK(named.count(entry.key) == 1);
        }
    }
}

TEST_CASE("a lesson's value tables show the trace's values", "[lesson]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    for (const Lesson& lesson : library.lessons(problems)) {
        const Scene scene = library.scene(lesson.header.scene);
        LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
        for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}})
            view.traces.push_back(trace_pixel(scene, 8, i, j));
        for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
            const std::string text = render_step(view, k);
            for (const LessonPart& part : lesson.steps[k].parts) {
                for (const std::string& key : part.keys) {
                    for (const PixelTrace& trace : view.traces) {
                        const auto value = lesson_value(trace, key);
                        if (!value) continue;
                        const std::string shown = fmt::format("({}, {}): {}", trace.header.i, trace.header.j,
                                                              value_text(*value, builtin_vocabulary().find(key)->kind,
                                                                         lesson.language));
                        INFO(lesson.file << " step " << k + 1 << ": " << shown);
                        CHECK(text.find(shown) != std::string::npos);
                    }
                }
            }
        }
    }
}

TEST_CASE("every built-in lesson ends with an exercise and its answer", "[lesson]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    for (const Lesson& lesson : library.lessons(problems)) {
        INFO(lesson.file);
        REQUIRE_FALSE(lesson.steps.empty());
        CHECK(lesson.steps.back().id == "exercise");
        CHECK(has_answers(lesson.steps.back()));
    }
}
