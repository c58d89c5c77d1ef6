// The grey of a grid line pixel that stands out from every square it
// borders: two squares along a line, four at a crossing. Of black, white and
// the greys halfway between two neighbours' luminances, the one farthest
// from the nearest neighbour; black first on a tie. Black lines over light
// squares, white over dark ones, mid-grey between black and white: the
// margin from each square is at least 64 on a line (two squares) and 32 at a
// crossing (four).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>

namespace promyk {

inline std::uint8_t contrasting_grey(std::initializer_list<int> luminances) {
    int sorted[4] = {};
    int n = 0;
    for (const int l : luminances) {  // insertion: at most four
        if (n == 4) break;
        int k = n++;
        for (; k > 0 && sorted[k - 1] > l; --k) sorted[k] = sorted[k - 1];
        sorted[k] = l;
    }
    auto margin = [&](int level) {
        int nearest = 255;
        for (int k = 0; k < n; ++k) nearest = std::min(nearest, std::abs(level - sorted[k]));
        return nearest;
    };
    int best = 0, best_margin = margin(0);
    auto consider = [&](int level) {
        const int m = margin(level);
        if (m > best_margin) best = level, best_margin = m;
    };
    consider(255);
    for (int k = 0; k + 1 < n; ++k) consider((sorted[k] + sorted[k + 1] + 1) / 2);
    return static_cast<std::uint8_t>(best);
}

}  // namespace promyk
