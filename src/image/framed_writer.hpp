// A pane with things drawn around it: a strip above (the column numbers), a
// strip to its left (the row numbers) and a strip below (a map's legend).
// The strips are drawn before the image is written; the pane's rows stream
// through, each after its row of the left strip.
#pragma once

#include <memory>

#include "image/canvas.hpp"
#include "image/image_writer.hpp"

namespace promyk {

struct Frame {
    Canvas top;     // the image's whole width (or empty)
    Canvas left;    // as tall as the pane (or empty)
    Canvas bottom;  // the image's whole width (or empty)

    bool empty() const { return top.height() == 0 && left.width() == 0 && bottom.height() == 0; }
};

// The image a pane of pane_width × pane_height makes inside `frame`.
int framed_width(const Frame& frame, int pane_width);
int framed_height(const Frame& frame, int pane_height);

// Wraps `inner`, of framed_width × framed_height: takes the pane's rows
// (pane_width pixels of inner's channels), writes the top strip before the
// first, the left strip's row before each, the bottom strip at finish().
// std::invalid_argument if the sizes or channels disagree.
std::unique_ptr<ImageWriter> frame_image_writer(std::unique_ptr<ImageWriter> inner, Frame frame, int pane_width,
                                                int pane_height);

}  // namespace promyk
