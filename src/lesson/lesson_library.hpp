// Where lessons come from: the files built into promyk, or a teacher's
// folder (--lessons DIR) whose files take the place of the built-in ones of
// the same path and add new ones.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson.hpp"
#include "scene/scene.hpp"

namespace promyk {

struct LessonFile {
    std::string path;  // relative to the lessons folder: "pl/03-sphere.md", "scenes/x.json"
    std::string shown;  // as messages name it: "DIR/pl/03-sphere.md" or "pl/03-sphere.md (built in)"
    std::string text;
};

class LessonLibrary {
public:
    // The built-in files, overridden by those under `folder` when it is not empty.
    // InputError when the folder cannot be read.
    explicit LessonLibrary(const std::string& folder = "");

    // Every lesson of every language, in file order (NN-name), parsed;
    // problems of form are appended.
    std::vector<Lesson> lessons(std::vector<LessonProblem>& problems) const;

    // The lesson `name` in `language`, or nothing. InputError if the lesson
    // file has faults (with the first one's line).
    std::optional<Lesson> find(const std::string& name, Language language) const;

    // The lesson's scene: the article's, or a file in scenes/ (InputError if missing or bad).
    Scene scene(const std::string& name) const;

    const std::vector<LessonFile>& files() const { return files_; }

    // Lesson-like files of the folder that are not read: a .md file in a
    // folder other than pl/ and en/ (EN/, de/), for --check to mention.
    const std::vector<std::string>& unread() const { return unread_; }

    // Writes every lesson, the messages and the scenes into `folder` (created
    // if missing), for a teacher to edit. OutputError on failure.
    static void dump_builtin(const std::string& folder);

private:
    std::vector<LessonFile> files_;  // sorted by path
    std::vector<std::string> unread_;
};

}  // namespace promyk
