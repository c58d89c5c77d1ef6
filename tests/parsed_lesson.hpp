// A lesson parsed from text and checked against the built-in vocabulary,
// each problem reported as a failed check (the tests' lessons must be clean).
#pragma once

#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "lesson/lesson.hpp"
#include "lesson/lesson_check.hpp"
#include "trace/vocabulary.hpp"

namespace promyk::testing {

inline Lesson parsed(const std::string& text, Language language = Language::en) {
    std::vector<LessonProblem> problems;
    Lesson lesson = parse_lesson(text, "x.md", language, problems);
    check_lesson(lesson, builtin_vocabulary(), problems);
    for (const LessonProblem& problem : problems) FAIL_CHECK(problem.line << ": " << problem.message);
    return lesson;
}

}  // namespace promyk::testing
