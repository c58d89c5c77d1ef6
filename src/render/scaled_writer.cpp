// Small panes drawn big: each pixel a scale x scale block, optionally with
// 1-pixel grid lines between the blocks, so an 8 x 8 render can be shown in
// class beside the numbers `promyk trace` prints for its pixels. A wrapper
// around any image writer, with its channels (a block of grey or of RGB
// pixels; grid lines grid_grey in every channel); it streams, holding one
// output row.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "render/image_writer.hpp"

namespace promyk {
namespace {

class ScaledWriter final : public ImageWriter {
public:
    ScaledWriter(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid)
        : ImageWriter(w, w, inner->channels()), inner_(std::move(inner)), scale_(scale), grid_(grid) {
        if (scale < 1) throw std::invalid_argument(fmt::format("scale {} is not positive", scale));
        const long side = scaled_side(w, scale, grid);
        if (inner_->width() != side || inner_->height() != side) {
            throw std::invalid_argument(fmt::format("scaled writer: inner image is {}x{}, expected {}x{}",
                                                    inner_->width(), inner_->height(), side, side));
        }
        row_.resize(inner_->row_bytes());
        grid_row_.assign(inner_->row_bytes(), grid_grey);
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        const int first = rows_written();
        take_rows(count);
        const int w = width();
        const auto n = static_cast<std::size_t>(channels());
        for (int r = 0; r < count; ++r) {
            const std::uint8_t* in = rows + static_cast<std::size_t>(r) * row_bytes();
            std::uint8_t* out = row_.data();
            for (int j = 0; j < w; ++j) {
                if (grid_ && j > 0) out = std::fill_n(out, n, grid_grey);
                if (n == 1) {  // grey: a run of one byte, no per-pixel copy call
                    out = std::fill_n(out, scale_, in[j]);
                } else {
                    const std::uint8_t* pixel = in + static_cast<std::size_t>(j) * n;
                    for (int k = 0; k < scale_; ++k) out = std::copy(pixel, pixel + n, out);
                }
            }
            if (grid_ && first + r > 0) inner_->write_rows(grid_row_.data(), 1);
            for (int k = 0; k < scale_; ++k) inner_->write_rows(row_.data(), 1);
        }
    }

    void finish() override {
        require_complete();
        inner_->finish();
    }

private:
    std::unique_ptr<ImageWriter> inner_;
    int scale_;
    bool grid_;
    std::vector<std::uint8_t> row_;
    std::vector<std::uint8_t> grid_row_;
};

}  // namespace

long scaled_side(int w, int scale, bool grid) {
    return static_cast<long>(w) * scale + (grid ? static_cast<long>(w) - 1 : 0);
}

std::unique_ptr<ImageWriter> scale_image_writer(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid) {
    return std::make_unique<ScaledWriter>(std::move(inner), w, scale, grid);
}

}  // namespace promyk
