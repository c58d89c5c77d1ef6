// The parts of a trace's JSON line (append_trace_json, trace/trace.hpp), in
// the order they are written, so that a writer of many lines
// (trace/trace_lines.hpp) can write once what every pixel of a render shares.
// Internal to trace/.
#pragma once

#include <string>

#include "trace/trace.hpp"

namespace promyk::trace_json {

// {"schema":1,"promyk":...,"scene":...,"scene_hash":...,"scene_file":...,
// "scene_content":{...},"w":8,"z_E":2 — the scene and the pane: the same for
// every pixel of a render.
void append_opening(std::string& out, const TraceHeader& header);

// ,"pixel":{"i":3,"j":4},"numeric":{"real":...,"formula":...,"spp":1} — the
// pixel, and the settings the kernel computed it with.
void append_pixel(std::string& out, const TraceHeader& header);

// ,"effects":[...] and ,"skipped":[...]: the stages, the same for every pixel.
void append_stages(std::string& out, const TraceHeader& header);

// ,"steps":[...],"branch":...,"result":...} — the rest of the line, after
// the header (no newline).
void append_body(std::string& out, const PixelTrace& trace);

}  // namespace promyk::trace_json
