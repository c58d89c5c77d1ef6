#include "lesson/lesson_check.hpp"

#include <algorithm>
#include <map>

#include "trace/messages.hpp"

namespace promyk {

namespace {

bool is_special(const std::string& name) { return name == "i" || name == "j" || name == "w" || name == "branch"; }

std::string branch_list(const Vocabulary& vocabulary) {
    std::string out;
    for (const BranchEntry& branch : vocabulary.branches) out += (out.empty() ? "" : ", ") + branch.branch;
    return out;
}

}  // namespace

bool depends_on_pixel(const std::string& name, const Vocabulary& vocabulary) {
    if (name == "w") return false;
    if (is_special(name)) return true;
    const VocabularyEntry* entry = vocabulary.find(name);
    return entry == nullptr || !entry->given;
}

void check_lesson(const Lesson& lesson, const Vocabulary& vocabulary, std::vector<LessonProblem>& problems) {
    const auto problem = [&](int line, std::string_view id, const MessageArgs& args) {
        problems.push_back({lesson.file, line, message(lesson.language, id, args)});
    };
    for (const LessonStep& step : lesson.steps) {
        for (const LessonPart& part : step.parts) {
            if (part.kind == PartKind::values) {
                for (const std::string& key : part.keys)
                    if (vocabulary.find(key) == nullptr) problem(part.line, "error_unknown_key", {{"key", key}});
                continue;
            }
            for (const std::string& branch : part.branches)
                if (vocabulary.find_branch(branch) == nullptr)
                    problem(part.line, "error_unknown_branch", {{"branch", branch}, {"branches", branch_list(vocabulary)}});
            // The placeholders come in order: count the lines once, not from the start for each.
            int line = part.text_line;
            std::size_t counted = 0;
            for (const Placeholder& placeholder : find_placeholders(part.text)) {
                line += static_cast<int>(std::count(part.text.begin() + static_cast<long>(counted),
                                                    part.text.begin() + static_cast<long>(placeholder.begin), '\n'));
                counted = placeholder.begin;
                if (!placeholder.valid) {
                    problem(line, "error_bad_placeholder", {{"text", placeholder.name}});
                } else if (!is_special(placeholder.name) && vocabulary.find(placeholder.name) == nullptr) {
                    problem(line, "error_unknown_key", {{"key", placeholder.name}});
                } else if (part.kind == PartKind::prose && !placeholder.symbol &&
                           depends_on_pixel(placeholder.name, vocabulary)) {
                    problem(line, "error_pixel_outside_block", {{"key", placeholder.name}});
                }
            }
        }
    }
}

void check_translations(const std::vector<Lesson>& lessons, std::vector<LessonProblem>& problems) {
    std::map<std::string, std::vector<const Lesson*>> by_name;
    for (const Lesson& lesson : lessons) by_name[lesson.header.name].push_back(&lesson);
    const auto step_ids = [](const Lesson& lesson) {
        std::string ids;
        for (const LessonStep& step : lesson.steps) ids += (ids.empty() ? "" : ", ") + step.id;
        return ids;
    };
    for (const auto& [name, versions] : by_name) {
        if (name.empty()) continue;  // a lesson without a name is already reported at its header
        // Two files of one language with the same name: only the first would ever run.
        for (std::size_t a = 0; a < versions.size(); ++a)
            for (std::size_t b = 0; b < a; ++b)
                if (versions[a]->language == versions[b]->language) {
                    problems.push_back({versions[a]->file, versions[a]->header.name_line,
                                        message(versions[a]->language, "error_name_twice",
                                                {{"name", name}, {"other", versions[b]->file}})});
                    break;
                }
        for (const Language language : {Language::pl, Language::en}) {
            const bool present = std::any_of(versions.begin(), versions.end(),
                                             [&](const Lesson* lesson) { return lesson->language == language; });
            if (present) continue;
            for (const Lesson* lesson : versions)
                problems.push_back({lesson->file, 1,
                                    message(lesson->language, "error_missing_translation",
                                            {{"name", name}, {"lang", std::string(language_code(language))}})});
        }
        for (const Lesson* lesson : versions) {
            for (const Lesson* other : versions) {
                if (other == lesson || other->language == lesson->language) continue;
                if (step_ids(*lesson) != step_ids(*other))
                    problems.push_back({lesson->file, lesson->steps.empty() ? 1 : lesson->steps.front().line,
                                        message(lesson->language, "error_step_mismatch",
                                                {{"lang", std::string(language_code(other->language))},
                                                 {"other", other->file},
                                                 {"here", step_ids(*lesson)},
                                                 {"there", step_ids(*other)}})});
            }
        }
    }
}

}  // namespace promyk
