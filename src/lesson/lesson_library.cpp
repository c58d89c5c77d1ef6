#include "lesson/lesson_library.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <map>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "util/atomic_file.hpp"
#include "util/embedded_files.hpp"
#include "util/errors.hpp"
#include "util/read_input.hpp"
#include "util/system_error_text.hpp"

namespace promyk {

namespace {

namespace fs = std::filesystem;

// A lesson file's language is its folder: "pl/..." or "en/...".
std::optional<Language> language_of(const std::string& path) {
    const auto slash = path.find('/');
    if (slash == std::string::npos || path.size() < 3 || path.compare(path.size() - 3, 3, ".md") != 0) return std::nullopt;
    return parse_language(path.substr(0, slash));
}

// Every file of a lessons folder is read when the folder is opened: a huge
// one (a disk image named en/01-x.md) is refused rather than read into memory.
constexpr std::size_t max_lesson_file_bytes = 8 << 20;

// Regular files only (the caller checks), yet one swapped for a FIFO after
// the check waits interruptibly (util/read_input).
std::string read_text(const fs::path& path) {
    WholeFile file = read_whole_file(path.string(), max_lesson_file_bytes);
    switch (file.failure) {
        case WholeFile::Failure::none:
            break;
        case WholeFile::Failure::cannot_open:
        case WholeFile::Failure::cannot_read:
            throw InputError(path.string(), "",
                             ui_message("file_cannot_read", {{"reason", system_error_text(file.error)}}));
        case WholeFile::Failure::too_large:
            throw InputError(path.string(), "",
                             ui_message("file_too_large", {{"bytes", std::to_string(max_lesson_file_bytes)}}));
    }
    return std::move(file.bytes);
}

}  // namespace

LessonLibrary::LessonLibrary(const std::string& folder) {
    for (const embedded::EmbeddedFile& file : embedded::lesson_files())
        files_.push_back({std::string(file.path), std::string(file.path) + " (built in)", std::string(file.text)});
    if (!folder.empty()) {
        std::map<std::string, std::size_t> index;
        for (std::size_t k = 0; k < files_.size(); ++k) index.emplace(files_[k].path, k);
        std::error_code error;
        if (!fs::is_directory(folder, error))
            throw InputError(folder, "", ui_message("lessons_need_folder"));
        for (auto it = fs::recursive_directory_iterator(folder, error); !error && it != fs::recursive_directory_iterator();
             it.increment(error)) {
            // Lexically: fs::relative would follow symlinks (and throw on a loop).
            const std::string relative = it->path().lexically_relative(folder).generic_string();
            if (!language_of(relative) && relative.rfind("scenes/", 0) != 0) {
                const bool markdown = relative.size() > 3 && relative.compare(relative.size() - 3, 3, ".md") == 0;
                if (markdown && relative.find('/') != std::string::npos) unread_.push_back(it->path().string());
                continue;
            }
            // Only regular files (also through a symlink) are read: a FIFO
            // would wait forever, a device never end.
            std::error_code status_error;
            const bool regular = it->is_regular_file(status_error);
            if (status_error && status_error != std::errc::no_such_file_or_directory)
                throw InputError(it->path().string(), "",
                                 ui_message("file_cannot_read", {{"reason", system_error_text(status_error)}}));
            if (!regular) continue;
            LessonFile file{relative, it->path().string(), read_text(it->path())};
            // A file of the folder replaces the built-in one of the same path (a map: a folder may hold 10^4 files).
            const auto [same, added] = index.emplace(relative, files_.size());
            if (added)
                files_.push_back(std::move(file));
            else
                files_[same->second] = std::move(file);
        }
        if (error) throw InputError(folder, "", ui_message("folder_cannot_read", {{"reason", system_error_text(error)}}));
    }
    std::sort(files_.begin(), files_.end(), [](const LessonFile& a, const LessonFile& b) { return a.path < b.path; });
}

std::vector<Lesson> LessonLibrary::lessons(std::vector<LessonProblem>& problems) const {
    std::vector<Lesson> out;
    for (const LessonFile& file : files_) {
        if (const auto language = language_of(file.path)) out.push_back(parse_lesson(file.text, file.shown, *language, problems));
    }
    return out;
}

std::optional<Lesson> LessonLibrary::find(const std::string& name, Language language) const {
    std::optional<Lesson> found;
    for (const LessonFile& file : files_) {
        if (language_of(file.path) != language) continue;
        std::vector<LessonProblem> problems;
        Lesson lesson = parse_lesson(file.text, file.shown, language, problems);
        if (lesson.header.name != name) continue;
        // Two files with one name (a renamed copy beside the built-in one): neither is the lesson.
        if (found)
            throw InputError(file.shown, message(language, "location_line", {{"line", std::to_string(lesson.header.name_line)}}),
                             message(language, "error_name_twice", {{"name", name}, {"other", found->file}}));
        if (!problems.empty())
            throw InputError(file.shown,
                             message(language, "location_line", {{"line", std::to_string(problems.front().line)}}),
                             problems.front().message);
        found = std::move(lesson);
    }
    return found;
}

Scene LessonLibrary::scene(const std::string& name) const {
    if (name == "article") return article_scene();
    for (const LessonFile& file : files_)
        if (file.path == "scenes/" + name) return parse_scene(file.text, file.shown);
    throw InputError(name, "", ui_message("lesson_no_scene"));
}

void LessonLibrary::dump_builtin(const std::string& folder) {
    // A teacher's edited lessons are never overwritten: every target is
    // checked before the first file is written.
    for (const embedded::EmbeddedFile& file : embedded::lesson_files()) {
        const fs::path path = fs::path(folder) / std::string(file.path);
        std::error_code error;
        if (fs::exists(path, error))
            throw UsageError(ui_message("dump_folder_exists", {{"folder", path.string()}}));
    }
    // All or nothing: a failure (a full disk) removes the files written so
    // far and the folders made for them (DIR/, DIR/en/), so that no
    // half-filled or empty folder is left for the next --dump to refuse.
    std::vector<fs::path> written;
    std::vector<fs::path> created;  // each folder before the folders inside it
    try {
        for (const embedded::EmbeddedFile& file : embedded::lesson_files()) {
            const fs::path path = fs::path(folder) / std::string(file.path);
            std::error_code error;
            std::vector<fs::path> missing;
            for (fs::path up = path.parent_path(); !up.empty() && !fs::exists(up, error); up = up.parent_path()) {
                missing.push_back(up);
                if (up == up.parent_path()) break;
            }
            created.insert(created.end(), missing.rbegin(), missing.rend());
            fs::create_directories(path.parent_path(), error);
            if (error)
                throw OutputError(ui_message("cannot_create", {{"path", path.parent_path().string()},
                                                               {"reason", system_error_text(error)}}));
            AtomicFile out(path.string());
            out.write(file.text);
            out.commit();
            written.push_back(path);
        }
    } catch (...) {
        for (const fs::path& path : written) {
            std::error_code ignored;
            fs::remove(path, ignored);
        }
        for (auto folder_made = created.rbegin(); folder_made != created.rend(); ++folder_made) {
            std::error_code ignored;
            fs::remove(*folder_made, ignored);  // only when empty: never a file the teacher put there since
        }
        throw;
    }
}

}  // namespace promyk
