// Worksheets: blanks where the pixels' numbers go, the scene's values kept,
// and an answer key that holds every number.
#include <catch2/catch.hpp>

#include <set>

#include "lesson/lesson_library.hpp"
#include "lesson/worksheet.hpp"
#include "render/trace_pixel.hpp"

using namespace promyk;

namespace {

const std::vector<std::pair<int, int>> worksheet_pixels = {{0, 0}, {5, 1}, {3, 4}};

// Texts the scene gives (S, r, background ...): a worksheet keeps them, so a
// pixel's number that happens to read the same (I_P = 0.5 for a miss) may appear.
std::set<std::string> given_texts(const PixelTrace& trace, const Vocabulary& vocabulary, Language language) {
    std::set<std::string> texts;
    for (const GivenValue& given : trace.header.given) {
        const VocabularyEntry* entry = vocabulary.find(given.key);
        texts.insert(value_text(given.value, entry ? entry->kind : "scalar", language));
        if (const Vec3d* v = std::get_if<Vec3d>(&given.value))
            for (const double c : {v->x, v->y, v->z}) texts.insert(number_text(c, language));
    }
    return texts;
}

// The texts of a pixel's own numbers (steps and I_P), whole and by component,
// long enough not to be found by chance ("2", "0,5").
std::set<std::string> pixel_texts(const PixelTrace& trace, const Vocabulary& vocabulary, Language language) {
    std::set<std::string> texts;
    const auto add = [&](const std::string& key, const StepValue& value) {
        const VocabularyEntry* entry = vocabulary.find(key);
        texts.insert(value_text(value, entry ? entry->kind : "scalar", language));
        if (const Vec3d* v = std::get_if<Vec3d>(&value))
            for (const double c : {v->x, v->y, v->z}) texts.insert(number_text(c, language));
        else if (const double* number = std::get_if<double>(&value))
            texts.insert(number_text(*number, language));
    };
    for (const Step& step : trace.steps) {
        if (std::holds_alternative<std::string>(step.value)) continue;  // words are shown
        // A plane's n̂ and n̂·Q are the scene's, the same for every pixel: shown too.
        std::string path(key_name(step.key));
        for (int g = step.group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent)
            path = trace.groups[static_cast<std::size_t>(g)].kind + "[" +
                   std::to_string(trace.groups[static_cast<std::size_t>(g)].index) + "]." + path;
        if (!is_scene_value(path)) add(std::string(key_name(step.key)), step.value);
    }
    add("I_P", trace.result);
    const std::set<std::string> given = given_texts(trace, vocabulary, language);
    std::set<std::string> out;
    for (const std::string& text : texts)
        if (text.size() >= 4 && given.count(text) == 0) out.insert(text);
    return out;
}

}  // namespace

TEST_CASE("a worksheet shows no pixel's number, keeps the scene's, and its key has them all", "[worksheet]") {
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    REQUIRE(problems.empty());
    for (const Lesson& lesson : lessons) {
        const Scene scene = library.scene(lesson.header.scene);
        for (const LessonFormat format : {LessonFormat::text, LessonFormat::markdown}) {
            LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
            view.format = format;
            view.digits = lesson.header.digits;  // as promyk lesson sets it
            for (const auto& [i, j] : worksheet_pixels) view.traces.push_back(trace_pixel(scene, 8, i, j));
            const Worksheet worksheet(view);
            std::string sheet = render_lesson_title(view) + worksheet.intro();
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) sheet += render_step(view, k);
            sheet += worksheet.answer_template();
            const std::string key = worksheet.answer_key();
            INFO(lesson.file << (format == LessonFormat::text ? " text" : " markdown") << "\n" << sheet);
            for (const Placeholder& placeholder : find_placeholders(sheet)) FAIL_CHECK("left in the output: " << placeholder.name);
            // What the lesson writes in its own words (lesson 1 asks "Why 10.240000000000002?") is not a blank.
            std::string words;
            for (const LessonStep& step : lesson.steps) {
                words += step.title + "\n";
                for (const LessonPart& part : step.parts) words += part.text + "\n";
            }
            for (const PixelTrace& trace : view.traces)
                for (const std::string& text : pixel_texts(trace, builtin_vocabulary(), lesson.language))
                    if (sheet.find(text) != std::string::npos && words.find(text) == std::string::npos) FAIL_CHECK("pixel (" << trace.header.i << ", " << trace.header.j << ")'s " << text << " is on the worksheet");
            // Blanks are numbered 1, 2, ... and each is in the key with its value.
            for (std::size_t n = 0; n < worksheet.blanks().size(); ++n) {
                const WorksheetBlank& blank = worksheet.blanks()[n];
                CHECK(blank.number == static_cast<int>(n) + 1);
                CHECK(sheet.find("(" + std::to_string(blank.number) + ")") != std::string::npos);
                const VocabularyEntry* entry = builtin_vocabulary().find(path_key(blank.key));
                std::string kind = blank.component != 0 || entry == nullptr ? "scalar" : entry->kind;
                if (std::holds_alternative<Vec3d>(blank.value) && kind != "point" && kind != "vector") kind = "colour";
                const std::string value = shown_value_text(blank.value, kind, lesson.language, view.digits);
                CHECK(key.find("(" + std::to_string(blank.number) + ") ") != std::string::npos);
                CHECK(key.find(value) != std::string::npos);
            }
            if (lesson.header.name != "vectors") CHECK_FALSE(worksheet.blanks().empty());
        }
    }
}

