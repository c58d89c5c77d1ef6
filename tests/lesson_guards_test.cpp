// Lessons that hold on any pixel and any scene: blocks guarded by values,
// a step's needs, {i},{j} in prose, wildcard rows, scene blocks, the effect
// a scene lacks, the computed figure of the pane, and the formula of I_P
// that the scene's effects call for.
#include <catch2/catch.hpp>

#include <map>
#include <optional>

#include "flat_text.hpp"
#include "geometry/unit_normal.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "parsed_lesson.hpp"
#include "render/trace_pixel.hpp"
#include "trace/intensity_formula.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "trace/trace_text.hpp"

using namespace promyk;

namespace {

std::string guarded_lesson(const std::string& body, const std::string& header = "") {
    return "---\nname: demo\ntitle: T\nsummary: S\n" + header + "---\n" + body;
}

using promyk::testing::parsed;

// A lesson's whole text for the pixels on a scene, as the runner shows it.
struct RunText {
    Scene scene;
    LessonView view;
    std::shared_ptr<std::map<std::pair<int, int>, PixelTrace>> pane = std::make_shared<std::map<std::pair<int, int>, PixelTrace>>();
    RunText(const Lesson& lesson, Scene s, const std::vector<std::pair<int, int>>& pixels, const std::string& file,
            int w = 8)
        : scene(std::move(s)), view{lesson, builtin_vocabulary(), {}, scene.name, w} {
        view.scene = &scene;
        view.scene_file = file;
        view.own_scene = file == lesson.header.scene;
        for (const auto& [i, j] : pixels) view.traces.push_back(trace_pixel(scene, w, i, j));
        auto cache = pane;
        const Scene* traced = &scene;
        view.pane_pixel = [cache, traced, w](int i, int j) -> const PixelTrace& {
            auto at = cache->find({i, j});
            if (at == cache->end()) at = cache->emplace(std::make_pair(i, j), trace_pixel(*traced, w, i, j)).first;
            return at->second;
        };
    }
    std::string text() const {
        std::string out = render_lesson_title(view);
        for (std::size_t k = 0; k < view.lesson.steps.size(); ++k) out += render_step(view, k) + render_answers(view, k);
        return out;
    }
};

Scene example(const std::string& name) { return LessonLibrary().scene(name); }

// The first pixel of the pane, row by row, that takes the branch.
std::pair<int, int> first_of(const Scene& scene, Branch branch, int w = 8) {
    for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j)
            if (trace_pixel(scene, w, i, j).branch == branch) return {i, j};
    return {-1, -1};
}

}  // namespace

TEST_CASE("a block may be guarded by conditions on values: has:, no:, >, <=", "[lesson][guards]") {
    REQUIRE(parse_condition("has:t"));
    CHECK(parse_condition("has:t")->op == Condition::Op::exists);
    CHECK(parse_condition("no:light[0].sphere[0].s_1")->op == Condition::Op::missing);
    CHECK(parse_condition("no:light[0].sphere[0].s_1")->path == "light[0].sphere[0].s_1");
    CHECK(parse_condition("D>0")->op == Condition::Op::greater);
    CHECK(parse_condition("D<=0")->op == Condition::Op::less_equal);
    CHECK(parse_condition("D≤0.5")->bound == 0.5);
    CHECK(parse_condition("light[1].D>=-2")->bound == -2);
    CHECK_FALSE(parse_condition("lit"));
    CHECK_FALSE(parse_condition("D>"));
    CHECK_FALSE(parse_condition("D>0,5"));
    CHECK_FALSE(parse_condition("has:"));

    const Lesson lesson = parsed(
        guarded_lesson("## [a] A\n\n::: pixel D>0\nfacing ({i}, {j})\n:::\n\n::: has:t D<=0\nturned ({i}, {j})\n:::\n\n"
                    "::: no:t\nmissed ({i}, {j})\n:::\n\n::: lit cos_alpha>0.9\nbright ({i}, {j})\n:::\n"));
    REQUIRE(lesson.steps[0].parts.size() == 4);
    CHECK(lesson.steps[0].parts[0].branches.empty());
    CHECK(lesson.steps[0].parts[3].branches == std::vector<std::string>{"lit"});
    // Every pixel of the pane: each block is shown exactly when its condition holds.
    const Scene scene = article_scene();
    std::vector<std::pair<int, int>> all;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) all.emplace_back(i, j);
    const RunText run(lesson, scene, all, "article");
    const std::string text = render_step(run.view, 0);
    for (const PixelTrace& trace : run.view.traces) {
        const std::string at = "(" + std::to_string(trace.header.i) + ", " + std::to_string(trace.header.j) + ")";
        const auto D = lesson_value(trace, "D");
        const bool facing = D && std::get<double>(*D) > 0;
        INFO(at);
        CHECK((text.find("facing " + at) != std::string::npos) == facing);
        CHECK((text.find("turned " + at) != std::string::npos) == (D && !facing));
        CHECK((text.find("missed " + at) != std::string::npos) == (trace.branch == Branch::miss));
        const auto cos = lesson_value(trace, "cos_alpha");
        CHECK((text.find("bright " + at) != std::string::npos) == (trace.branch == Branch::lit && std::get<double>(*cos) > 0.9));
    }
}

