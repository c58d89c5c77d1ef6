// Small panes drawn big: each pixel a scale x scale block, optionally with
// 1-pixel grid lines between the blocks, so an 8 x 8 render can be shown in
// class beside the numbers `promyk trace` prints for its pixels. A wrapper
// around any image writer, with its channels (a block of grey or of RGB
// pixels); each grid line pixel is a grey that contrasts with the squares it
// borders (image/grid_contrast.hpp). It streams, holding one output row and
// the previous input row (for the line between two rows).
#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "image/canvas.hpp"
#include "image/grid_contrast.hpp"
#include "image/image_writer.hpp"

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
        grid_row_.resize(inner_->row_bytes());
        luma_.resize(static_cast<std::size_t>(w));
        previous_luma_.resize(static_cast<std::size_t>(w));
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        const int first = rows_written();
        take_rows(count);
        const int w = width();
        const auto n = static_cast<std::size_t>(channels());
        for (int r = 0; r < count; ++r) {
            const std::uint8_t* in = rows + static_cast<std::size_t>(r) * row_bytes();
            std::uint8_t* out = row_.data();
            if (grid_) {
                luma_.swap(previous_luma_);
                for (int j = 0; j < w; ++j) {
                    const std::uint8_t* p = in + static_cast<std::size_t>(j) * n;
                    luma_[static_cast<std::size_t>(j)] = n == 1 ? p[0] : luminance(p[0], p[1], p[2]);
                }
            }
            for (int j = 0; j < w; ++j) {
                if (grid_ && j > 0) out = std::fill_n(out, n, contrasting_grey({luma(j - 1), luma(j)}));
                if (n == 1) {  // grey: a run of one byte, no per-pixel copy call
                    out = std::fill_n(out, scale_, in[j]);
                } else {
                    const std::uint8_t* pixel = in + static_cast<std::size_t>(j) * n;
                    for (int k = 0; k < scale_; ++k) out = std::copy(pixel, pixel + n, out);
                }
            }
            if (grid_ && first + r > 0) {
                fill_grid_row(w, n);
                inner_->write_rows(grid_row_.data(), 1);
            }
            for (int k = 0; k < scale_; ++k) inner_->write_rows(row_.data(), 1);
        }
    }

    void finish() override {
        require_complete();
        inner_->finish();
    }

private:
    int luma(int j) const { return luma_[static_cast<std::size_t>(j)]; }
    int above(int j) const { return previous_luma_[static_cast<std::size_t>(j)]; }

    // The line between the previous row and this one: under each block a grey
    // against the squares above and below, at each crossing against all four.
    void fill_grid_row(int w, std::size_t n) {
        std::uint8_t* out = grid_row_.data();
        for (int j = 0; j < w; ++j) {
            if (j > 0) out = std::fill_n(out, n, contrasting_grey({above(j - 1), above(j), luma(j - 1), luma(j)}));
            out = std::fill_n(out, n * static_cast<std::size_t>(scale_), contrasting_grey({above(j), luma(j)}));
        }
    }

    std::unique_ptr<ImageWriter> inner_;
    int scale_;
    bool grid_;
    std::vector<std::uint8_t> row_;
    std::vector<std::uint8_t> grid_row_;
    std::vector<int> luma_, previous_luma_;  // the input rows' luminances, with a grid
};

}  // namespace

long scaled_side(int w, int scale, bool grid) {
    return static_cast<long>(w) * scale + (grid ? static_cast<long>(w) - 1 : 0);
}

std::unique_ptr<ImageWriter> scale_image_writer(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid) {
    return std::make_unique<ScaledWriter>(std::move(inner), w, scale, grid);
}

}  // namespace promyk
