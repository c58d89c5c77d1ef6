#include "image/canvas.hpp"

#include <algorithm>
#include <stdexcept>

namespace promyk {

Canvas::Canvas(int width, int height, int channels, Paint background)
    : width_(width), height_(height), channels_(channels) {
    if (width < 0 || height < 0 || (channels != 1 && channels != 3))
        throw std::invalid_argument("canvas: bad size or channels");
    pixels_.resize(row_bytes() * static_cast<std::size_t>(height));
    fill(0, 0, width, height, background);
}

void Canvas::fill(int x, int y, int w, int h, Paint colour) {
    const int x0 = std::max(x, 0), y0 = std::max(y, 0);
    const int x1 = std::min(x + w, width_), y1 = std::min(y + h, height_);
    for (int yy = y0; yy < y1; ++yy) {
        std::uint8_t* p = pixels_.data() + static_cast<std::size_t>(yy) * row_bytes();
        for (int xx = x0; xx < x1; ++xx) {
            if (channels_ == 1) {
                p[xx] = colour.r;
            } else {
                p[3 * xx] = colour.r, p[3 * xx + 1] = colour.g, p[3 * xx + 2] = colour.b;
            }
        }
    }
}

Paint Canvas::at(int x, int y) const {
    const std::uint8_t* p = row(y);
    if (channels_ == 1) return Paint::grey(p[x]);
    return {p[3 * x], p[3 * x + 1], p[3 * x + 2]};
}

}  // namespace promyk
