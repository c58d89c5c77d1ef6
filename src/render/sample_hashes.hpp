// The part of a sample's hash (render/samples.hpp's sample_hash) that does
// not depend on the row: mix32(j hash_j ^ mix32(s + hash_s)) for column j
// and sample s. The sampled rows in lanes (render/sample_lanes.hpp) read it
// from a table made once per thread and pane instead of computing it for
// every pixel of every row: one load where eight integer operations were.
#pragma once

#include <cstdint>

namespace promyk {

// The table for a w-pixel pane at spp samples: entry s * stride + j, for
// j = 0 .. stride - 1, stride = w + 16 (the last vector of a row reads past
// w). Null when it would be larger than column_hashes_max_bytes (then the
// rows compute it). Valid until this thread asks for another pane.
struct ColumnHashes {
    const std::uint32_t* hashes = nullptr;
    int stride = 0;
};
inline constexpr long long column_hashes_max_bytes = 4LL << 20;
ColumnHashes sample_column_hashes(int w, int spp);

}  // namespace promyk
