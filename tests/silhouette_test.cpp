// Background skipping (render/silhouette.hpp) never changes a pixel: on
// random spheres, on spheres whose silhouette passes exactly through pixel
// centres (a tangent ray, Δ/4 = 0 up to rounding) and on spheres around the
// line of sight (nothing can be proven there), every drawn row equals the
// traced path pixel for pixel on every instruction-set path, and the
// proven columns really are misses of the kernel, with each formula that
// skips (the article's and stable: the program's Δ/4; fma: Kahan's Δ/4;
// geometric: its delta_g), and the bounds the proofs rest on hold against quad.
// The same for float's kernel (--real float), proven with float's bounds.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <type_traits>
#include <vector>

#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "lane_worlds_support.hpp"
#include "math/real.hpp"
#include "render/article_lanes.hpp"
#include "render/article_row.hpp"
#include "render/float_row.hpp"
#include "render/isa.hpp"
#include "render/kernel.hpp"
#include "render/pane.hpp"
#include "render/renderer.hpp"
#include "render/sampling.hpp"
#include "render/sample_lanes_span.hpp"
#include "render/silhouette.hpp"
#include "render/tracer.hpp"
#include "trace/recorder.hpp"

using namespace promyk;
using lane_worlds_support::lane_formulas;
using lane_worlds_support::traced_ray;