TEST_CASE("a step's needs: with no chosen pixel that has them, the step names the first pixel of the pane that does", "[lesson][guards]") {
    for (const Language language : {Language::en, Language::pl}) {
        const Lesson lesson = parsed(guarded_lesson("## [a] A\n\n::: needs lit\n\nFor pixel ({i}, {j}), compute cos α.\n\n"
                                                 "::: answer\ncos α = {cos_alpha:4} at ({i}, {j})\n:::\n"),
                                     language);
        REQUIRE(lesson.steps[0].needs_branches == std::vector<std::string>{"lit"});
        const Scene scene = article_scene();
        // The first lit pixel, row by row.
        std::pair<int, int> first{-1, -1};
        for (int i = 0; i < 8 && first.first < 0; ++i)
            for (int j = 0; j < 8 && first.first < 0; ++j)
                if (trace_pixel(scene, 8, i, j).branch == Branch::lit) first = {i, j};
        REQUIRE(first.first >= 0);
        const std::string hint = "--pixel " + std::to_string(first.first) + "," + std::to_string(first.second);
        {
            const RunText run(lesson, scene, {{0, 0}}, "article");  // a miss only
            const std::string text = flat(render_step(run.view, 0));
            INFO(text);
            CHECK(text.find(hint) != std::string::npos);
            CHECK(text.find("(0, 0)") == std::string::npos);  // the prose naming the step's pixel is left out
            CHECK(render_answers(run.view, 0).empty());
            CHECK(text.find("—") == std::string::npos);
        }
        {
            // The step's pixel is the first chosen one that has its needs: prose and answer agree.
            const RunText run(lesson, scene, {{0, 0}, {5, 1}, {3, 4}}, "article");
            const std::string text = flat(run.text());
            INFO(text);
            CHECK(text.find(hint) == std::string::npos);
            const std::string pixel = run.view.traces[1].branch == Branch::lit ? "(5, 1)" : "(3, 4)";
            CHECK(text.find("For pixel " + pixel) != std::string::npos);
            CHECK(render_answers(run.view, 0).find("at " + pixel) != std::string::npos);
        }
    }
}

TEST_CASE("an answer whose values no chosen pixel reached is replaced by the pixel that has them", "[lesson][guards]") {
    const Lesson lesson = parsed(guarded_lesson("## [a] A\n\nQuestion.\n\n::: answer\nt = {t:4}\n:::\n"));
    const RunText run(lesson, article_scene(), {{0, 0}}, "article");
    const std::string text = flat(run.text());
    INFO(text);
    CHECK(text.find("t = —") == std::string::npos);
    CHECK(text.find("promyk lesson demo --pixel") != std::string::npos);
}

