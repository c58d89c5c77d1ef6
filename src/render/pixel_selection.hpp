// Which pixels of a render get a trace: none, all, or a set of pixels and
// rectangular regions (corners inclusive).
#pragma once

#include <utility>
#include <vector>

namespace promyk {

struct PixelRegion {
    int i0, j0, i1, j1;  // top-left and bottom-right corners, inclusive
};

class PixelSelection {
public:
    static PixelSelection all();

    void add_pixel(int i, int j);
    void add_region(const PixelRegion& region);

    bool empty() const { return !all_ && pixels_.empty() && regions_.empty(); }
    bool is_all() const { return all_; }
    bool contains(int i, int j) const;
    bool row_has_any(int i) const;

private:
    bool all_ = false;
    std::vector<std::pair<int, int>> pixels_;  // sorted by (i, j), unique
    std::vector<PixelRegion> regions_;
};

}  // namespace promyk
