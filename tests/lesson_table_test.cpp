// A lesson's value table labels each row with the step's formula in TeX,
// from the vocabulary (lessons/vocabulary.json), and I_P's row with the
// formula of the scene's effects: Lambert's on the article's scene, the
// weighted sum when a material has k_a. The expected TeX is written out here
// from the vocabulary file, not taken from the code that builds the rows.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "lesson/lesson.hpp"
#include "lesson/lesson_render.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/vocabulary.hpp"

using namespace promyk;

namespace {

const char* const table_lesson = "---\nname: demo\ntitle: T\nsummary: S\n---\n## [a] A\n= C delta I_P\n";

// Step 0 of the table lesson on `scene` at pixel (5, 1) of w 8, in `format`.
std::string table_of(const Scene& scene, LessonFormat format, Language language) {
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(table_lesson, "x.md", language, problems);
    REQUIRE(problems.empty());
    LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
    view.format = format;
    view.scene = &scene;
    view.traces.push_back(trace_pixel(scene, 8, 5, 1));
    return render_step(view, 0);
}

const std::string C_row = R"(C = \vec{E}\cdot\vec{S} = x_E x_S + y_E y_S + z_E z_S)";
const std::string delta_row = R"(\tfrac{\Delta}{4} = C^2 - )";
const std::string lambert_row = R"(I_P = \frac{I\,D}{r\sqrt{)";
const std::string weights_row = R"(I_P = k_a I + k_d\,I \max(0, \cos\alpha))";

}  // namespace

TEST_CASE("a value table's rows are labelled with their formulas, I_P's with the scene's effects", "[lesson][table]") {
    const Scene article = article_scene();
    const Scene ambient = load_scene_text(
        R"({"name": "ambient", "z_E": 2, "background": 0.5, "spheres": [{"S": [0, 0, 3.2], "r": 1.1, "material": 0}],
            "lights": [{"L": [1.5, 1, 1], "I": 1}], "materials": [{"ambient": 0.2, "diffuse": 0.8}]})",
        "ambient.json");
    for (const Language language : {Language::en, Language::pl}) {
        for (const LessonFormat format : {LessonFormat::markdown, LessonFormat::html}) {
            const std::string on_article = table_of(article, format, language);
            INFO(on_article);
            // HTML escapes its TeX's & < > only, none of which these rows have.
            CHECK(on_article.find(C_row) != std::string::npos);
            CHECK(on_article.find(delta_row) != std::string::npos);
            CHECK(on_article.find(lambert_row) != std::string::npos);
            CHECK(on_article.find(weights_row) == std::string::npos);

            const std::string on_ambient = table_of(ambient, format, language);
            INFO(on_ambient);
            CHECK(on_ambient.find(C_row) != std::string::npos);
            CHECK(on_ambient.find(weights_row) != std::string::npos);
            CHECK(on_ambient.find(lambert_row) == std::string::npos);
        }
    }
}