TEST_CASE("a worksheet keeps the scene's values and gives the same value the same blank", "[worksheet]") {
    for (const Language language : {Language::en, Language::pl}) {
        std::vector<LessonProblem> problems;
        const Lesson lesson = parse_lesson("---\nname: demo\ntitle: T\nsummary: S\n---\n## [a] A\n\nS = {S}\n\n= t EE\n\n"
                                           "::: pixel\nr = {r}, t = {t}, P = {P}, x = {P.x:3}\n:::\n",
                                           "x.md", language, problems);
        REQUIRE(problems.empty());
        const Scene scene = article_scene();
        LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
        view.traces.push_back(trace_pixel(scene, 8, 3, 4));
        view.traces.push_back(trace_pixel(scene, 8, 0, 0));
        const Worksheet worksheet(view);
        const std::string text = render_step(view, 0);
        INFO(text);
        const char* point = language == Language::pl ? "(0; 0; 3,2)" : "(0, 0, 3.2)";
        CHECK(text.find(std::string("S = ") + point) != std::string::npos);
        CHECK(text.find(language == Language::pl ? "r = 1,1" : "r = 1.1") != std::string::npos);
        // The table's t of (3, 4) is blank 1; the block shows the same blank again.
        CHECK(text.find("t = " + Worksheet::blank_text(1, "scalar", language)) != std::string::npos);
        CHECK(text.find(Worksheet::blank_text(1, "scalar", language)) != text.rfind(Worksheet::blank_text(1, "scalar", language)));
        CHECK(text.find("—") != std::string::npos);  // the miss has no t: a dash, not a blank
        const std::string point_blank = Worksheet::blank_text(5, "point", language);
        CHECK(point_blank.find(language == Language::pl ? ";" : ",") != std::string::npos);
        CHECK(point_blank.front() == '(');
        CHECK(Worksheet::blank_text(5, "vector", language).front() == '[');
        const std::string form = worksheet.answer_template();
        CHECK(form.find("[3,4]") != std::string::npos);
        CHECK(form.find("P.x = ") != std::string::npos);
    }
}

TEST_CASE("a worksheet blanks a number inside a group and shows a word filled in", "[worksheet]") {
    Scene scene;
    scene.name = "two spheres";
    scene.spheres = {Sphere{{-0.5, -0.2, 3.2}, 0.9}, Sphere{{0.9, 0.4, 4.6}, 1.3}};
    scene.lights = {Light{{1.5, 1, 1}, 1}};
    for (const Language language : {Language::en, Language::pl}) {
        std::vector<LessonProblem> problems;
        const Lesson lesson = parse_lesson("---\nname: demo\ntitle: T\nsummary: S\n---\n## [a] A\n\nS1 = {sphere[1].S}\n\n"
                                           "= sphere[0].t sphere[1].t nearest\n\n"
                                           "::: pixel\nt1 = {sphere[1].t}, D = {light[0].D}, the nearest: {nearest}\n:::\n",
                                           "x.md", language, problems);
        REQUIRE(problems.empty());
        LessonView view{lesson, builtin_vocabulary(), {}, scene.name, 8};
        view.traces.push_back(trace_pixel(scene, 8, 3, 4));
        const Worksheet worksheet(view);
        const std::string text = render_step(view, 0);
        INFO(text);
        // Blanks 1 and 2 are the table's t of sphere 0 and sphere 1; the block repeats blank 2.
        REQUIRE(worksheet.blanks().size() == 3);
        CHECK(worksheet.blanks()[1].key == "sphere[1].t");
        CHECK(text.find("t1 = " + Worksheet::blank_text(2, "scalar", language)) != std::string::npos);
        CHECK(worksheet.blanks()[2].key == "light[0].D");
        // The scene's S of sphere 1 and the nearest object stay as they are.
        CHECK(text.find(language == Language::pl ? "S1 = (0,9; 0,4; 4,6)" : "S1 = (0.9, 0.4, 4.6)") != std::string::npos);
        CHECK(text.find(std::string("the nearest: ") + (language == Language::pl ? "kula 0" : "sphere 0")) != std::string::npos);
        const std::string form = worksheet.answer_template();
        CHECK(form.find("sphere[1].t = ") != std::string::npos);
        CHECK(form.find("light[0].D = ") != std::string::npos);
        CHECK(form.find("nearest") == std::string::npos);
        const std::string key = worksheet.answer_key();
        const double t1 = std::get<double>(worksheet.blanks()[1].value);
        CHECK(key.find(shown_number(t1, language, 4)) != std::string::npos);
        CHECK(key.find("[sphere[1].t]") != std::string::npos);
    }
}
