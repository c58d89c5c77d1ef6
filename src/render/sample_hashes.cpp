#include "render/sample_hashes.hpp"

#include <cstddef>
#include <vector>

#include "render/samples.hpp"

namespace promyk {

ColumnHashes sample_column_hashes(int w, int spp) {
    const int stride = w + 16;
    if (static_cast<long long>(stride) * spp * 4 > column_hashes_max_bytes) return {};
    thread_local std::vector<std::uint32_t> table;
    thread_local int table_w = -1, table_spp = -1;
    if (table_w != w || table_spp != spp) {
        table.resize(static_cast<std::size_t>(stride) * static_cast<std::size_t>(spp));
        for (int s = 0; s < spp; ++s) {
            const std::uint32_t sample = mix32(static_cast<std::uint32_t>(s) + hash_s);
            for (int j = 0; j < stride; ++j)
                table[static_cast<std::size_t>(s) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(j)] =
                    mix32(static_cast<std::uint32_t>(j) * hash_j ^ sample);
        }
        table_w = w, table_spp = spp;
    }
    return {table.data(), stride};
}

}  // namespace promyk
