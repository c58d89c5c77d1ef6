// Background skipping (render/silhouette.hpp) never changes a pixel: on
// random spheres, on spheres whose silhouette passes exactly through pixel
// centres (a tangent ray, Δ/4 = 0 up to rounding) and on spheres around the
// line of sight (nothing can be proven there), every drawn row equals the
// traced path pixel for pixel on every instruction-set path, and the
// proven columns really are misses of the kernel.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/article_lanes.hpp"
#include "render/article_row.hpp"
#include "render/isa.hpp"
#include "render/kernel.hpp"
#include "render/pane.hpp"
#include "render/renderer.hpp"
#include "render/silhouette.hpp"
#include "render/tracer.hpp"
#include "trace/recorder.hpp"

using namespace promyk;

namespace {

// Rows drawn against the traced path on every path; returns the pixels skipped.
long long check_world(const ArticleWorld<double>& world, int w, int& mismatches) {
    NullRecorder none;
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
    long long skipped = 0;
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (int i = 0; i < w; ++i) {
            const RowCounts drawn = render_row(world, w, i, grey.data());
            int misses = 0;
            for (int j = 0; j < w; ++j) {
                const PixelResult<double> pixel = trace_ray(world, pane_point(i, j, w, world.z_E), none);
                misses += pixel.branch == Branch::miss;
                if (grey[static_cast<std::size_t>(j)] != to_byte(pixel.I_P)) {
                    if (mismatches++ < 5)
                        FAIL_CHECK(isa_name(isa) << ": pixel (" << i << ", " << j << ") drawn "
                                                 << int(grey[static_cast<std::size_t>(j)]) << ", traced "
                                                 << int(to_byte(pixel.I_P)));
                }
            }
            if (drawn.branches[static_cast<int>(Branch::miss)] != misses) ++mismatches;
            if (drawn.sphere_tests + drawn.skipped != w) ++mismatches;
            skipped += drawn.skipped;
        }
    }
    return skipped;
}

ArticleWorld<double> world_of(double x, double y, double z, double r, double z_E = 2) {
    return {z_E, {x, y, z}, r, {1.5, 1, 1}, 1, 0.5};
}

}  // namespace

TEST_CASE("skipping: the proven columns are misses of the kernel's own delta", "[silhouette]") {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> position(-3, 3), depth(2.5, 12), radius(0.05, 2.5);
    int checked = 0, proven = 0;
    for (int s = 0; s < 400; ++s) {
        const ArticleWorld<double> world = world_of(position(random), position(random), depth(random), radius(random));
        const int w = 16 + s % 97;
        std::vector<double> x_E(static_cast<std::size_t>(w));
        for (int j = 0; j < w; ++j) x_E[static_cast<std::size_t>(j)] = pane_x<double>(j, w);
        for (int i = 0; i < w; ++i) {
            const lanes::ArticleRow<double> row(world, pane_y<double>(i, w));
            const RowSpan span = row_hit_span(row, x_E.data(), w);
            REQUIRE(0 <= span.lo);
            REQUIRE(span.lo <= span.hi);
            REQUIRE(span.hi <= w);
            for (int j = 0; j < w; ++j) {
                if (j >= span.lo && j < span.hi) continue;
                ++proven;
                const lanes::LanePixel<lanes::Double2> pixel = lanes::article_lanes(row, lanes::splat<lanes::Double2>(x_E[static_cast<std::size_t>(j)]));
                if (!lanes::lane_of(pixel.miss, 0)) FAIL_CHECK("scene " << s << ", w " << w << ": pixel (" << i << ", " << j << ") skipped but hit");
                ++checked;
            }
        }
    }
    INFO(proven << " pixels proven background");
    CHECK(checked == proven);
    CHECK(proven > 100000);
}

TEST_CASE("skipping never changes a pixel: random spheres, tangent silhouettes, spheres around the line of sight",
          "[silhouette][isa]") {
    int mismatches = 0;
    long long skipped = 0;
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> position(-2, 2), depth(2.5, 9), radius(0.1, 2);
    for (int s = 0; s < 60; ++s) {
        INFO("random sphere " << s);
        skipped += check_world(world_of(position(random), position(random), depth(random), radius(random)), 37 + s, mismatches);
    }
    // Tangent: r chosen so that pixel (i, j)'s ray just touches the sphere,
    // r² = |S|² − C²/|E|², for pixels all over the pane; the neighbours of
    // such a pixel sit on the silhouette too.
    for (int s = 0; s < 40; ++s) {
        const int w = 24 + s;
        const int i = static_cast<int>(random() % static_cast<unsigned>(w)), j = static_cast<int>(random() % static_cast<unsigned>(w));
        const double x = position(random) * 0.5, y = position(random) * 0.5, z = depth(random);
        const Vec3d E = pane_point(i, j, w, 2.0);
        const double C = E.x * x + E.y * y + E.z * z, EE = E.x * E.x + E.y * E.y + E.z * E.z;
        const double rr = x * x + y * y + z * z - C * C / EE;
        if (!(rr > 0.01)) continue;
        INFO("tangent at pixel (" << i << ", " << j << ") of w " << w);
        for (const double nudge : {-1e-15, 0.0, 1e-15})
            skipped += check_world(world_of(x, y, z, std::sqrt(rr) * (1 + nudge)), w, mismatches);
    }
    // Around the line of sight along x (r² ≥ y_S² + z_S²): nothing is proven,
    // every pixel is computed.
    {
        int around = 0;
        const long long none = check_world(world_of(5, 0, 1, 2), 40, around);
        CHECK(none == 0);
        mismatches += around;
    }
    CHECK(mismatches == 0);
    CHECK(skipped > 100000);
}
