// The lesson runner's HTML output (the web page's lessons): every text from a
// lesson or a scene escaped, well formed, and the same numbers as Markdown.
#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <vector>

#include "html_check.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_html.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_run.hpp"
#include "scene/scene_json.hpp"

using namespace promyk;

namespace {

std::string unescaped(std::string text) {
    for (const auto& [entity, c] : std::vector<std::pair<std::string, std::string>>{
             {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}}) {
        for (std::size_t k = text.find(entity); k != std::string::npos; k = text.find(entity, k + c.size()))
            text.replace(k, entity.size(), c);
    }
    return text;
}

// The numbers a reader sees, in order: math ($…$, span.math) and Markdown's
// list markers left out (HTML numbers its lists itself).
std::vector<std::string> html_numbers_of(const std::string& text) {
    static const std::regex number(R"((?:−|-)?\d+(?:[.,]\d+)*(?:e(?:[+-]|−)?\d+)?)");
    std::vector<std::string> out;
    for (std::sregex_iterator it(text.begin(), text.end(), number), end; it != end; ++it) out.push_back(it->str());
    return out;
}

std::vector<std::string> markdown_numbers(std::string markdown) {
    markdown = std::regex_replace(markdown, std::regex(R"(\$[^$\n]+\$)"), " ");
    markdown = std::regex_replace(markdown, std::regex(R"((^|\n) *\d+\. )"), "$1");
    return html_numbers_of(markdown);
}

std::vector<std::string> html_numbers(std::string html) {
    html = std::regex_replace(html, std::regex(R"(<span class="math">[^<]*</span>)"), " ");
    html = std::regex_replace(html, std::regex(R"(<[^>]*>)"), " ");
    return html_numbers_of(unescaped(html));
}

std::string run_lesson(const Lesson& lesson, const Scene& scene, LessonFormat format, std::vector<LessonPixel> pixels,
                       int w = 8) {
    LessonRunOptions options;
    options.scene_file = lesson.header.scene;
    options.w = w;
    options.pixels = std::move(pixels);
    options.real = lesson_real(lesson);
    options.formula = lesson_formula(lesson);
    options.spp = lesson.header.spp;
    options.digits = lesson.header.digits;
    options.format = format;
    LessonRun run(lesson, scene, options);
    return run.document();
}

const char* const hostile_lesson = R"(---
name: hostile
title: <script>alert("t")</script> & 'co'
summary: A & B <b>bold?</b> "quoted"
---

## [first] <img src=x onerror=alert(1)> first

Prose with <script>alert(1)</script>, a & b, "q" and 'a', **bold** and $\frac{a<b}{c}$ and {t}.

= t delta

::: dark lit
hit at ({i}, {j}) <iframe>
:::

::: answer
t = {t} </details><script>x</script>
:::
)";

}  // namespace

TEST_CASE("html_escape and html_inline escape every text and keep TeX as text", "[lesson][html]") {
    CHECK(html_escape(R"(<a href="x">&'</a>)") == "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
    CHECK(html_inline("a **b** *c* `<d>` $x<y$ e * f") ==
          "a <strong>b</strong> <em>c</em> <code>&lt;d&gt;</code> <span class=\"math\">x&lt;y</span> e * f");
    // The article's symbols as it prints them; longer names and words stay text.
    CHECK(html_inline("(t x_E, t y_E, t z_E), I_P; t_hit, max_W, a_Eb, xx_E, x_E2") ==
          "(t x<sub>E</sub>, t y<sub>E</sub>, t z<sub>E</sub>), I<sub>P</sub>; t_hit, max_W, a_Eb, xx_E, x_E2");
    CHECK(html_inline("`x_E` $x_E$ x_E") == "<code>x_E</code> <span class=\"math\">x_E</span> x<sub>E</sub>");
    // An unclosed marker is a character; what opened closes, so the line stays well formed.
    CHECK(html_inline("**open") == "**open");
    CHECK(html_fault(html_prose("- a\n- **b\n\n1. c\n\n```\n<x>\n```\n| a | b |\n|---|---|\n| 1 | <2> |\n")) == "");
    CHECK(html_fault("<p>a & b</p>") != "");  // the checker itself can fail
    CHECK(html_fault("<p><em>a</p></em>") != "");
}

TEST_CASE("a hostile lesson and scene name come out as text, not markup", "[lesson][html]") {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(hostile_lesson, "en/hostile.md", Language::en, problems);
    REQUIRE(problems.empty());
    const Scene scene = load_scene_text(R"({"name": "<script>alert('s')</script> & \"x\"", "z_E": 2, "spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [1.5, 1, 1], "I": 1}]})", "evil.json");
    const std::string html = run_lesson(lesson, scene, LessonFormat::html, {{3, 4}, {0, 0}});
    INFO(html);
    CHECK(html_fault(html) == "");
    for (const char* markup : {"<script", "<img", "<iframe", "<b>", "</details><script"}) CHECK(html.find(markup) == std::string::npos);
    CHECK(html.find("&lt;script&gt;alert(&#39;s&#39;)&lt;/script&gt; &amp; &quot;x&quot;") != std::string::npos);
    CHECK(html.find("&lt;script&gt;alert(&quot;t&quot;)&lt;/script&gt; &amp; &#39;co&#39;") != std::string::npos);
    CHECK(html.find("<span class=\"math\">\\frac{a&lt;b}{c}</span>") != std::string::npos);
    CHECK(html.find("<strong>bold</strong>") != std::string::npos);
    // The answer is behind its reveal, after its step's section.
    CHECK(html.find("<details class=\"answer\" data-step=\"1\"><summary>") > html.find("</section>"));
}

TEST_CASE("every lesson in both languages is well-formed HTML with the Markdown output's numbers", "[lesson][html]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    REQUIRE(problems.empty());
    std::size_t runs = 0;
    for (const Lesson& lesson : lessons) {
        const Scene scene = library.scene(lesson.header.scene);
        // The lesson's own pixels, and each of a miss, a dark and a lit pixel alone.
        for (const std::vector<LessonPixel>& pixels :
             {lesson.header.pixels, std::vector<LessonPixel>{{0, 0}}, {{5, 1}}, {{3, 4}}}) {
            const std::string html = run_lesson(lesson, scene, LessonFormat::html, pixels);
            const std::string markdown = run_lesson(lesson, scene, LessonFormat::markdown, pixels);
            INFO(lesson.file << " pixel (" << pixels.front().i << ", " << pixels.front().j << ")");
            CHECK(html_fault(html) == "");
            const std::vector<std::string> shown = html_numbers(html);
            CHECK(shown.size() > 10);
            CHECK(shown == markdown_numbers(markdown));
            // Each step a section with its number, and as many answers as Markdown has.
            CHECK(std::regex_search(html, std::regex("<section class=\"lesson-step\" data-step=\"" +
                                                     std::to_string(lesson.steps.size()) + "\"")));
            const auto count = [](const std::string& text, const std::string& what) {
                std::size_t n = 0;
                for (std::size_t k = text.find(what); k != std::string::npos; k = text.find(what, k + 1)) ++n;
                return n;
            };
            CHECK(count(html, "<details class=\"answer\"") == count(markdown, "<details>"));
            ++runs;
        }
    }
    CHECK(runs == 4 * lessons.size());
    CHECK(lessons.size() >= 22);
}
