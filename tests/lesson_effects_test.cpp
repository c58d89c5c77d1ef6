// Issue 15's last points: every formula shown is the one of the effects the
// scene uses (trace steps, the branch line, lesson rows); the planes
// exercise's needs hold exactly where the floor is the nearest hit; Phong's
// squarings and the shadow ray's entry point are trace steps a lesson shows
// for any pixel; one word wrapper, which never ends a line early before a
// bracketed group.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "flat_text.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "parsed_lesson.hpp"
#include "render/stages.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/intensity_formula.hpp"
#include "trace/trace_text.hpp"
#include "util/wrap.hpp"

using namespace promyk;

namespace {

const std::string lesson_source = PROMYK_SOURCE_DIR;

std::vector<std::string> effects_example_scenes() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(lesson_source + "/lessons/scenes"))
        if (entry.path().extension() == ".json" && entry.path().string().find(".schema.") == std::string::npos)
            out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

// The letters of each effect a formula may use only when the scene has it.
std::vector<std::string> foreign_symbols(const Scene& scene) {
    const Stages stages = plan_stages(scene);
    bool weights = false;
    for (const Material& m : scene.materials) weights = weights || m.ambient > 0 || m.diffuse != 1;
    std::vector<std::string> out;
    if (!stages.colour) out.insert(out.end(), {"⊙", "cₖ", "m·", "m ⊙", "c·("});
    if (!stages.phong) out.insert(out.end(), {"k_s", "R̂", "V̂", "ⁿ"});
    if (!stages.shadows) out.insert(out.end(), {"vₖ", "v·"});
    if (!stages.phong && !weights) out.insert(out.end(), {"k_a", "k_d"});
    if (scene.lights.size() < 2) out.insert(out.end(), {"Σ"});
    return out;
}

using promyk::testing::parsed;

LessonView view_of(const Lesson& lesson, const Scene& scene, std::vector<PixelTrace> traces, const std::string& file,
                   int w) {
    LessonView view{lesson, builtin_vocabulary(), {}, scene.name, w};
    view.scene = &scene;
    view.scene_file = file;
    view.own_scene = file == lesson.header.scene;
    view.traces = std::move(traces);
    return view;
}

double lesson_number(const PixelTrace& trace, const std::string& path) {
    const std::optional<StepValue> value = lesson_value(trace, path);
    REQUIRE(value);
    return std::get<double>(*value);
}

}  // namespace

TEST_CASE("no formula shown mentions an effect the scene does not use", "[lesson][effects]") {
    const Lesson rows = parsed(
        "---\nname: demo\ntitle: T\nsummary: S\n---\n## [a] A\n\n= I_P light[*].contribution\n\n::: pixel\n"
        "({i}, {j}): {branch}\n:::\n");
    for (const std::string& file : effects_example_scenes()) {
        const Scene scene = load_scene_file(lesson_source + "/lessons/scenes/" + file);
        const std::vector<std::string> foreign = foreign_symbols(scene);
        const std::string effects = effect_set(scene);
        // A pixel of every branch of an 8 × 8 pane.
        std::set<Branch> seen;
        for (int i = 0; i < 8; ++i) {
            for (int j = 0; j < 8; ++j) {
                const PixelTrace trace = trace_pixel(scene, 8, i, j);
                if (!seen.insert(trace.branch).second) continue;
                INFO(file << " (" << effects << "), pixel (" << i << ", " << j << "), " << branch_name(trace.branch));
                std::vector<std::pair<std::string, std::string>> shown;
                for (const Language language : {Language::en, Language::pl}) {
                    for (const TraceLayout layout : {TraceLayout::narrow, TraceLayout::wide}) {
                        TraceTextOptions options;
                        options.language = language;
                        options.layout = layout;
                        const std::string text = format_trace_text(trace, builtin_vocabulary(), options);
                        // Each step's formula, the branch's words and the result's
                        // formula are shown, and are the ones checked below.
                        for (const Step& step : trace.steps) {
                            const std::string key(key_name(step.key));
                            const std::string formula = step_formula(builtin_vocabulary().find(key), key, effects);
                            if (formula.empty()) continue;
                            CHECK(flat(text).find(flat(formula)) != std::string::npos);
                            shown.emplace_back("step " + key, formula);
                        }
                        if (layout == TraceLayout::narrow) {
                            const std::string about = branch_about(builtin_vocabulary(), trace.branch, effects, language);
                            CHECK(flat(text).find(flat(about)) != std::string::npos);
                            shown.emplace_back("branch", about);
                            if (trace.branch == Branch::lit || trace.branch == Branch::shadowed) {
                                const std::string result = intensity_formula_text(effects, language);
                                CHECK(flat(text).find(flat(intensity_formula(effects).formula)) != std::string::npos);
                                shown.emplace_back("result", result);
                            }
                        }
                    }
                    Lesson lesson = rows;
                    lesson.language = language;
                    const LessonView view = view_of(lesson, scene, {trace}, file, 8);
                    shown.emplace_back("lesson", render_step(view, 0));
                }
                for (const auto& [where, text] : shown)
                    for (const std::string& symbol : foreign) {
                        INFO(where << " shows " << symbol << ":\n" << text);
                        CHECK(text.find(symbol) == std::string::npos);
                    }
            }
        }
    }
    // The property can fail: everything.json's full formula has every letter.
    CHECK(intensity_formula("lights+shadows+phong+colour").formula.find("⊙") != std::string::npos);
    CHECK(effect_set(load_scene_file(lesson_source + "/lessons/scenes/everything.json")) == "lights+shadows+phong+colour");
    CHECK(intensity_formula("lights+shadows+phong+colour").formula.find("vₖ") != std::string::npos);
}

