// Row and column numbers around a w × w pane drawn at a scale (render
// --labels): i on the left margin, centred on row i's band, and j on the top
// margin, centred on column j's band. When the numbers would touch (a small
// scale, a big w), only every k-th row and column is numbered, k the first of
// 1, 2, 5, 10, 20, 50, ... that leaves room. The image grows by the margins.
#pragma once

#include "image/framed_writer.hpp"

namespace promyk {

struct PaneLabels {
    int size = 1;        // the font's pixel size (bitmap_font.hpp)
    int every = 1;       // k: rows and columns 0, k, 2k, ... are numbered
    int left_width = 0;  // the left margin
    int top_height = 0;  // the top margin
};

// The layout for a w × w pane at `scale`, with or without 1-pixel grid lines.
PaneLabels pane_labels(int w, int scale, bool grid);

// Draws the numbers into frame.top (the image's whole width) and frame.left
// (the pane's height), black on white, in `channels` channels.
void draw_pane_labels(const PaneLabels& labels, int w, int scale, bool grid, int channels, Frame& frame);

}  // namespace promyk