TEST_CASE("a wildcard row makes one row an object, and a row about an object the scene lacks is left out", "[lesson][guards]") {
    const Lesson lesson = parsed(guarded_lesson("## [a] A\n\n= sphere[*].t light[1].D\n"));
    const RunText two(lesson, example("two_spheres.json"), {{3, 4}}, "two_spheres.json");
    const std::string text = render_step(two.view, 0);
    INFO(text);
    CHECK(text.find("t (sphere 0)") != std::string::npos);
    CHECK(text.find("t (sphere 1)") != std::string::npos);
    CHECK(text.find("sphere 2") == std::string::npos);
    CHECK(text.find("light 1") == std::string::npos);  // one light in two_spheres
    const RunText lights(lesson, example("two_lights.json"), {{3, 4}}, "two_lights.json");
    CHECK(render_step(lights.view, 0).find("N·K (light 1)") != std::string::npos);
    CHECK(expanded_keys(lights.view, {"light[*].sphere[*].s_1"}).size() == 2);
}

TEST_CASE("a scene block is shown on its scene only, a scene without the lesson's effect says so", "[lesson][guards]") {
    const Lesson lesson =
        parsed(guarded_lesson("## [a] A\n\n::: scene\nOWN\n:::\n\n::: scene floor.json\nFLOOR\n:::\n\nALWAYS\n",
                           "scene: shadows.json\neffect: shadows\n"));
    const RunText own(lesson, example("shadows.json"), {{3, 4}}, "shadows.json");
    std::string text = own.text();
    CHECK(text.find("OWN") != std::string::npos);
    CHECK(text.find("FLOOR") == std::string::npos);
    CHECK(text.find("ALWAYS") != std::string::npos);
    CHECK(text.find("has no shadows") == std::string::npos);
    const RunText article(lesson, article_scene(), {{3, 4}}, "article");
    text = flat(article.text());
    CHECK(text.find("OWN") == std::string::npos);
    CHECK(text.find("ALWAYS") != std::string::npos);
    CHECK(text.find("has no shadows, which this lesson is about: see its example scene, shadows.json") != std::string::npos);
    CHECK(text.find("\"article\" has no shadows") != std::string::npos);
    const RunText floor(lesson, example("floor.json"), {{3, 4}}, "floor.json");
    CHECK(floor.text().find("FLOOR") != std::string::npos);
}

TEST_CASE("the computed figure draws the pane by branch and marks the chosen pixels", "[lesson][guards]") {
    const Lesson lesson = parsed(guarded_lesson("## [a] A\n\n::: figure pane\n"));
    REQUIRE(lesson.steps[0].parts.size() == 1);
    CHECK(lesson.steps[0].parts[0].kind == PartKind::figure);
    const Scene scene = article_scene();
    const RunText run(lesson, scene, {{3, 4}, {0, 0}}, "article");
    const std::string text = render_step(run.view, 0);
    INFO(text);
    std::vector<std::string> rows;
    for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1) {
        const std::string line = text.substr(at, end - at);
        if (line.size() > 5 && line.rfind("   ", 0) == 0 && std::isdigit(static_cast<unsigned char>(line[3]))) rows.push_back(line);
    }
    REQUIRE(rows.size() == 8);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const char shown = rows[static_cast<std::size_t>(i)][5 + 2 * static_cast<std::size_t>(j)];
            const Branch branch = trace_pixel(scene, 8, i, j).branch;
            const char expected = i == 3 && j == 4 ? '1' : i == 0 && j == 0 ? '2' : branch == Branch::miss ? '.' : branch == Branch::dark ? '-' : '#';
            CHECK(shown == expected);
        }
    CHECK(flat(text).find("1 pixel (3, 4) (lit side)") != std::string::npos);
    std::vector<LessonProblem> problems;
    parse_lesson(guarded_lesson("## [a] A\n\n::: figure cone\n"), "x.md", Language::en, problems);
    CHECK(problems.size() == 1);
}

