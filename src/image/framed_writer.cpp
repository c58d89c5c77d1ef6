#include "image/framed_writer.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace promyk {
namespace {

class FramedWriter final : public ImageWriter {
public:
    FramedWriter(std::unique_ptr<ImageWriter> inner, Frame frame, int pane_width, int pane_height)
        : ImageWriter(pane_width, pane_height, inner->channels()), inner_(std::move(inner)), frame_(std::move(frame)) {
        const int n = channels();
        const bool sizes = inner_->width() == framed_width(frame_, pane_width) &&
                           inner_->height() == framed_height(frame_, pane_height) &&
                           (frame_.left.width() == 0 || frame_.left.height() == pane_height) &&
                           (frame_.top.height() == 0 || frame_.top.width() == inner_->width()) &&
                           (frame_.bottom.height() == 0 || frame_.bottom.width() == inner_->width());
        for (const Canvas* c : {&frame_.top, &frame_.left, &frame_.bottom})
            if (c->width() > 0 && c->height() > 0 && c->channels() != n)
                throw std::invalid_argument("framed writer: a strip's channels differ from the image's");
        if (!sizes) throw std::invalid_argument("framed writer: the strips do not fit the image");
        row_.resize(inner_->row_bytes());
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        const int first = rows_written();
        take_rows(count);
        if (first == 0 && count > 0) write_strip(frame_.top);
        const std::size_t left = frame_.left.row_bytes();
        for (int r = 0; r < count; ++r) {
            if (left > 0) std::copy_n(frame_.left.row(first + r), left, row_.data());
            std::copy_n(rows + static_cast<std::size_t>(r) * row_bytes(), row_bytes(), row_.data() + left);
            inner_->write_rows(row_.data(), 1);
        }
    }

    void finish() override {
        require_complete();
        write_strip(frame_.bottom);
        inner_->finish();
    }

private:
    void write_strip(const Canvas& strip) {
        for (int y = 0; y < strip.height(); ++y) inner_->write_rows(strip.row(y), 1);
    }

    std::unique_ptr<ImageWriter> inner_;
    Frame frame_;
    std::vector<std::uint8_t> row_;
};

}  // namespace

int framed_width(const Frame& frame, int pane_width) { return frame.left.width() + pane_width; }
int framed_height(const Frame& frame, int pane_height) {
    return frame.top.height() + pane_height + frame.bottom.height();
}

std::unique_ptr<ImageWriter> frame_image_writer(std::unique_ptr<ImageWriter> inner, Frame frame, int pane_width,
                                                int pane_height) {
    return std::make_unique<FramedWriter>(std::move(inner), std::move(frame), pane_width, pane_height);
}

}  // namespace promyk
