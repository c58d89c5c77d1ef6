// The JSON Lines of many pixels of one render (render --traces): each line
// is append_trace_json's, byte for byte, but what every pixel's header
// shares (the scene, its text, the pane, the stages) is written once, and
// the kernel is given a header without it, so tracing a pixel copies no
// scene text.
#pragma once

#include <string>

#include "trace/trace.hpp"

namespace promyk {

class TraceLines {
public:
    explicit TraceLines(const TraceHeader& header);

    // The header to trace each pixel with (Kernel::trace): the pane's size
    // and the numeric settings; its scene fields are empty.
    const TraceHeader& pixel_header() const { return pixel_header_; }

    // Appends the line of `trace`, traced with pixel_header(), and a newline.
    void append(std::string& out, const PixelTrace& trace) const;

private:
    TraceHeader pixel_header_;
    std::string opening_;  // {"schema":...,"w":...,"z_E":...
    std::string stages_;   // ,"effects":[...],"skipped":[...]
};

}  // namespace promyk