TEST_CASE("the formula of I_P is the one of the scene's effects, in lessons and in the trace", "[lesson][guards]") {
    CHECK(effect_set(article_scene()) == "lambert");
    CHECK(effect_set(example("two_lights.json")) == "lights");
    CHECK(effect_set(example("shadows.json")) == "shadows");
    CHECK(effect_set(example("phong.json")) == "phong");
    CHECK(effect_set(example("colour.json")) == "colour");
    CHECK(intensity_formula("lambert").formula == builtin_vocabulary().find("I_P")->formula);
    CHECK(intensity_formula("colour").formula.find("m ⊙") != std::string::npos);
    const Lesson lesson = parsed(guarded_lesson("## [a] A\n\n= I_P\n"));
    for (const std::string name : {"two_lights.json", "shadows.json", "phong.json", "colour.json"}) {
        const Scene scene = example(name);
        const RunText run(lesson, scene, {first_of(scene, Branch::lit)}, name);
        const std::string formula = intensity_formula(effect_set(scene)).formula;
        INFO(name);
        CHECK(render_step(run.view, 0).find("I_P = " + formula) != std::string::npos);
        // The trace's footer, its wrapped lines joined again.
        std::string footer;
        for (const char c : format_trace_text(run.view.traces.front(), builtin_vocabulary()))
            if (!((c == ' ' || c == '\n') && !footer.empty() && footer.back() == ' ')) footer += c == '\n' ? ' ' : c;
        CHECK(footer.find("I_P = " + formula + " = ") != std::string::npos);
    }
    const RunText article(lesson, article_scene(), {{3, 4}}, "article");
    CHECK(render_step(article.view, 0).find("I_P = I·D / (r·√|K|²)") != std::string::npos);
    // A light's contribution without Phong or colour is not shown with their letters.
    const Lesson rows = parsed(guarded_lesson("## [a] A\n\n= light[0].contribution\n"));
    const RunText lights(rows, example("two_lights.json"), {{2, 2}}, "two_lights.json");
    CHECK(render_step(lights.view, 0).find("= I·max(0, cos α)") != std::string::npos);
    const RunText shadows(rows, example("shadows.json"), {{2, 2}}, "shadows.json");
    CHECK(render_step(shadows.view, 0).find("= v·I·max(0, cos α)") != std::string::npos);
    const RunText colour(rows, example("colour.json"), {{2, 2}}, "colour.json");
    CHECK(render_step(colour.view, 0).find("= c ⊙ (m ⊙ (I·max(0, cos α)))") != std::string::npos);
}

TEST_CASE("lesson checks read the new forms (conditions, needs, {i} in prose) and report their faults", "[lesson][guards]") {
    const auto problems = [](const std::string& body) {
        std::vector<LessonProblem> found;
        const Lesson lesson = parse_lesson(guarded_lesson(body), "x.md", Language::en, found);
        check_lesson(lesson, builtin_vocabulary(), found);
        return found;
    };
    CHECK(problems("## [a] A\n\nPixel ({i}, {j}).\n\n::: needs lit has:t\n").empty());
    CHECK(problems("## [a] A\n\n::: needs lot\n").size() == 1);
    CHECK(problems("## [a] A\n\n::: needs has:tt\n").size() == 1);
    CHECK(problems("## [a] A\n\n::: needs\n").size() == 1);
    CHECK(problems("## [a] A\n\n::: lit has:sphere[0].DD\nx\n:::\n").size() == 1);
    CHECK(problems("## [a] A\n\n= sphere[*].t\n").empty());
    CHECK(problems("## [a] A\n\n= sphere[*].D\n").size() == 1);
    CHECK(problems("## [a] A\n\nPixel value {t} in prose.\n").size() == 1);
    CHECK(problems("## [a] A\n\n::: scene a.json b.json\nx\n:::\n").size() == 1);
}

namespace {

// A built-in lesson in a language (its faults fail the test).
Lesson builtin_lesson(const std::string& name, Language language) {
    const std::optional<Lesson> lesson = LessonLibrary().find(name, language);
    REQUIRE(lesson);
    return *lesson;
}

// "RV⁴ · RV¹⁶": the powers that n's binary digits 1 name, lowest first.
std::string squarings_product(int n) {
    static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out;
    for (int bit = 0; (1 << bit) <= n; ++bit) {
        if (!(n & (1 << bit))) continue;
        std::string power;
        for (const char c : std::to_string(1 << bit)) power += digits[c - '0'];
        out += (out.empty() ? "" : " · ") + std::string("RV") + (bit == 0 ? "" : power);
    }
    return out;
}

std::string binary(int n) {
    std::string out;
    for (; n > 0; n >>= 1) out.insert(out.begin(), char('0' + (n & 1)));
    return out;
}

}  // namespace