TEST_CASE("the planes exercise's needs hold exactly where the floor is the nearest hit", "[lesson][effects]") {
    const LessonLibrary library;
    const Scene scene = library.scene("floor_wall.json");
    const Plane& floor = scene.planes.at(0);
    for (const Language language : {Language::en, Language::pl}) {
        const std::optional<Lesson> lesson = library.find("planes", language);
        REQUIRE(lesson);
        const LessonStep* exercise = nullptr;
        for (const LessonStep& step : lesson->steps)
            if (step.id == "exercise") exercise = &step;
        REQUIRE(exercise);
        REQUIRE_FALSE(exercise->needs.empty());
        // The sweep's 8 × 8 pane and the lesson's own w.
        std::size_t floors = 0, others = 0;
        for (const int w : {8, lesson->header.w}) {
            const LessonView view = view_of(*lesson, scene, {}, "floor_wall.json", w);
            for (int i = 0; i < w; ++i) {
                for (int j = 0; j < w; ++j) {
                    const PixelTrace trace = trace_pixel(scene, w, i, j);
                    // Computed here from the geometry: the floor's t, and every other object's nearest t > 0.
                    const Vec3d E{(2.0 * j + 1) / w - 1, -(2.0 * i + 1) / w + 1, scene.z_E};
                    const auto plane_t = [&](const Plane& p) {
                        const Vec3d n = p.n / std::sqrt(dot(p.n, p.n));
                        return dot(n, E) == 0 ? -1.0 : dot(n, p.Q) / dot(n, E);
                    };
                    const double t_floor = plane_t(floor);
                    double t_other = INFINITY;
                    for (std::size_t k = 1; k < scene.planes.size(); ++k)
                        if (const double t = plane_t(scene.planes[k]); t > 0) t_other = std::min(t_other, t);
                    for (const Sphere& s : scene.spheres) {
                        const double EE = dot(E, E), C = dot(E, s.S), delta = C * C - EE * (dot(s.S, s.S) - s.r * s.r);
                        if (delta <= 0) continue;
                        for (const double t : {(C - std::sqrt(delta)) / EE, (C + std::sqrt(delta)) / EE})
                            if (t > 0) t_other = std::min(t_other, t);
                    }
                    const bool floor_nearest = t_floor > 0 && t_floor < t_other;
                    bool holds = true;
                    for (const Condition& condition : exercise->needs) holds = holds && condition_holds(view, trace, condition);
                    INFO("w " << w << ", pixel (" << i << ", " << j << "): floor's t " << t_floor << ", others' " << t_other);
                    CHECK(holds == floor_nearest);
                    (floor_nearest ? floors : others) += 1;
                    // On the floor the answer's P is the floor's point: y = Q.y.
                    if (holds) CHECK(std::get<Vec3d>(*lesson_value(trace, "P")).y == Approx(floor.Q.y));
                }
            }
        }
        // Pixels that see the floor's plane in front of them but the wall or sphere nearer exist.
        CHECK(floors > 10);
        CHECK(others > 10);
    }
    // The condition reads a word step: "nearest=plane[0]" is the trace's "plane 0".
    const std::optional<Condition> nearest = parse_condition("nearest=plane[0]");
    REQUIRE(nearest);
    CHECK(nearest->op == Condition::Op::is_word);
    CHECK(nearest->word == "plane 0");
    CHECK_FALSE(parse_condition("=plane[0]"));
}

