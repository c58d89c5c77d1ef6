// A render sink that keeps the image's bytes, row after row, for the tests
// that compare a whole image (set row_bytes first: w, or 3 w for colour).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/renderer.hpp"

namespace promyk::testing {

struct Collect final : RenderSink {
    std::vector<std::uint8_t> bytes;
    std::size_t row_bytes = 0;
    void image_rows(const std::uint8_t* rows, int count) override {
        bytes.insert(bytes.end(), rows, rows + static_cast<std::size_t>(count) * row_bytes);
    }
};

}  // namespace promyk::testing
