// Background skipping (render/silhouette.hpp) never changes a pixel: on
// random spheres, on spheres whose silhouette passes exactly through pixel
// centres (a tangent ray, Δ/4 = 0 up to rounding) and on spheres around the
// line of sight (nothing can be proven there), every drawn row equals the
// traced path pixel for pixel on every instruction-set path, and the
// proven columns really are misses of the kernel, with each formula that
// skips (the article's and stable: the program's Δ/4; fma: Kahan's Δ/4;
// geometric: its delta_g), and the bounds the proofs rest on hold against quad.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "lane_worlds_support.hpp"
#include "math/real.hpp"
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
using lane_worlds_support::lane_formulas;
using lane_worlds_support::traced_ray;

namespace {

// Rows drawn against the traced path on every path, with every formula
// that has lanes; returns the pixels skipped.
long long check_world(const ArticleWorld<double>& world, int w, int& mismatches) {
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
    long long skipped = 0;
    for (const Isa isa : supported_isas()) {
      PathForced forced(isa);
      for (const Formula formula : lane_formulas) {
        for (int i = 0; i < w; ++i) {
            const RowCounts drawn = render_row(world, w, i, grey.data(), formula);
            int misses = 0;
            for (int j = 0; j < w; ++j) {
                const PixelResult<double> pixel = traced_ray(world, pane_point(i, j, w, world.z_E), formula);
                misses += pixel.branch == Branch::miss;
                if (grey[static_cast<std::size_t>(j)] != to_byte(pixel.I_P)) {
                    if (mismatches++ < 5)
                        FAIL_CHECK(isa_name(isa) << ", " << formula_name(formula) << ": pixel (" << i << ", " << j << ") drawn "
                                                 << int(grey[static_cast<std::size_t>(j)]) << ", traced "
                                                 << int(to_byte(pixel.I_P)));
                }
            }
            if (drawn.branches[static_cast<int>(Branch::miss)] != misses) ++mismatches;
            if (drawn.sphere_tests + drawn.skipped != w) ++mismatches;
            skipped += drawn.skipped;
        }
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
    long long checked = 0, proven = 0, proven_geometric = 0;
    for (int s = 0; s < 400; ++s) {
        const ArticleWorld<double> world = world_of(position(random), position(random), depth(random), radius(random));
        const int w = 16 + s % 97;
        std::vector<double> x_E(static_cast<std::size_t>(w));
        for (int j = 0; j < w; ++j) x_E[static_cast<std::size_t>(j)] = pane_x<double>(j, w);
        for (int i = 0; i < w; ++i) {
            const lanes::ArticleRow<double> row(world, pane_y<double>(i, w));
            for (const Formula formula : lane_formulas) {
                const RowSpan span = row_hit_span(row, x_E.data(), w, formula);
                REQUIRE(0 <= span.lo);
                REQUIRE(span.lo <= span.hi);
                REQUIRE(span.hi <= w);
                for (int j = 0; j < w; ++j) {
                    if (j >= span.lo && j < span.hi) continue;
                    ++proven;
                    if (formula == Formula::geometric) ++proven_geometric;
                    const bool miss = lanes::with_root(formula, [&](auto root) {
                        const auto pixel = lanes::article_lanes<decltype(root)::template Root>(
                            row, lanes::splat<lanes::Double2>(x_E[static_cast<std::size_t>(j)]));
                        return lanes::lane_of(pixel.miss, 0);
                    });
                    if (!miss)
                        FAIL_CHECK(formula_name(formula) << ", scene " << s << ", w " << w << ": pixel (" << i << ", "
                                                         << j << ") skipped but hit");
                    ++checked;
                }
            }
        }
    }
    INFO(proven << " pixels proven background, " << proven_geometric << " of them with the geometric formula");
    CHECK(checked == proven);
    CHECK(proven > 300000);
    CHECK(proven_geometric > 100000);
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
    // Near the ends of double's range, where the bounds' own arithmetic and
    // the geometric formula's squares of l could overflow or underflow: the
    // article's scene scaled up and down, and a tiny z_E.
    for (const double scale : {1e-160, 1e-120, 1e-60, 1e60, 1e120, 1e150, 1e153, 1e154}) {
        INFO("scaled by " << scale);
        skipped += check_world({2 * scale, {0.5 * scale, 0.25 * scale, 6 * scale}, 1.1 * scale, {1.5, 1, 1}, 1, 0.5},
                               21, mismatches);
    }
    skipped += check_world(world_of(0.3, 0.2, 4, 0.9, 1e-200), 21, mismatches);
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

namespace {

// A ray of the pane through (x, y) at z_E, random or grazing a random
// sphere (y chosen so that the exact Δ is about 0, where it cancels most),
// at scales from 1e-30 to 1e30 a third of the time.
struct Case {
    ArticleWorld<double> world;
    double x, y;
    bool grazing;
};

Case random_case(std::mt19937_64& random, int s) {
    std::uniform_real_distribution<double> unit(-1, 1), depth(1.5, 40), radius(0.01, 3), eye(0.2, 4);
    const double scale = s % 3 == 0 ? 1 : std::pow(10.0, unit(random) * 30);
    Case c{world_of(unit(random) * 3 * scale, unit(random) * 3 * scale, depth(random) * scale,
                    radius(random) * scale, eye(random)),
           unit(random), unit(random), false};
    if (s % 2 != 0) return c;
    const Vec3d S = c.world.S;
    // A direction at angle a = asin(r/|S|) from S: the sphere's rim.
    const double len = std::sqrt(S.x * S.x + S.y * S.y + S.z * S.z);
    const double sin_a = c.world.r / len;
    if (!(sin_a < 1)) return c;
    const double ux = unit(random), uy = unit(random);
    // A random direction perpendicular to S, then the rim's direction
    // S/|S| cos a + perp/|perp| sin a, through the pane at z_E.
    const Vec3d perp{ux * S.z, uy * S.z, -(ux * S.x + uy * S.y)};
    const double p_len = std::sqrt(perp.x * perp.x + perp.y * perp.y + perp.z * perp.z);
    if (!(p_len > 0)) return c;
    const double cos_a = std::sqrt(1 - sin_a * sin_a);
    const Vec3d d{S.x / len * cos_a + perp.x / p_len * sin_a, S.y / len * cos_a + perp.y / p_len * sin_a,
                  S.z / len * cos_a + perp.z / p_len * sin_a};
    if (!(d.z > 0)) return c;
    c.x = d.x / d.z * c.world.z_E, c.y = d.y / d.z * c.world.z_E, c.grazing = true;
    return c;
}

// The exact Δ/4 = C² − |E|²(|S|² − r²) at the case's E, in quad.
quad exact_delta(const Case& c) {
    const quad xq = c.x, yq = c.y, zq = c.world.z_E, Sx = c.world.S.x, Sy = c.world.S.y, Sz = c.world.S.z,
               rq = c.world.r;
    const quad Cq = xq * Sx + yq * Sy + zq * Sz, EEq = xq * xq + yq * yq + zq * zq;
    return Cq * Cq - EEq * (Sx * Sx + Sy * Sy + Sz * Sz - rq * rq);
}

}  // namespace

// The article's, stable and fma skipping rest on one bound: the kernel's Δ̂,
// the article's products or Kahan's fmas, is within e = row_error of the
// exact Δ for |x| ≤ 1 (render/silhouette.hpp).
TEST_CASE("skipping: the article's and Kahan's delta are within the row's bound of the exact one", "[silhouette]") {
    std::mt19937_64 random(29);
    double worst_article = 0, worst_fma = 0;  // the largest |computed − exact| / e
    int grazing = 0, checked = 0;
    for (int s = 0; s < 200000; ++s) {
        const Case c = random_case(random, s);
        if (!(std::fabs(c.x) <= 1)) continue;  // the bound is the pane's, |x| ≤ 1
        grazing += c.grazing, ++checked;
        const lanes::ArticleRow<double> row(c.world, c.y);
        const double EE = (c.x * c.x + row.yy) + row.zz;
        const double C = (c.x * c.world.S.x + row.ySy) + row.zSz;
        const lanes::FmaRoot<double> kahan(row, c.x, EE, C);
        const quad exact = exact_delta(c);
        const double e = silhouette_detail::row_error(row);
        REQUIRE(std::isfinite(e));
        const auto off = [&](double computed) {
            return static_cast<double>(quad_math::fabs(static_cast<quad>(computed) - exact)) / e;
        };
        worst_article = std::max(worst_article, off(silhouette_detail::delta_hat(row, c.x)));
        worst_fma = std::max(worst_fma, off(kahan.delta));
    }
    INFO("largest errors " << worst_article << " (article) and " << worst_fma << " (fma) of the bound, " << checked
                           << " rays, " << grazing << " grazing");
    CHECK(grazing > 20000);
    CHECK(worst_article <= 1);
    CHECK(worst_fma <= 1);
    // Not a bound so loose that any error would pass.
    CHECK(worst_article > 1.0 / 64);
    CHECK(worst_fma > 1.0 / 256);
}

// The geometric formula's skipping rests on one bound: its computed delta_g
// is within g = 64u(|S|² + r²) of the exact Δ/|E|² (render/silhouette.hpp).
// Checked against quad on random spheres and rays, on rays that graze the
// sphere (where delta_g is nearly 0 and cancels most) and on far spheres.
TEST_CASE("skipping: the geometric formula's delta_g is within its bound of the exact one", "[silhouette]") {
    std::mt19937_64 random(23);
    double worst = 0;  // the largest |computed − exact| / g
    int grazing = 0;
    for (int s = 0; s < 200000; ++s) {
        const Case c = random_case(random, s);
        grazing += c.grazing;
        const lanes::ArticleRow<double> row(c.world, c.y);
        const double EE = (c.x * c.x + row.yy) + row.zz;
        const double C = (c.x * c.world.S.x + row.ySy) + row.zSz;
        const lanes::GeometricRoot<double> root(row, c.x, EE, C);
        const quad exact = exact_delta(c) / ((static_cast<quad>(c.x) * c.x + static_cast<quad>(c.y) * c.y) +
                                             static_cast<quad>(c.world.z_E) * c.world.z_E);
        const double g = silhouette_detail::geometric_error(row);
        const double off = static_cast<double>(quad_math::fabs(static_cast<quad>(root.delta_g) - exact)) / g;
        if (off > worst) worst = off;
    }
    INFO("largest error " << worst << " of the bound, " << grazing << " grazing rays");
    CHECK(grazing > 50000);
    CHECK(worst <= 1);
    // Not a bound so loose that any error would pass: the worst case uses a
    // few percent of it (64 units of roundoff against the dozen or so that occur).
    CHECK(worst > 1.0 / 64);
}
