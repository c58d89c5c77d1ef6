#include "lesson/answers_run.hpp"

#include <set>
#include <utility>

#include "lesson/lesson_check.hpp"
#include "lesson/lesson_render.hpp"

namespace promyk {

std::vector<AnswerCheck> check_lesson_answers(LessonRun& run, std::string_view text, const std::string& file) {
    LessonView& view = run.view();
    const Kernel& kernel = run.kernel();
    const TraceHeader& header = run.header();
    const LessonPixel first{view.traces.front().header.i, view.traces.front().header.j};
    // A bad line makes that answer unreadable, the rest are checked; a fraction is a number.
    AnswerLimits limits;
    limits.w = view.w;
    limits.scene_hash = header.scene_hash;
    limits.settings = true;
    limits.forgiving = true;
    limits.keys = lesson_keys(view.lesson, view.vocabulary);
    const std::vector<PixelAnswers> answers =
        read_answers(text, file, view.vocabulary, view.lesson.language, first, limits).pixels;
    // A heading may name a pixel the lesson did not choose: it is traced too.
    std::set<std::pair<int, int>> traced;
    for (const PixelTrace& trace : view.traces) traced.emplace(trace.header.i, trace.header.j);
    for (const PixelAnswers& pixel : answers)
        if (traced.emplace(pixel.pixel.i, pixel.pixel.j).second)
            view.traces.push_back(kernel.trace(header, pixel.pixel.i, pixel.pixel.j));
    // Every pixel in every setting the answers or the lesson name (delta@float = …).
    std::vector<std::string> qualifiers;
    for (const PixelAnswers& pixel : answers)
        for (const Answer& answer : pixel.answers)
            if (answer.unreadable.empty()) qualifiers.push_back(split_settings(answer.key).second);
    for (const SettingsUse& use : settings_used(view.lesson)) qualifiers.push_back(use.settings);
    view.others.clear();
    run.trace_settings(qualifiers);
    std::vector<AnswerCheck> checks = check_answers(answers, view.traces, view.others);
    // A fraction or a number with more digits than the type holds, wrong against the computed value
    // alone, is judged against the exact value: the same pixel and formula in quad, traced only for these.
    std::vector<std::string> exact;
    std::set<std::pair<int, int>> exact_pixels;
    for (const AnswerCheck& check : checks)
        if (check.needs_exact) {
            exact.push_back(exact_settings(split_settings(check.answer.key).second));
            exact_pixels.emplace(check.pixel.i, check.pixel.j);
        }
    if (!exact.empty()) {
        run.trace_settings(exact, &exact_pixels);
        checks = check_answers(answers, view.traces, view.others);
    }
    return checks;
}

}  // namespace promyk
