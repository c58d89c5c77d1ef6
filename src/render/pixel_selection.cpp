#include "render/pixel_selection.hpp"

#include <algorithm>
#include <climits>

namespace promyk {

PixelSelection PixelSelection::all() {
    PixelSelection selection;
    selection.all_ = true;
    return selection;
}

void PixelSelection::add_pixel(int i, int j) {
    const std::pair<int, int> pixel{i, j};
    const auto at = std::lower_bound(pixels_.begin(), pixels_.end(), pixel);
    if (at == pixels_.end() || *at != pixel) pixels_.insert(at, pixel);
}

void PixelSelection::add_region(const PixelRegion& region) { regions_.push_back(region); }

bool PixelSelection::contains(int i, int j) const {
    if (all_) return true;
    for (const PixelRegion& r : regions_)
        if (r.i0 <= i && i <= r.i1 && r.j0 <= j && j <= r.j1) return true;
    return std::binary_search(pixels_.begin(), pixels_.end(), std::pair<int, int>{i, j});
}

bool PixelSelection::row_has_any(int i) const {
    if (all_) return true;
    for (const PixelRegion& r : regions_)
        if (r.i0 <= i && i <= r.i1) return true;
    const auto at = std::lower_bound(pixels_.begin(), pixels_.end(), std::pair<int, int>{i, INT_MIN});
    return at != pixels_.end() && at->first == i;
}

}  // namespace promyk