TEST_CASE("Phong's squarings and the shadow ray's entry point are trace steps", "[lesson][effects][trace]") {
    // Phong: RV^2, RV^4, ... are the squarings power() makes, recorded while 2^k <= n.
    for (const int n : {1, 2, 20, 31, 10000}) {
        Scene scene = load_scene_file(lesson_source + "/lessons/scenes/phong.json");
        scene.materials[0].exponent = n;
        const PixelTrace trace = trace_pixel(scene, 8, 3, 5);
        const double RV = lesson_number(trace, "light[0].RV");
        REQUIRE(RV > 0);
        double square = RV;
        for (int k = 1; k <= squaring_count; ++k) {
            const std::string path = "light[0]." + std::string(key_name(squaring_key(k)));
            INFO("n = " << n << ", " << path);
            if ((1 << k) <= n) {
                square = square * square;
                CHECK(lesson_number(trace, path) == square);  // the same products, the same bits
            } else {
                CHECK_FALSE(lesson_value(trace, path));
            }
        }
        CHECK(lesson_number(trace, "light[0].RV_n") == Approx(std::pow(RV, n)).epsilon(1e-12));
    }
    // Shadows: P + s1 K lies on the blocking sphere.
    const Scene shadows = load_scene_file(lesson_source + "/lessons/scenes/shadows.json");
    int entered = 0;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const PixelTrace trace = trace_pixel(shadows, 8, i, j);
            if (!lesson_value(trace, "light[0].sphere[0].s_1")) {
                CHECK_FALSE(lesson_value(trace, "light[0].sphere[0].P_s1"));
                continue;
            }
            const Vec3d P = std::get<Vec3d>(*lesson_value(trace, "P"));
            const Vec3d K = std::get<Vec3d>(*lesson_value(trace, "light[0].K"));
            const double s_1 = lesson_number(trace, "light[0].sphere[0].s_1");
            const Vec3d P_s1 = std::get<Vec3d>(*lesson_value(trace, "light[0].sphere[0].P_s1"));
            CHECK(P_s1.x == P.x + s_1 * K.x);
            CHECK(P_s1.y == P.y + s_1 * K.y);
            CHECK(P_s1.z == P.z + s_1 * K.z);
            CHECK(lesson_number(trace, "light[0].sphere[0].d_s1") == Approx(shadows.spheres[0].r).epsilon(1e-12));
            ++entered;
        }
    }
    CHECK(entered > 0);
}

