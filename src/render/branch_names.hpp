// The names of the branch atlas's categories: one definition for the CLI's
// legends (render/map_legend.cpp) and the web page's (web_export/wasm).
#pragma once

#include "render/maps.hpp"

namespace promyk {

// The id of the message (lessons/messages_words.json) that names a category.
const char* branch_category_message(BranchCategory category);

}  // namespace promyk
