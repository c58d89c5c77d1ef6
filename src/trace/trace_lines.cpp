#include "trace/trace_lines.hpp"

#include "trace/trace_json_parts.hpp"

namespace promyk {

TraceLines::TraceLines(const TraceHeader& header) {
    trace_json::append_opening(opening_, header);
    trace_json::append_stages(stages_, header);
    // Only what the kernels read (w) and what differs from pixel to pixel or
    // kernel to kernel (i, j, the numeric settings) is left.
    pixel_header_.w = header.w;
    pixel_header_.z_E = header.z_E;
    pixel_header_.real = header.real;
    pixel_header_.formula = header.formula;
    pixel_header_.spp = header.spp;
    pixel_header_.effects.clear();
}

void TraceLines::append(std::string& out, const PixelTrace& trace) const {
    out += opening_;
    trace_json::append_pixel(out, trace.header);
    out += stages_;
    trace_json::append_body(out, trace);
    out += '\n';
}

}  // namespace promyk