namespace {

RowCounts drawn_row(const ArticleWorld<double>& world, int w, int i, std::uint8_t* grey, Formula formula) {
    return render_row(world, w, i, grey, formula);
}
RowCounts drawn_row(const ArticleWorld<float>& world, int w, int i, std::uint8_t* grey, Formula formula) {
    RowCounts counts;
    REQUIRE(float_row_in_lanes(world, w, i, grey, formula, counts));
    return counts;
}

// Rows drawn against the traced path on every path, with every formula
// that has lanes, in double or float; returns the pixels skipped.
template <class Real>
long long check_world(const ArticleWorld<Real>& world, int w, int& mismatches) {
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
    long long skipped = 0;
    for (const Isa isa : supported_isas()) {
      PathForced forced(isa);
      for (const Formula formula : lane_formulas) {
        for (int i = 0; i < w; ++i) {
            const RowCounts drawn = drawn_row(world, w, i, grey.data(), formula);
            int misses = 0;
            for (int j = 0; j < w; ++j) {
                const PixelResult<Real> pixel = traced_ray(world, pane_point<Real>(i, j, w, world.z_E), formula);
                misses += pixel.branch == Branch::miss;
                if (grey[static_cast<std::size_t>(j)] != to_byte(static_cast<double>(pixel.I_P))) {
                    if (mismatches++ < 5)
                        FAIL_CHECK(isa_name(isa) << ", " << formula_name(formula) << ": pixel (" << i << ", " << j << ") drawn "
                                                 << int(grey[static_cast<std::size_t>(j)]) << ", traced "
                                                 << int(to_byte(static_cast<double>(pixel.I_P))));
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

namespace {

template <class Real>
ArticleWorld<Real> world_in(double x, double y, double z, double r, double z_E = 2) {
    return world_as<Real>(world_of(x, y, z, r, z_E));
}

// 400 random spheres on panes of 16 to 112: every column row_hit_span
// proves background, with each formula, is a miss of the kernel in Real
// (its bounds: rounding_of<Real>).
template <class Real>
void check_proven(long long& proven, long long& proven_geometric, long long& failed) {
    using Lanes = std::conditional_t<std::is_same_v<Real, float>, lanes::Float4, lanes::Double2>;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> position(-3, 3), depth(2.5, 12), radius(0.05, 2.5);
    for (int s = 0; s < 400; ++s) {
        const ArticleWorld<Real> world = world_in<Real>(position(random), position(random), depth(random), radius(random));
        const int w = 16 + s % 97;
        std::vector<Real> x_E(static_cast<std::size_t>(w));
        for (int j = 0; j < w; ++j) x_E[static_cast<std::size_t>(j)] = pane_x<Real>(j, w);
        for (int i = 0; i < w; ++i) {
            const lanes::ArticleRow<Real> row(world, pane_y<Real>(i, w));
            const lanes::ArticleRow<double> row_d(world_as<double>(world), row.y_E);
            for (const Formula formula : lane_formulas) {
                const RowSpan span = row_hit_span(row_d, x_E.data(), w, formula, rounding_of<Real>());
                REQUIRE(0 <= span.lo);
                REQUIRE(span.lo <= span.hi);
                REQUIRE(span.hi <= w);
                for (int j = 0; j < w; ++j) {
                    if (j >= span.lo && j < span.hi) continue;
                    ++proven;
                    if (formula == Formula::geometric) ++proven_geometric;
                    const bool miss = lanes::with_root(formula, [&](auto root) {
                        const auto pixel = lanes::article_lanes<decltype(root)::template Root>(
                            row, lanes::splat<Lanes>(x_E[static_cast<std::size_t>(j)]));
                        return lanes::lane_of(pixel.miss, 0);
                    });
                    if (!miss && failed++ < 5)
                        FAIL_CHECK(formula_name(formula) << ", scene " << s << ", w " << w << ": pixel (" << i << ", "
                                                         << j << ") skipped but hit");
                }
            }
        }
    }
}

// Each type's cases for check_never_changes: its random stream, how far a
// tangent radius is nudged (about a unit of the type's roundoff), the scales
// near the ends of its range (where the bounds' own arithmetic and the
// geometric formula's squares of l could overflow or underflow; in float,
// from 1e18 on the products' overflow proves nothing) and a tiny z_E.
template <class Real>
struct NeverChangesCases;
template <>
struct NeverChangesCases<double> {
    static constexpr unsigned seed = 11;
    static constexpr double nudge = 1e-15, tiny_z_E = 1e-200;
    static constexpr double scales[] = {1e-160, 1e-120, 1e-60, 1e60, 1e120, 1e150, 1e153, 1e154};
};
template <>
struct NeverChangesCases<float> {
    static constexpr unsigned seed = 13;
    static constexpr double nudge = 1e-7, tiny_z_E = 1e-20;
    static constexpr double scales[] = {1e-18, 1e-12, 1e-6, 1e6, 1e12, 1e16, 1e17, 1e18, 1e19};
};

// Rows drawn in Real, skipping with Real's bounds (the proofs' arithmetic in
// double on the scene's Real numbers), equal the traced path on every pixel:
// random spheres, silhouettes tangent in Real, the ends of Real's range,
// spheres around the line of sight.
template <class Real>
void check_never_changes() {
    using Cases = NeverChangesCases<Real>;
    int mismatches = 0;
    long long skipped = 0;
    std::mt19937_64 random(Cases::seed);
    std::uniform_real_distribution<double> position(-2, 2), depth(2.5, 9), radius(0.1, 2);
    for (int s = 0; s < 60; ++s) {
        INFO("random sphere " << s);
        skipped += check_world(world_in<Real>(position(random), position(random), depth(random), radius(random)),
                               37 + s, mismatches);
    }
    // Tangent: r chosen so that pixel (i, j)'s ray just touches the sphere,
    // r² = |S|² − C²/|E|² from the pixel's E and the centre in Real (in
    // double, finer than float), for pixels all over the pane; the
    // neighbours of such a pixel sit on the silhouette too.
    for (int s = 0; s < 40; ++s) {
        const int w = 24 + s;
        const int i = static_cast<int>(random() % static_cast<unsigned>(w)), j = static_cast<int>(random() % static_cast<unsigned>(w));
        const double x = static_cast<Real>(position(random) * 0.5), y = static_cast<Real>(position(random) * 0.5),
                     z = static_cast<Real>(depth(random));
        const Vec3<Real> E = pane_point<Real>(i, j, w, Real(2));
        const double C = double(E.x) * x + double(E.y) * y + double(E.z) * z,
                     EE = double(E.x) * E.x + double(E.y) * E.y + double(E.z) * E.z;
        const double rr = x * x + y * y + z * z - C * C / EE;
        if (!(rr > 0.01)) continue;
        INFO("tangent at pixel (" << i << ", " << j << ") of w " << w);
        for (const double nudge : {-Cases::nudge, 0.0, Cases::nudge})
            skipped += check_world(world_in<Real>(x, y, z, std::sqrt(rr) * (1 + nudge)), w, mismatches);
    }
    // The article's scene scaled up and down, and a tiny z_E.
    long long at_ends = 0;
    for (const double scale : Cases::scales) {
        INFO("scaled by " << scale);
        const ArticleWorld<double> scaled{2 * scale, {0.5 * scale, 0.25 * scale, 6 * scale}, 1.1 * scale, {1.5, 1, 1}, 1, 0.5};
        at_ends += check_world(world_as<Real>(scaled), 21, mismatches);
    }
    CHECK(at_ends > 0);
    skipped += at_ends + check_world(world_in<Real>(0.3, 0.2, 4, 0.9, Cases::tiny_z_E), 21, mismatches);
    // Around the line of sight along x (r² ≥ y_S² + z_S²): nothing is proven,
    // every pixel is computed.
    {
        int around = 0;
        const long long none = check_world(world_in<Real>(5, 0, 1, 2), 40, around);
        CHECK(none == 0);
        mismatches += around;
    }
    CHECK(mismatches == 0);
    CHECK(skipped > 100000);
}

}  // namespace

TEST_CASE("skipping: the proven columns are misses of the kernel's own delta, in double and in float",
          "[silhouette][float]") {
    long long proven = 0, proven_geometric = 0, failed = 0;
    check_proven<double>(proven, proven_geometric, failed);
    INFO("double: " << proven << " pixels proven background, " << proven_geometric << " with the geometric formula");
    CHECK(failed == 0);
    CHECK(proven > 300000);
    CHECK(proven_geometric > 100000);
    proven = proven_geometric = 0;
    check_proven<float>(proven, proven_geometric, failed);
    INFO("float: " << proven << " pixels proven background, " << proven_geometric << " with the geometric formula");
    CHECK(failed == 0);
    CHECK(proven > 300000);
    CHECK(proven_geometric > 100000);
}

namespace {

// A ray of the pane through (x, y) at z_E, random or grazing a random
// sphere (y chosen so that the exact Δ is about 0, where it cancels most),
// at scales from 1e-30 to 1e30 a third of the time.
struct SilhouetteCase {
    ArticleWorld<double> world;
    double x, y;
    bool grazing;
};

SilhouetteCase random_case(std::mt19937_64& random, int s) {
    std::uniform_real_distribution<double> unit(-1, 1), depth(1.5, 40), radius(0.01, 3), eye(0.2, 4);
    const double scale = s % 3 == 0 ? 1 : std::pow(10.0, unit(random) * 30);
    SilhouetteCase c{world_of(unit(random) * 3 * scale, unit(random) * 3 * scale, depth(random) * scale,
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
quad exact_delta(const SilhouetteCase& c) {
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
        const SilhouetteCase c = random_case(random, s);
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
        const SilhouetteCase c = random_case(random, s);
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

TEST_CASE("skipping never changes a pixel: random spheres, tangent silhouettes, spheres around the line of sight",
          "[silhouette][isa]") {
    check_never_changes<double>();
}

// --real float's rows skip with the same proofs, float's bounds
// (rounding_of<float>), the proofs' arithmetic in double on the float
// scene's numbers.
TEST_CASE("float skipping never changes a pixel: random spheres, silhouettes tangent in float, float's range ends, "
          "spheres around the line of sight",
          "[silhouette][isa][float]") {
    check_never_changes<float>();
}

// The float kernel's Δ̂ (the article's products, Kahan's fmas) within
// float's row_error of the exact Δ of its own numbers, and its delta_g
// within float's geometric_error, against quad: random, grazing and scaled
// rays (a scale float cannot hold leaves the bound infinite: not checked).
TEST_CASE("skipping in float: the float kernel's delta and delta_g are within float's bounds of the exact ones",
          "[silhouette][float]") {
    std::mt19937_64 random(31);
    const KernelRounding in_float = rounding_of<float>();
    double worst_article = 0, worst_fma = 0, worst_geometric = 0;
    int grazing = 0, checked = 0, checked_geometric = 0;
    for (int s = 0; s < 200000; ++s) {
        const SilhouetteCase d = random_case(random, s);
        const ArticleWorld<float> world = world_as<float>(d.world);
        const float x = static_cast<float>(d.x), y = static_cast<float>(d.y);
        const SilhouetteCase c{world_as<double>(world), x, y, d.grazing};  // the float numbers, exactly
        const lanes::ArticleRow<float> row(world, y);
        const lanes::ArticleRow<double> row_d(c.world, y);
        const float EE = (x * x + row.yy) + row.zz;
        const float C = (x * world.S.x + row.ySy) + row.zSz;
        const quad exact = exact_delta(c);
        const double e = silhouette_detail::row_error(row_d, in_float);
        if (std::fabs(x) <= 1 && std::isfinite(e)) {
            grazing += c.grazing, ++checked;
            const auto off = [&](float computed) {
                return static_cast<double>(quad_math::fabs(static_cast<quad>(computed) - exact)) / e;
            };
            worst_article = std::max(worst_article, off(lanes::ArticleRoot<float>(row, x, EE, C).delta));
            worst_fma = std::max(worst_fma, off(lanes::FmaRoot<float>(row, x, EE, C).delta));
        }
        if (std::isfinite(silhouette_detail::geometric_margin(row_d, in_float))) {
            ++checked_geometric;
            const quad exact_g = exact / ((static_cast<quad>(x) * x + static_cast<quad>(y) * y) +
                                          static_cast<quad>(world.z_E) * world.z_E);
            const double g = silhouette_detail::geometric_error(row_d, in_float);
            const float delta_g = lanes::GeometricRoot<float>(row, x, EE, C).delta_g;
            worst_geometric =
                std::max(worst_geometric, static_cast<double>(quad_math::fabs(static_cast<quad>(delta_g) - exact_g)) / g);
        }
    }
    INFO("largest errors " << worst_article << " (article), " << worst_fma << " (fma), " << worst_geometric
                           << " (geometric) of the bound; " << checked << " rays, " << grazing << " grazing, "
                           << checked_geometric << " for the geometric formula");
    CHECK(checked > 100000);
    CHECK(grazing > 10000);
    CHECK(checked_geometric > 100000);
    CHECK(worst_article <= 1);
    CHECK(worst_fma <= 1);
    CHECK(worst_geometric <= 1);
    // Not bounds so loose that any error would pass.
    CHECK(worst_article > 1.0 / 64);
    CHECK(worst_fma > 1.0 / 256);
    CHECK(worst_geometric > 1.0 / 64);
}

// On panes of millions of columns the columns the proofs test, two or more
// outside the silhouette, lie within a few units of float's roundoff of it:
// there float's bound e itself decides (on smaller panes its margins are
// wide: a proof with double's e for float's kernel passed the tests above
// but the bound's, and fails this one). Double's margins stay wide even here. Random spheres and
// rows, the 48 columns outside each end of the span checked against the
// kernel (rows) and against every sample of sample_pixel over trace_ray
// (sampled rows), in double and in float.
namespace {


template <class Real>
void check_edges(std::mt19937_64& random, int spheres, long long& checked, long long& failures) {
    std::uniform_real_distribution<double> position(-2, 2), depth(2.5, 9), radius(0.1, 2), unit(0, 1);
    for (int s = 0; s < spheres; ++s) {
        const ArticleWorld<Real> world = world_as<Real>(
            world_of(position(random), position(random), depth(random), radius(random)));
        const int w = (1 << 22) - 1 - s % 3;
        const int i = static_cast<int>(unit(random) * w);
        const Real y_E = pane_y<Real>(i, w);
        const lanes::ArticleRow<Real> row(world, y_E);
        const lanes::ArticleRow<double> row_d(world_as<double>(world), y_E);
        const KernelRounding kernel = rounding_of<Real>();
        std::vector<Real> x_E(static_cast<std::size_t>(w));
        for (int j = 0; j < w; ++j) x_E[static_cast<std::size_t>(j)] = pane_x<Real>(j, w);
        for (const Formula formula : lane_formulas) {
            // The centre ray: the columns two and more outside each end.
            const RowSpan span = row_hit_span(row_d, x_E.data(), w, formula, kernel);
            using Lanes = std::conditional_t<std::is_same_v<Real, float>, lanes::Float4, lanes::Double2>;
            const auto missed = [&](int j) {
                return lanes::with_root(formula, [&](auto root) {
                    const auto pixel = lanes::article_lanes<decltype(root)::template Root>(
                        row, lanes::splat<Lanes>(x_E[static_cast<std::size_t>(j)]));
                    return lanes::lane_of(pixel.miss, 0);
                });
            };
            for (int j = std::max(0, span.lo - 48); j < span.lo; ++j, ++checked)
                if (!missed(j) && failures++ < 5) FAIL_CHECK(formula_name(formula) << ": column " << j << " of " << w);
            for (int j = span.hi; j < std::min(w, span.hi + 48); ++j, ++checked)
                if (!missed(j) && failures++ < 5) FAIL_CHECK(formula_name(formula) << ": column " << j << " of " << w);
            // Four samples a pixel: every sample of the 48 columns outside.
            const RowSpan sampled = sampled_row_hit_span(world_as<double>(world), w, i, formula, kernel);
            const auto all_missed = [&](int j) {
                const SampledPixel<Real> pixel = sample_pixel<Real>(
                    w, i, j, 4, world.z_E,
                    [&](int, const Vec3<Real>& E) { return lane_worlds_support::traced_ray(world, E, formula); },
                    [](int, const PixelResult<Real>&) {});
                return pixel.branches[static_cast<int>(Branch::miss)] == 4;
            };
            for (int j = std::max(0, sampled.lo - 48); j < sampled.lo; ++j, ++checked)
                if (!all_missed(j) && failures++ < 5)
                    FAIL_CHECK(formula_name(formula) << ", spp 4: column " << j << " of " << w);
            for (int j = sampled.hi; j < std::min(w, sampled.hi + 48); ++j, ++checked)
                if (!all_missed(j) && failures++ < 5)
                    FAIL_CHECK(formula_name(formula) << ", spp 4: column " << j << " of " << w);
        }
    }
}

}  // namespace

TEST_CASE("skipping on panes of millions of columns: the columns just outside the span are misses, every sample too, "
          "in double and in float",
          "[silhouette][float]") {
    std::mt19937_64 random(37);
    long long checked = 0, failures = 0;
    check_edges<double>(random, 40, checked, failures);
    check_edges<float>(random, 40, checked, failures);
    CHECK(failures == 0);
    CHECK(checked > 20000);
}
