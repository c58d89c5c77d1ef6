// Scene files: the JSON form of a Scene (lessons/scenes/README.md describes
// the format, every field, its default and its constraints).
//
// Reading validates everything the engine of this version relies on and
// throws InputError naming the file and the fault: a JSON pointer for a bad
// field ("/spheres/0/r"), "line L, column C" for a syntax error, or an empty
// `where` for a fault of the file as a whole (missing, empty, too large).
// Faults of the fields are all reported at once (SceneErrors). Messages are
// in the run's language (ui_language()).
//
// The reading is in three parts: scene_parse (bytes to JSON), scene_validate
// (JSON to a Scene, the faults collected), scene_hints (the hint after an
// unknown key); scene_write writes a scene back.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene.hpp"
#include "util/errors.hpp"

namespace promyk {

// Scene files larger than this are refused before parsing.
inline constexpr std::size_t max_scene_file_bytes = std::size_t{1} << 20;  // 1 MiB

// A scene file that could not be opened or read: an InputError (exit 3) with
// an empty `where`, strerror's text in the message, and the errno of the
// failing call (ENOENT, EACCES, EISDIR, EIO, ...).
struct SceneFileError : InputError {
    SceneFileError(std::string file_name, const std::string& what, int error)
        : InputError(std::move(file_name), "", what), error_number(error) {}
    int error_number;
};

// One fault of a scene file: where (a JSON pointer, "line L, column C") and what.
struct SceneFault {
    std::string where, what;
};

// The most faults one error reports; the rest are counted ("and 5 more").
inline constexpr std::size_t max_reported_faults = 20;
// The reading stops after this many faults (a hostile file can hold 400,000):
// the rest are not counted ("and at least 980 more").
inline constexpr std::size_t max_collected_faults = 1000;

// A scene whose fields have faults: the first max_reported_faults of them in
// document order (a missing key where its object ends), and how many more
// (at least that many when the reading stopped at max_collected_faults).
// As an InputError it is the first fault.
struct SceneErrors : InputError {
    SceneErrors(std::string file_name, std::vector<SceneFault> all, std::size_t more_faults, bool all_counted)
        : InputError(std::move(file_name), all.front().where, all.front().what),
          faults(std::move(all)),
          more(more_faults),
          counted(all_counted) {}
    std::vector<SceneFault> faults;
    std::size_t more;
    bool counted;  // false: the reading stopped, and there may be more than `more`
};

// Reads and parses the scene file at `path`; the scene's `source` is `path`.
// Reads to the end of the file, however it arrives (a FIFO, a pipe, a slow
// device). A missing or unreadable file is a SceneFileError. A signal that
// interrupts the reading is Interrupted if it is SIGINT or SIGTERM (see
// util/interrupt.hpp) and is otherwise ignored.
Scene load_scene_file(const std::string& path);

// Reads a scene from its bytes (the file's whole content: the web page and
// the fuzzers call this); `name` names it in errors and becomes the scene's
// `source`.
Scene load_scene_text(std::string_view bytes, const std::string& name);

// The same as load_scene_text.
Scene parse_scene(std::string_view text, const std::string& source);

// Which fields scene_to_json writes when they hold their defaults.
enum class SceneDefaults {
    omitted,  // the canonical form: "shadows", "planes", "materials", an object's
              // "material" and a light's "colour" only when not the default
    written,  // every knob a teacher can turn: "shadows": false, "planes": [],
              // "materials": [], a light's "colour": [1, 1, 1] (an object with
              // the default material still has no "material": it has no index)
};

// The scene as a scene file: pretty, fields in the documented order, every
// number as the shortest text that reads back to the same double, a grey
// background as one number (else [r, g, b]), every field of a material.
// `source` is not written. parse_scene(scene_to_json(s), ...) gives back s
// for every scene that parse_scene accepts.
std::string scene_to_json(const Scene& scene, SceneDefaults defaults = SceneDefaults::omitted);

}  // namespace promyk
