// Small panes drawn big: each pixel a scale x scale block, optionally with
// 1-pixel grid lines between the blocks, so an 8 x 8 render can be shown in
// class beside the numbers `promyk trace` prints for its pixels. A wrapper
// around any image writer; it streams, holding one output row.
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "render/image_writer.hpp"

namespace promyk {
namespace {

class ScaledWriter final : public ImageWriter {
public:
    ScaledWriter(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid)
        : ImageWriter(w, w), inner_(std::move(inner)), scale_(scale), grid_(grid) {
        if (scale < 1) throw std::invalid_argument(fmt::format("scale {} is not positive", scale));
        const long side = scaled_side(w, scale, grid);
        if (inner_->width() != side || inner_->height() != side) {
            throw std::invalid_argument(fmt::format("scaled writer: inner image is {}x{}, expected {}x{}",
                                                    inner_->width(), inner_->height(), side, side));
        }
        row_.resize(static_cast<std::size_t>(side));
        grid_row_.assign(static_cast<std::size_t>(side), grid_grey);
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        const int first = rows_written();
        take_rows(count);
        const int w = width();
        for (int r = 0; r < count; ++r) {
            const std::uint8_t* in = rows + static_cast<std::size_t>(r) * static_cast<std::size_t>(w);
            std::size_t x = 0;
            for (int j = 0; j < w; ++j) {
                if (grid_ && j > 0) row_[x++] = grid_grey;
                for (int k = 0; k < scale_; ++k) row_[x++] = in[j];
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