TEST_CASE("lesson phong: what it says about n's binary digits holds for the scene's n", "[lesson][guards]") {
    const Scene own = example("phong.json");
    REQUIRE(own.materials.size() == 1);
    for (const Language language : {Language::en, Language::pl}) {
        const Lesson lesson = builtin_lesson("phong", language);
        // The own scene: the sentence about n names its n, its binary digits
        // and the product those digits call for, computed here.
        {
            const int n = own.materials[0].exponent;
            const RunText run(lesson, own, {{3, 5}, {2, 4}}, "phong.json");
            const std::string text = flat(run.text());
            INFO(text);
            const std::string product = squarings_product(n);
            CHECK(product == "RV⁴ · RV¹⁶");
            CHECK(text.find("n = " + std::to_string(n) + (language == Language::en ? ", which is " : ", czyli dwójkowo ") +
                            binary(n)) != std::string::npos);
            CHECK(text.find("RV²⁰ = " + product) != std::string::npos);
            CHECK(text.find("n = " + std::to_string(n) + " ") != std::string::npos);
        }
        // Another n, on a scene of another name: no sentence about 20 or its
        // digits, and the exercise names the scene's n.
        for (const int n : {7, 64, 10000}) {
            Scene scene = own;
            scene.materials[0].exponent = n;
            const RunText run(lesson, scene, {{3, 5}, {2, 4}}, "shiny.json");
            const std::string text = flat(run.text());
            INFO("n = " << n << ": " << text);
            CHECK(text.find("10100") == std::string::npos);
            CHECK(text.find("RV²⁰ =") == std::string::npos);
            CHECK(text.find("n = 20,") == std::string::npos);
            CHECK(text.find(binary(20)) == std::string::npos);
            CHECK(text.find(language == Language::en ? "20th power" : "potęgi 20 ") == std::string::npos);
            // From n = 16 up the exercise runs (it asks for RV¹⁶), naming the scene's n.
            if (n >= 16) CHECK(text.find("n = " + std::to_string(n) + " ") != std::string::npos);
        }
    }
}

TEST_CASE("lesson planes: n·E is the plane's own, never y_E, on a tilted plane", "[lesson][guards]") {
    // A plane tilted about the x axis, n = (0, 1, 1), seen by the lower rows.
    Scene tilted = example("floor_wall.json");
    tilted.planes.resize(1);
    tilted.planes[0].n = {0, 1, 1};
    tilted.planes[0].Q = {0, -1.5, 2};
    const int w = 15;
    // The first pixel, row by row, whose nearest hit is the plane.
    std::pair<int, int> on_plane{-1, -1};
    for (int i = w - 1; i >= 0 && on_plane.first < 0; --i)
        for (int j = 0; j < w && on_plane.first < 0; ++j)
            if (trace_pixel(tilted, w, i, j).hit_object == "plane 0") on_plane = {i, j};
    REQUIRE(on_plane.first >= 0);
    const PixelTrace trace = trace_pixel(tilted, w, on_plane.first, on_plane.second);
    const Vec3d E = std::get<Vec3d>(*lesson_value(trace, "E"));
    const Vec3d n_hat = unit_normal<double>(tilted.planes[0].n);
    const double NE = dot(n_hat, E);
    REQUIRE(E.y != NE);  // the floor's shortcut would be false here
    for (const Language language : {Language::en, Language::pl}) {
        const Lesson lesson = builtin_lesson("planes", language);
        const RunText run(lesson, tilted, {on_plane}, "tilted.json", w);
        const std::string text = flat(run.text());
        INFO(text);
        CHECK(text.find("n̂·E = y_E") == std::string::npos);
        CHECK(text.find("y_E = 0") == std::string::npos);
        CHECK(text.find("n̂·E = n̂_x·x_E + n̂_y·y_E + n̂_z·z_E = " + shown_number(NE, language, 4)) != std::string::npos);
    }
    // The lesson's own scene still says the floor's shortcut, which holds there.
    const Scene own = example("floor_wall.json");
    REQUIRE(own.planes[0].n == Vec3d{0, 1, 0});
    const Lesson lesson = builtin_lesson("planes", Language::en);
    const RunText run(lesson, own, {{14, 3}}, "floor_wall.json", w);
    CHECK(flat(run.text()).find("for the floor n̂·E = y_E") != std::string::npos);
}
