#include "image/pane_labels.hpp"

#include <algorithm>
#include <string>

#include "image/bitmap_font.hpp"
#include "image/image_writer.hpp"

namespace promyk {
namespace {

constexpr Paint ink = Paint::grey(0);
constexpr Paint paper = Paint::grey(255);

int digit_height(int size) { return (font::ink_bottom - font::ink_top + 1) * size; }

}  // namespace

PaneLabels pane_labels(int w, int scale, bool grid) {
    PaneLabels labels;
    // Numbers about a third of a big square's height, never below one font pixel.
    labels.size = std::clamp(scale / 16, 1, 4);
    const int s = labels.size;
    const int widest = text_width(std::to_string(w - 1), s);
    const int needed = std::max(widest, digit_height(s)) + 2 * s;  // a number and a gap
    const long pitch = scale + (grid ? 1 : 0);
    long k = 1;
    for (int step = 0; k * pitch < needed; ++step) k = (step % 3 == 1 ? k * 5 / 2 : k * 2);  // 1, 2, 5, 10, 20, 50, ...
    labels.every = static_cast<int>(k);
    labels.left_width = widest + 4 * s;
    labels.top_height = digit_height(s) + 4 * s;
    return labels;
}

void draw_pane_labels(const PaneLabels& labels, int w, int scale, bool grid, int channels, Frame& frame) {
    const int s = labels.size;
    const int side = static_cast<int>(scaled_side(w, scale, grid));
    const int pitch = scale + (grid ? 1 : 0);
    frame.top = Canvas(labels.left_width + side, labels.top_height, channels, paper);
    frame.left = Canvas(labels.left_width, side, channels, paper);
    const int pad = 2 * s;
    for (int n = 0; n < w; n += labels.every) {
        const std::string text = std::to_string(n);
        const int width = text_width(text, s);
        // Row n: right-aligned, its digits' middle on the band's middle;
        // kept inside the pane's height (it may reach up into the corner).
        int ink_y = n * pitch + (scale - digit_height(s)) / 2;
        ink_y = std::max(pad - labels.top_height, std::min(ink_y, side - digit_height(s)));
        const int x = labels.left_width - pad - width;
        draw_text(frame.left, x, ink_y - font::ink_top * s, text, s, ink);
        draw_text(frame.top, x, labels.top_height + ink_y - font::ink_top * s, text, s, ink);
        // Column n: centred on the band, kept inside the image.
        int x_col = labels.left_width + n * pitch + (scale - width) / 2;
        x_col = std::max(labels.left_width, std::min(x_col, frame.top.width() - width));
        draw_text(frame.top, x_col, pad - font::ink_top * s, text, s, ink);
    }
}

}  // namespace promyk
