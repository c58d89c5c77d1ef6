// The lesson parser (lesson/lesson.hpp: parse_lesson) and the checks that
// `promyk lesson --check` runs on a teacher's file (lesson_check.hpp): any
// text is a lesson with its problems listed, never a crash, a leak or
// undefined behaviour; every problem has a line inside the file.
#include <algorithm>

#include "fuzz_check.hpp"
#include "lesson/lesson.hpp"
#include "lesson/lesson_check.hpp"
#include "scene/scene.hpp"
#include "trace/vocabulary.hpp"

using namespace promyk;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Scene scene = article_scene();
    const std::string_view text = fuzz::bytes_of(data, size);
    const Language language = fuzz::language_of(size);
    set_ui_language(language);
    std::vector<LessonProblem> problems;
    const Lesson lesson = parse_lesson(text, "fuzz.md", language, problems);
    check_lesson(lesson, builtin_vocabulary(), problems, &scene);
    check_lesson(lesson, builtin_vocabulary(), problems);
    (void)lesson_keys(lesson, builtin_vocabulary());
    for (const SettingsUse& use : settings_used(lesson)) (void)parse_settings(use.settings);
    const long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n')) + 1;
    for (const LessonProblem& problem : problems)
        if (problem.line < 0 || problem.line > lines) fuzz::broken("a problem's line is outside the file");
    return 0;
}
