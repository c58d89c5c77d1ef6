// A size in bytes as people read it in messages: "17.8 MB", "250 MB", "812 B".
#pragma once

#include <string>

namespace promyk {

// SI units (kB, MB, GB, ... as disks are sold); one decimal below 100 of a
// unit, none above; a decimal comma in Polish (ui_language).
std::string byte_size_text(double bytes);

}  // namespace promyk