TEST_CASE("the phong and shadows lessons show the chain and the point for every pixel they show", "[lesson][effects]") {
    const LessonLibrary library;
    for (const Language language : {Language::en, Language::pl}) {
        const Scene phong = library.scene("phong.json");
        const std::optional<Lesson> lesson = library.find("phong", language);
        REQUIRE(lesson);
        for (int i = 0; i < 8; ++i) {
            for (int j = 0; j < 8; ++j) {
                const PixelTrace trace = trace_pixel(phong, 8, i, j);
                if (!lesson_value(trace, "light[0].RV_16")) continue;
                const LessonView view = view_of(*lesson, phong, {trace}, "phong.json", 8);
                std::string text;
                for (std::size_t k = 0; k < lesson->steps.size(); ++k) text += render_step(view, k) + render_answers(view, k);
                INFO("pixel (" << i << ", " << j << ")");
                // RV⁸ in the answer, to four decimals: this pixel's own.
                std::string RV_8 = fmt::format("{:.4f}", lesson_number(trace, "light[0].RV_8"));
                if (language == Language::pl) RV_8[1] = ',';
                CHECK(flat(text).find("RV⁸ = " + RV_8) != std::string::npos);
            }
        }
        const Scene shadows = library.scene("shadows.json");
        const std::optional<Lesson> lesson9 = library.find("shadows", language);
        REQUIRE(lesson9);
        for (int i = 0; i < 8; ++i) {
            for (int j = 0; j < 8; ++j) {
                const PixelTrace trace = trace_pixel(shadows, 8, i, j);
                const std::optional<StepValue> s_1 = lesson_value(trace, "light[0].sphere[0].s_1");
                if (trace.branch != Branch::shadowed || !s_1 || !(std::get<double>(*s_1) > 0 && std::get<double>(*s_1) < 1))
                    continue;
                const LessonView view = view_of(*lesson9, shadows, {trace}, "shadows.json", 8);
                const std::string text = flat(render_answers(view, lesson9->steps.size() - 1));
                INFO("pixel (" << i << ", " << j << "): " << text);
                CHECK(text.find("|P + s₁K − S| = " + shown_number(lesson_number(trace, "light[0].sphere[0].d_s1"), language, 4)) !=
                      std::string::npos);
            }
        }
    }
}

TEST_CASE("one word wrapper: short groups whole, no line ending early before a group", "[lesson][wrap]") {
    // A group that fits is moved whole; one longer than group_columns breaks like prose.
    CHECK(wrap_text(std::string(70, 'a') + " (3, 4) end") == std::string(70, 'a') + " (3, 4)\nend");
    CHECK(wrap_text(std::string(75, 'a') + " (3, 4) end") == std::string(75, 'a') + "\n(3, 4) end");
    const std::string long_group = std::string(50, 'a') + " b (apart from the single one coming straight from the bulb) c";
    const std::string wrapped = wrap_text(long_group);
    CHECK(wrapped.substr(0, wrapped.find('\n')) == std::string(50, 'a') + " b (apart from the single one");
    // The first line's lead is counted.
    CHECK(wrap_text("one two", 0, 10, 6) == "one\ntwo");
    // An indented line keeps its indent; continuation lines take `indent`.
    CHECK(wrap_text("  x " + std::string(80, 'y'), 4) == "  x\n    " + std::string(80, 'y'));
}

TEST_CASE("the word wrapper never starts a line with a lone product operator", "[lesson][wrap]") {
    // At every line width: the "·" (and "×", "⊙") that stands alone as a word
    // stays at the end of the line before it.
    const std::string text =
        "I_P = 0.7 · 0.2023 + 0.5 · 0.3714 · 1, RV⁴ · RV¹⁶ · RV³² and 8 × 8 squares, c ⊙ m, a · b · c · d · e";
    int breaks = 0;
    for (std::size_t columns = 6; columns <= 90; ++columns) {
        const std::string wrapped = wrap_text(text, 2, columns);
        INFO("columns " << columns << ":\n" << wrapped);
        std::size_t start = 0;
        for (std::size_t end; start <= wrapped.size(); start = end + 1) {
            end = std::min(wrapped.find('\n', start), wrapped.size());
            std::string line = wrapped.substr(start, end - start);
            line.erase(0, line.find_first_not_of(' '));
            for (const std::string op : {"·", "×", "⊙"}) CHECK(line.rfind(op, 0) != 0);
            if (end == wrapped.size()) break;
            ++breaks;
        }
        // Only the breaks moved: the words are the same.
        std::string joined;
        for (const char c : wrapped) joined += c == '\n' ? ' ' : c;
        std::string flat_joined;
        for (const char c : joined)
            if (!(c == ' ' && !flat_joined.empty() && flat_joined.back() == ' ')) flat_joined += c;
        CHECK(flat_joined == text);
    }
    CHECK(breaks > 50);
    CHECK(wrap_text("aaaa bb · cc", 0, 9) == "aaaa bb ·\ncc");
    CHECK(wrap_text("aaaa · bb", 0, 7) == "aaaa ·\nbb");
}
