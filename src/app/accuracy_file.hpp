// The JSON of `promyk bench accuracy --json` read back (promyk export
// --bench): checked against what the page's plot needs from
// src/bench/accuracy.schema.json, so a bad file is refused here with its
// file and JSON pointer (exit 3), not drawn wrong in the browser.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace promyk::app {

// The file's JSON, or InputError(path, "/results/3/ratio", why).
nlohmann::json read_accuracy_file(const std::string& text, const std::string& path);

}  // namespace promyk::app
