// Checking lessons against the vocabulary and against each other:
// `promyk lesson --check`. Every problem names the file and line, in the
// lesson's own language.
#pragma once

#include <vector>

#include "lesson/lesson.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

// Unknown keys and branches, malformed placeholders, pixel values outside a block.
void check_lesson(const Lesson& lesson, const Vocabulary& vocabulary, std::vector<LessonProblem>& problems);

// Every lesson exists in every language, with the same steps in the same order.
void check_translations(const std::vector<Lesson>& lessons, std::vector<LessonProblem>& problems);

// True when a placeholder's value differs from pixel to pixel ({t}, {i}), false
// for the scene's values ({S}, {r}) and {w}. Unknown names count as per-pixel.
bool depends_on_pixel(const std::string& name, const Vocabulary& vocabulary);

}  // namespace promyk
