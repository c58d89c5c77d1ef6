// The kernels' grey levels in lanes (render/article_row_lanes.hpp's
// put_grey_levels) against image/quantize.hpp's to_byte, one value at a
// time: every tie k + 1/2 that a double can reach, its neighbours, the ends
// of [0, 1], and values that are not numbers.
#include <catch2/catch.hpp>

// Four and eight doubles in this baseline unit: every call is inlined, so
// the warning that such a vector's ABI differs without AVX does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "image/quantize.hpp"
#include "render/article_row_lanes.hpp"

using namespace promyk;

namespace {

// Intensities whose y = v · 255 lands on or beside every k + 1/2 and every k.
std::vector<double> hard_intensities(int& exact_ties) {
    std::vector<double> values;
    exact_ties = 0;
    for (int k = 0; k <= 255; ++k) {
        for (const double target : {k + 0.5, static_cast<double>(k)}) {
            const double centre = target / 255;
            double below = centre, above = centre;
            for (int step = 0; step < 64; ++step) {
                below = std::nextafter(below, -1.0);
                above = std::nextafter(above, 2.0);
                values.push_back(below);
                values.push_back(above);
            }
            values.push_back(centre);
        }
    }
    for (const double v : values) {
        const double y = (v > 0 ? (v < 1 ? v : 1) : 0) * 255;
        if (y - std::floor(y) == 0.5) ++exact_ties;
    }
    const double inf = std::numeric_limits<double>::infinity();
    for (const double v : {0.0, -0.0, 1.0, -1.0, 2.0, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::lowest(), std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)})
        values.push_back(v);
    std::mt19937_64 random(20261203);
    std::uniform_real_distribution<double> spread(-0.25, 1.25);
    for (int n = 0; n < 100000; ++n) values.push_back(spread(random));
    return values;
}

template <class Vector>
void check_width(const std::vector<double>& values) {
    constexpr int width = lanes::LaneTraits<Vector>::width;
    std::size_t wrong = 0;
    for (std::size_t k = 0; k + width <= values.size(); k += width) {
        Vector v;
        for (int lane = 0; lane < width; ++lane) v[lane] = values[k + static_cast<std::size_t>(lane)];
        std::uint8_t out[width];
        lanes::put_grey_levels(v, out, width);
        for (int lane = 0; lane < width; ++lane) {
            const double value = values[k + static_cast<std::size_t>(lane)];
            if (out[lane] != to_byte(value)) {
                ++wrong;
                UNSCOPED_INFO("v = " << value << ": lanes " << int(out[lane]) << ", to_byte " << int(to_byte(value)));
            }
        }
    }
    CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("grey levels in lanes are to_byte's, ties and ends included, at every width", "[lanes][grey]") {
    int exact_ties = 0;
    const std::vector<double> values = hard_intensities(exact_ties);
    CHECK(exact_ties > 200);  // the ties are reached, not only their neighbours
    check_width<lanes::Double2>(values);
    check_width<lanes::Double4>(values);
    check_width<lanes::Double8>(values);
}
