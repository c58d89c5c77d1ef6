// A small in-memory picture (the margins and the legend around a rendered
// pane): width × height pixels of 1 (grey) or 3 (r, g, b) bytes. Drawing
// clips at the edges, so a caller may draw partly outside.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace promyk {

struct Paint {
    std::uint8_t r = 0, g = 0, b = 0;
    static constexpr Paint grey(std::uint8_t v) { return {v, v, v}; }
};

// Rec. 709 luma of an sRGB colour on 0..255 (integer weights summing to 256).
inline int luminance(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return (54 * r + 183 * g + 19 * b + 128) >> 8;
}
inline int luminance(Paint c) { return luminance(c.r, c.g, c.b); }

class Canvas {
public:
    Canvas() = default;
    // A canvas filled with `background`; a grey canvas (channels 1) keeps its r.
    Canvas(int width, int height, int channels, Paint background = Paint::grey(255));

    int width() const noexcept { return width_; }
    int height() const noexcept { return height_; }
    int channels() const noexcept { return channels_; }
    const std::uint8_t* row(int y) const { return pixels_.data() + static_cast<std::size_t>(y) * row_bytes(); }
    std::size_t row_bytes() const noexcept {
        return static_cast<std::size_t>(width_) * static_cast<std::size_t>(channels_);
    }

    // The rectangle [x, x + w) × [y, y + h), clipped to the canvas.
    void fill(int x, int y, int w, int h, Paint colour);
    void put(int x, int y, Paint colour) { fill(x, y, 1, 1, colour); }
    Paint at(int x, int y) const;

private:
    int width_ = 0, height_ = 0, channels_ = 1;
    std::vector<std::uint8_t> pixels_;
};

}  // namespace promyk
