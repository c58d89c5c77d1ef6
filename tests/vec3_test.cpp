#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "math/vec3.hpp"
#include "render/pane.hpp"
#include "image/quantize.hpp"

using promyk::Vec3d;

TEST_CASE("Vec3 operations follow the article's formulas", "[math]") {
    const Vec3d P{1, 2, 3}, Q{4, -5, 6};
    CHECK((P - Q) == Vec3d{-3, 7, -3});
    CHECK((P + Q) == Vec3d{5, -3, 9});
    CHECK((2.0 * P) == Vec3d{2, 4, 6});
    CHECK(promyk::dot(P, Q) == 1 * 4 + 2 * -5 + 3 * 6);
    CHECK(promyk::length_squared(P) == 14);
}

TEST_CASE("dot sums left to right, as the program writes it", "[math]") {
    // Three products a, b, c can be summed in three ways: (a + b) + c (left
    // to right, the program's), a + (b + c) and (a + c) + b. With 1 and
    // +-1e16 (1e16 +- 1 rounds back to 1e16: the spacing there is 2) each
    // vector below tells the left-to-right sum from the others:
    const Vec3d ones{1, 1, 1};
    // (1e16 + -1e16) + 1 = 1; 1e16 + (-1e16 + 1) = 0; (1e16 + 1) + -1e16 = 0.
    CHECK(promyk::dot(Vec3d{1e16, -1e16, 1}, ones) == 1.0);
    // (1 + 1e16) + -1e16 = 0; 1 + (1e16 + -1e16) = 1.
    CHECK(promyk::dot(Vec3d{1, 1e16, -1e16}, ones) == 0.0);
    // (1e16 + 1) + -1e16 = 0; (1e16 + -1e16) + 1 = 1.
    CHECK(promyk::dot(Vec3d{1e16, 1, -1e16}, ones) == 0.0);
    // The same through the products: x_P x_Q + y_P y_Q + z_P z_Q.
    CHECK(promyk::dot(Vec3d{2e16, -1e16, 0.5}, Vec3d{0.5, 1, 2}) == 1.0);
}

TEST_CASE("pane: pixel (i, j) maps to the centre of its square", "[pane]") {
    // The article's Fig. 2: a 4 x 4 pane, square (3, 2) -> E = (0.25, -0.75, z_E).
    const Vec3d E = promyk::pane_point(3, 2, 4, 2.0);
    CHECK(E == Vec3d{0.25, -0.75, 2});
    // i is the row from the top: row 0 is at the top (y_E > 0), column 0 at the left (x_E < 0).
    const Vec3d top_left = promyk::pane_point(0, 0, 8, 2.0);
    CHECK(top_left == Vec3d{-0.875, 0.875, 2});
    // w = 1: the one pixel is the pane's centre.
    CHECK(promyk::pane_point(0, 0, 1, 3.0) == Vec3d{0, 0, 3});
}

TEST_CASE("intensity to 8 bits is round(clamp(v, 0, 1) * 255)", "[quantize]") {
    using promyk::to_byte;
    CHECK(to_byte(0.0) == 0);
    CHECK(to_byte(1.0) == 255);
    CHECK(to_byte(0.5) == 128);  // 127.5 rounds half up
    CHECK(to_byte(127.0 / 255) == 127);
    CHECK(to_byte(std::nextafter(127.5, 0.0) / 255) == 127);
    CHECK(to_byte(-0.25) == 0);
    CHECK(to_byte(7.0) == 255);
    CHECK(to_byte(std::numeric_limits<double>::quiet_NaN()) == 0);
    CHECK(to_byte(std::numeric_limits<double>::infinity()) == 255);
    // Every grey level k is reached by k / 255 exactly.
    for (int k = 0; k <= 255; ++k) CHECK(to_byte(k / 255.0) == k);
}
