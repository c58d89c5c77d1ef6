// Files embedded in the binary at build time (cmake/embed_files.cmake): the
// lessons, the messages in each language and the example scenes, so an
// installed promyk runs lessons from any folder.
#pragma once

#include <string_view>
#include <vector>

namespace promyk::embedded {

struct EmbeddedFile {
    std::string_view path;  // relative to lessons/, e.g. "pl/03-sphere.md"
    std::string_view text;
};

// Every file under lessons/ that promyk reads: */NN-name.md, messages.json, scenes/*.json.
const std::vector<EmbeddedFile>& lesson_files();

}  // namespace promyk::embedded
