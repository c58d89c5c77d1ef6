// A lesson with the real numbers of its pixels, as terminal text or as
// Markdown ($…$ math, tables, <details> for answers).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

enum class LessonFormat { text, markdown };

struct LessonView {
    const Lesson& lesson;
    const Vocabulary& vocabulary;
    std::vector<PixelTrace> traces;  // one a pixel column, in the order chosen
    std::string scene_name;
    int w = 8;
    LessonFormat format = LessonFormat::text;
    bool color = false;  // terminal text only: bold headings
    // Worksheets (lesson/worksheet.hpp): when set, each value of a pixel that
    // a table or a block shows is asked for here first; a text returned takes
    // the number's place (a blank), nothing keeps the number.
    std::function<std::optional<std::string>(const PixelTrace& trace, const std::string& key, char component)> shown_value{};
};

// The lesson's title, summary and setup (scene, pane, pixels).
std::string render_lesson_title(const LessonView& view);

// Step k (0-based) without its answers; with `numbered`, "Step k of n".
std::string render_step(const LessonView& view, std::size_t k);

// Step k's answers, or an empty string when it has none.
std::string render_answers(const LessonView& view, std::size_t k);

bool has_answers(const LessonStep& step);

// The value a placeholder or a value table names, for one pixel's trace;
// nothing where the pixel's computation did not reach it.
std::optional<StepValue> lesson_value(const PixelTrace& trace, const std::string& key);

}  // namespace promyk
