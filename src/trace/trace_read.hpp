// Reading traces back: one `promyk trace --format json` object, or a trace
// file of `promyk render --traces` (JSON Lines), from its bytes, with no file
// system in between (the web page and the fuzzers call these). Writing a
// trace read from a line (append_trace_json) gives the line back.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "trace/trace.hpp"

namespace promyk {

// Trace files larger than this are refused before reading (a trace of the
// article's scene is about 1.5 kB a pixel: 64 MiB holds about 40,000 pixels).
inline constexpr std::size_t max_trace_file_bytes = std::size_t{64} << 20;

// One trace. The header's `given` and `given_groups` are left empty (they
// are not in the JSON: trace_header of the scene in scene_content makes
// them). InputError naming `file` and `where` (a JSON pointer, or "line L"
// before it in a file) for anything that is not a trace this version writes.
PixelTrace read_trace_json(std::string_view text, const std::string& file, const std::string& where = "");

// A trace file: its lines, each read, in the file's order. Every trace must
// be of the same scene (scene_hash), w and settings (real, formula, spp),
// and each pixel may appear once. Empty lines are skipped.
struct TraceFile {
    std::vector<PixelTrace> traces;
    std::vector<std::string> lines;  // each trace's line as the file holds it
};
TraceFile read_trace_file(std::string_view bytes, const std::string& file);

}  // namespace promyk
