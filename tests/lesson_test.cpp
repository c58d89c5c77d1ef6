// Lessons: reading the format, checking it, and the numbers a lesson prints.
#include <catch2/catch.hpp>

#include <regex>

#include <fmt/format.h>
#include <set>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/keys.hpp"
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

TEST_CASE("placeholders: keys, components, decimals, symbols, LaTeX braces are not placeholders", "[lesson]") {
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
    CHECK(first_line(with_body("## [a] A\n\n{branch}\n")) == 8);
    CHECK(first_line(with_body("## [a] A\n\n({i}, {j})\n")) == 0);             // prose names the step's pixel
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
        const Lesson lesson = parse_lesson(with_body("## [a] A\n::: pixel\n<{i},{j}> delta={delta:all} t={t:all} D={D:5} d4={delta}\n:::\n"),
                                           "x.md", language, problems);
        REQUIRE(problems.empty());
        const Scene scene = article_scene();
        LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
        for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}})
            view.traces.push_back(trace_pixel(scene, 8, i, j));
        const std::string text = render_step(view, 0);
        INFO(text);
        CHECK(text.find('{') == std::string::npos);
        static const std::regex row(R"(<(\d),(\d)>\s+delta=(\S+)\s+t=(\S+)\s+D=(\S+)\s+d4=(\S+))");
        int rows = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
            const PixelTrace& trace = view.traces.at(static_cast<std::size_t>(rows));
            CHECK(std::stoi((*it)[1]) == trace.header.i);
            CHECK(read_number((*it)[3]) == std::get<double>(*lesson_value(trace, "delta")));
            // {delta} shows 4 significant digits (the lessons' default)
            CHECK((*it)[6] == shown_number(std::get<double>(*lesson_value(trace, "delta")), language, 4));
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
    for (const Lesson& lesson : lessons) {
        const Scene scene = library.scene(lesson.header.scene);
        check_lesson(lesson, builtin_vocabulary(), problems, &scene);
    }
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
                    for (const std::string& key : part.keys) named.insert(path_key(key));
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
        view.digits = lesson.header.digits;  // as promyk lesson sets it
        for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}})
            view.traces.push_back(trace_pixel(scene, 8, i, j));
        for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
            const std::string text = render_step(view, k);
            for (const LessonPart& part : lesson.steps[k].parts) {
                for (const std::string& key : part.keys) {
                    for (const PixelTrace& trace : view.traces) {
                        const auto value = lesson_value(trace, key);
                        if (!value) continue;
                        std::string kind = builtin_vocabulary().find(path_key(key))->kind;
                        if (std::holds_alternative<Vec3d>(*value) && kind != "point" && kind != "vector") kind = "colour";
                        const std::string shown =
                            fmt::format("({}, {}): {}", trace.header.i, trace.header.j,
                                        shown_value_text(*value, kind, lesson.language, lesson.header.digits));
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

// --- groups: several objects and lights ------------------------------------

namespace {

// lessons/scenes/two_spheres.json, built here so that the test does not
// depend on the scene loader.
Scene two_spheres_scene() {
    Scene scene;
    scene.name = "two spheres";
    scene.spheres = {Sphere{{-0.5, -0.2, 3.2}, 0.9}, Sphere{{0.9, 0.4, 4.6}, 1.3}};
    scene.lights = {Light{{1.5, 1, 1}, 1}};
    return scene;
}

// lessons/scenes/shadows.json: a sphere over a floor, a light above, shadows.
Scene shadows_scene() {
    Scene scene;
    scene.name = "shadows";
    scene.spheres = {Sphere{{0, 0, 3.2}, 1.1}};
    scene.planes = {Plane{{0, -1.1, 0}, {0, 1, 0}}};
    scene.lights = {Light{{1.5, 3, 1}, 1}};
    scene.shadows = true;
    return scene;
}

// A step's value by its groups: the trace's own record, not lesson_value.
const StepValue* step_in(const PixelTrace& trace, const std::vector<std::pair<std::string, int>>& groups, Key key) {
    for (const Step& step : trace.steps) {
        if (step.key != key) continue;
        std::vector<std::pair<std::string, int>> chain;
        for (int g = step.group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent)
            chain.insert(chain.begin(), {trace.groups[static_cast<std::size_t>(g)].kind, trace.groups[static_cast<std::size_t>(g)].index});
        if (chain == groups) return &step.value;
    }
    return nullptr;
}

std::string render_first_step(const std::string& body, const Scene& scene, const std::vector<std::pair<int, int>>& pixels,
                              Language language) {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(with_body(body), "x.md", language, problems);
    check_lesson(lesson, builtin_vocabulary(), problems, &scene);
    for (const LessonProblem& problem : problems) FAIL_CHECK(problem.line << ": " << problem.message);
    LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
    for (const auto& [i, j] : pixels) view.traces.push_back(trace_pixel(scene, 8, i, j));
    return render_step(view, 0);
}

}  // namespace

TEST_CASE("placeholders name values inside groups: {sphere[1].t}, {light[0].sphere[1].delta_s:4}", "[lesson]") {
    const std::vector<Placeholder> found =
        find_placeholders("{sphere[1].t} {light[0].sphere[1].delta_s:4} {light[0].K.x:3} {symbol:light[0].D} {t} {sphere[].t} {sphere[1]t}");
    REQUIRE(found.size() == 7);
    CHECK(found[0].name == "t");
    CHECK(found[0].path == "sphere[1].t");
    CHECK(found[1].name == "delta_s");
    CHECK(found[1].path == "light[0].sphere[1].delta_s");
    CHECK(found[1].decimals == 4);
    CHECK(found[2].path == "light[0].K");
    CHECK(found[2].component == 'x');
    CHECK(found[2].decimals == 3);
    CHECK(found[3].symbol);
    CHECK(found[3].name == "D");
    CHECK(found[4].path == "t");
    CHECK_FALSE(found[5].valid);
    CHECK_FALSE(found[6].valid);
    const std::optional<ValuePath> path = parse_value_path("light[0].plane[12].NK");
    REQUIRE(path);
    REQUIRE(path->groups.size() == 2);
    CHECK(path->groups[1].kind == "plane");
    CHECK(path->groups[1].index == 12);
    CHECK(path->key == "NK");
    CHECK_FALSE(parse_value_path("light[0]."));
    CHECK_FALSE(parse_value_path("light[1234567].D"));
    CHECK(path_key("light[0].sphere[1].delta_s") == "delta_s");
}

TEST_CASE("a placeholder in a group shows that group's value, {t_hit} is the top level's, words are translated", "[lesson]") {
    const Scene scene = two_spheres_scene();
    // (3, 4): both spheres are hit and sphere 0 is nearer; (2, 5): only sphere 1.
    const PixelTrace both = trace_pixel(scene, 8, 3, 4);
    REQUIRE(std::get<std::string>(*step_in(both, {}, Key::nearest)) == "sphere 0");
    const double t0 = std::get<double>(*step_in(both, {{"sphere", 0}}, Key::t));
    const double t1 = std::get<double>(*step_in(both, {{"sphere", 1}}, Key::t));
    REQUIRE(t0 < t1);
    const double D = std::get<double>(*step_in(both, {{"light", 0}}, Key::D));
    for (const Language language : {Language::en, Language::pl}) {
        const std::string text = render_first_step(
            "## [a] A\n\nS0 = {sphere[0].S}, r1 = {sphere[1].r}, L0 = {light[0].L}\n\n"
            "::: lit\n<{i},{j}> t0={sphere[0].t} t1={sphere[1].t} t={t_hit} D={light[0].D:5} K.x={light[0].K.x:3} "
            "nearest={nearest} found1={sphere[1].found}\n:::\n",
            scene, {{3, 4}, {2, 5}}, language);
        INFO(text);
        // The block is reflowed to 80 columns: compare with single spaces.
        const std::string flat = std::regex_replace(text, std::regex(R"(\s+)"), " ");
        CHECK(flat.find("t0=" + shown_number(t0, language, 4) + " ") != std::string::npos);
        CHECK(flat.find("t1=" + shown_number(t1, language, 4) + " ") != std::string::npos);
        CHECK(flat.find("t=" + shown_number(t0, language, 4) + " ") != std::string::npos);  // the nearer one
        CHECK(flat.find("D=" + number_text(D, language, 5)) != std::string::npos);
        const Vec3d K = std::get<Vec3d>(*step_in(both, {{"light", 0}}, Key::K));
        CHECK(flat.find("K.x=" + number_text(K.x, language, 3)) != std::string::npos);
        CHECK(flat.find("nearest=" + word_text(language, "sphere 0")) != std::string::npos);
        CHECK(flat.find(language == Language::pl ? "nearest=kula 0" : "nearest=sphere 0") != std::string::npos);
        CHECK(flat.find("found1=" + word_text(language, "near")) != std::string::npos);
        CHECK(flat.find("r1 = " + number_text(1.3, language)) != std::string::npos);
        CHECK(flat.find(language == Language::pl ? "S0 = (−0,5; −0,2; 3,2)" : "S0 = (−0.5, −0.2, 3.2)") != std::string::npos);
        // (2, 5) misses sphere 0: its t0 is not reached, its t is sphere 1's.
        const PixelTrace only = trace_pixel(scene, 8, 2, 5);
        CHECK(flat.find("<2,5> t0=— t1=" + shown_number(std::get<double>(*step_in(only, {{"sphere", 1}}, Key::t)), language, 4)) !=
              std::string::npos);
    }
}

TEST_CASE("value tables take paths, and a shadow ray's tests are nested in their light", "[lesson]") {
    const Scene scene = shadows_scene();
    const PixelTrace shadowed = trace_pixel(scene, 8, 7, 2);
    REQUIRE(shadowed.branch == Branch::shadowed);
    const double s1 = std::get<double>(*step_in(shadowed, {{"light", 0}, {"sphere", 0}}, Key::s_1));
    const std::string text = render_first_step(
        "## [a] A\n= light[0].sphere[0].s_1 light[0].blocker plane[0].NE\n\n::: shadowed\n"
        "s1={light[0].sphere[0].s_1:4} blocker={light[0].blocker}\n:::\n",
        scene, {{7, 2}, {7, 6}}, Language::en);
    INFO(text);
    CHECK(text.find("(7, 2): " + shown_number(s1, Language::en, 4)) != std::string::npos);
    CHECK(text.find("(7, 6): —") != std::string::npos);  // the light is not blocked: the ray missed the sphere
    CHECK(text.find("s₁ (light 0, sphere 0) = ") != std::string::npos);  // the row says whose s₁ it is
    CHECK(text.find("s1=" + number_text(s1, Language::en, 4) + " blocker=sphere 0") != std::string::npos);
    CHECK(text.find("(7, 2): sphere 0") != std::string::npos);
    CHECK(text.find("(7, 6): none") != std::string::npos);
}

TEST_CASE("a path that names no group of the trace is reported at its line, in the lesson's language", "[lesson]") {
    const Scene scene = two_spheres_scene();
    const auto problems_with_scene = [&](const std::string& body, Language language = Language::en) {
        std::vector<LessonProblem> problems;
        const Lesson lesson = parse_lesson(with_body(body), "x.md", language, problems);
        check_lesson(lesson, builtin_vocabulary(), problems, &scene);
        return problems;
    };
    const auto first = [&](const std::string& body) {
        const std::vector<LessonProblem> problems = problems_with_scene(body);
        return problems.empty() ? std::make_pair(0, std::string()) : std::make_pair(problems.front().line, problems.front().message);
    };
    CHECK(first("## [a] A\n::: pixel\n{sphere[1].t} {light[0].sphere[1].delta_s} {light[0].K.x:2}\n:::\n").first == 0);
    CHECK(first("## [a] A\n= sphere[0].t sphere[1].t nearest light[0].D\n").first == 0);
    CHECK(first("## [a] A\n::: shadowed\n{light[0].blocker}\n:::\n").first == 0);  // the branch shadowed
    const auto [cone_line, cone] = first("## [a] A\n::: pixel\nfine\n{cone[0].t}\n:::\n");
    CHECK(cone_line == 9);
    CHECK(cone.find("no group \"cone\"") != std::string::npos);
    const auto [nest_line, nest] = first("## [a] A\n\n= sphere[0].light[0].D\n");
    CHECK(nest_line == 8);
    CHECK(nest.find("sphere[0].light[0].D") != std::string::npos);
    const auto [key_line, key] = first("## [a] A\n::: pixel\n{sphere[0].D}\n:::\n");
    CHECK(key_line == 8);
    CHECK(key.find("no D in sphere[0]") != std::string::npos);
    const auto [index_line, index] = first("## [a] A\n::: pixel\n{sphere[2].t}\n:::\n");
    CHECK(index_line == 8);
    CHECK(index.find("has no sphere[2] (it has 2)") != std::string::npos);
    CHECK(first("## [a] A\n::: pixel\n{sphere[0].nope}\n:::\n").second.find("unknown key \"sphere[0].nope\"") != std::string::npos);
    CHECK(first("## [a] A\n\nt0 = {sphere[0].t}\n").first == 8);  // a pixel's value in prose
    CHECK(first("## [a] A\n\nS0 = {sphere[0].S}, r = {sphere[1].r}, L = {light[0].L}\n").first == 0);  // the scene's
    const std::vector<LessonProblem> pl = problems_with_scene("## [a] A\n::: pixel\n{sphere[0].D}\n:::\n", Language::pl);
    REQUIRE(pl.size() == 1);
    CHECK(pl[0].message.find("w śladzie nie ma D w grupie sphere[0]") != std::string::npos);
}

TEST_CASE("the keys a lesson may name in a group are the keys the tracer records there", "[lesson]") {
    Scene planes = shadows_scene();
    planes.shadows = true;
    planes.planes.push_back(Plane{{0, 0, 6}, {0, 0, 1}});  // seen from its back
    planes.lights.push_back(Light{{-2, 1, 0.5}, 0.5});
    planes.materials = {Material{0.1, 0.7, 0.5, 20}};
    planes.spheres[0].material = 0;
    Scene inside = two_spheres_scene();
    inside.spheres[0] = Sphere{{0, 0, 0.5}, 3};  // the eye inside
    inside.shadows = true;
    for (const Scene& scene : {planes, inside, two_spheres_scene()}) {
        std::set<std::string> seen;
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j) {
                const PixelTrace trace = trace_pixel(scene, 8, i, j);
                for (const Step& step : trace.steps) {
                    std::string path(key_name(step.key));
                    for (int g = step.group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent) {
                        const TraceGroup& group = trace.groups[static_cast<std::size_t>(g)];
                        path = group.kind + "[" + std::to_string(group.index) + "]." + path;
                    }
                    if (!seen.insert(path).second) continue;
                    INFO(scene.name << ": " << path);
                    CHECK(check_path(path, builtin_vocabulary(), &scene).fault == PathFault::none);
                    CHECK(lesson_value(trace, path).has_value());
                }
            }
    }
}

TEST_CASE("a lesson's spp: header is a square, and its numbers come from the centre sample", "[lesson]") {
    const std::string text(good_lesson);
    const auto with_spp = [&](const std::string& spp) {
        return std::regex_replace(text, std::regex("w: 8\n"), "w: 8\nspp: " + spp + "\n");
    };
    std::vector<LessonProblem> problems;
    CHECK(parse_lesson(with_spp("16"), "x.md", Language::en, problems).header.spp == 16);
    CHECK(problems.empty());
    for (const std::string bad : {"3", "0", "2048", "-4", "4.0", "x"}) {
        INFO("spp: " << bad);
        CHECK(first_line(with_spp(bad)) == 6);
    }
    // {delta} reads the centre sample's delta, {I_mean} the top level's mean.
    const PixelTrace trace = trace_pixel(article_scene(), 8, 1, 4, RealType::double_, Formula::article, 4);
    REQUIRE(trace.samples);
    const std::string centre = "sample[" + std::to_string(trace.samples->centre) + "].";
    const auto number = [&](const std::string& path) { return std::get<double>(lesson_value(trace, path).value()); };
    CHECK(number("delta") == number(centre + "delta"));
    CHECK(number("delta") != number("sample[" + std::to_string((trace.samples->centre + 1) % 4) + "].delta"));
    REQUIRE(lesson_value(trace, "I_mean"));
    CHECK(std::get<double>(*lesson_value(trace, "I_mean")) == trace.result);
}
