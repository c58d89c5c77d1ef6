// Checking lessons against the vocabulary and against each other:
// `promyk lesson --check`. Every problem names the file and line, in the
// lesson's own language.
#pragma once

#include <vector>

#include "lesson/lesson.hpp"
#include "scene/scene.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

// Why a path (lesson.hpp: "light[0].sphere[1].delta_s") cannot name a value.
enum class PathFault {
    none,
    malformed,      // not kind[N].…key
    unknown_key,    // the key is not in the vocabulary
    unknown_group,  // the kind is not sphere, plane or light
    nesting,        // groups nest only as the trace nests them: light[k].sphere[m], light[k].plane[m]
    not_in_group,   // the trace never records the key in that group (D of a sphere's test)
    index,          // the scene has no such object or light
};

struct PathCheck {
    PathFault fault = PathFault::none;
    std::string group;  // the group at fault ("sphere[2]"), or the kind ("cone")
    std::string keys;   // not_in_group: the keys that group holds; index: how many the scene has
};

// Checks a path against the trace's shape: top-level keys are any key; a
// group holds the keys the tracer records in it (and, for sphere and light,
// the scene's S, r and L, I). With a scene, an index must name one of its
// objects or lights.
PathCheck check_path(const std::string& path, const Vocabulary& vocabulary, const Scene* scene = nullptr);

// Unknown keys and branches, malformed placeholders, pixel values outside a
// block, paths that name no group of the trace (with `scene`: no object of it).
void check_lesson(const Lesson& lesson, const Vocabulary& vocabulary, std::vector<LessonProblem>& problems,
                  const Scene* scene = nullptr);

// A settings qualifier a lesson names ("float", "float,geometric"), where.
struct SettingsUse {
    std::string settings;
    std::string qualified;  // the path as written, "delta@float"
    int line = 0;
};

// Every settings qualifier in the lesson's value tables and placeholders, in order.
std::vector<SettingsUse> settings_used(const Lesson& lesson);

// The keys a lesson asks for (a worksheet's blanks): its placeholders and
// value tables' keys that are pixel numbers, not the scene's values, words,
// symbols or {i}, {j}, {w}, {branch}; qualified ("delta@float", "P.x"), each
// once, in order. An answer file's unknown key is told these.
std::vector<std::string> lesson_keys(const Lesson& lesson, const Vocabulary& vocabulary);

// Every lesson exists in every language, with the same steps in the same order.
void check_translations(const std::vector<Lesson>& lessons, std::vector<LessonProblem>& problems);

// True when a placeholder's value differs from pixel to pixel ({t}, {i}), false
// for the scene's values ({S}, {r}) and {w}. Unknown names count as per-pixel.
bool depends_on_pixel(const std::string& name, const Vocabulary& vocabulary);

}  // namespace promyk
