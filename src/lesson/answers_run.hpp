// A lesson's answers checked as `promyk lesson NAME --answers FILE` checks
// them: the command line and the web page's worksheet (web_export/wasm) both
// call this, so the page's marks are the CLI's.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "lesson/answers.hpp"
#include "lesson/lesson_run.hpp"

namespace promyk {

// Reads the answer file `text` (named `file` in its messages) for the run's
// lesson and checks every answer: a pixel a heading names is traced too,
// and so are the other settings an answer's key names and, where a
// fraction or many digits need it, the exact value (quad). The run's view
// keeps those traces, for answers_report and answer_mark.
std::vector<AnswerCheck> check_lesson_answers(LessonRun& run, std::string_view text, const std::string& file);

}  // namespace promyk
