// Scene files: the entry points that read them (a file, or its bytes).

#include "scene/scene_json.hpp"

#include <cerrno>
#include <system_error>

#include "scene/scene_parse.hpp"
#include "scene/scene_validate.hpp"
#include "trace/messages.hpp"
#include "util/interrupt.hpp"
#include "util/read_input.hpp"

namespace promyk {

namespace {

std::string errno_text(int error) { return std::error_code(error, std::generic_category()).message(); }

}  // namespace

// Read whole by util/read_input (a FIFO's writer waited for, any interrupt
// honoured), then parsed.
Scene load_scene_file(const std::string& path) {
    const WholeFile file = read_whole_file(path, max_scene_file_bytes);
    switch (file.failure) {
        case WholeFile::Failure::none:
            break;
        case WholeFile::Failure::cannot_open:
            throw SceneFileError(path, ui_message("scene_cannot_open", {{"reason", errno_text(file.error)}}),
                                 file.error);
        case WholeFile::Failure::cannot_read:
            throw SceneFileError(path, ui_message("scene_cannot_read", {{"reason", errno_text(file.error)}}),
                                 file.error);
        case WholeFile::Failure::too_large:
            scene_detail::reject(path, "",
                                 ui_message("scene_file_too_large", {{"limit", std::to_string(max_scene_file_bytes)}}));
    }
    return load_scene_text(file.bytes, path);
}

Scene load_scene_text(std::string_view bytes, const std::string& name) {
    scene_detail::ParsedJson parsed = scene_detail::parse_json(bytes, name);
    throw_if_interrupted();  // parsing a scene of thousands of objects is render's longest step before the probe
    return scene_detail::validate_scene(parsed, name);
}

Scene parse_scene(std::string_view text, const std::string& source) { return load_scene_text(text, source); }

}  // namespace promyk
