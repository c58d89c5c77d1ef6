// Rows drawn from several samples a pixel in lanes (render/sample_lanes.hpp)
// give every pixel the bits the traced path gives it: render/sampling.hpp's
// sample_pixel over trace_ray, the path tracing records through. Mean, branch
// (the centre sample's), grey level and the row's counts (disagreeing pixels
// too), on every instruction-set path this processor has, with each formula
// that has lanes, on the example scenes, the hard cases (silhouettes tangent
// to pixel centres, huge and tiny scales), non-finite worlds and random spheres.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lane_worlds_support.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/article_row.hpp"
#include "render/float_row.hpp"
#include "render/isa.hpp"
#include "render/sample_hashes.hpp"
#include "render/sampling.hpp"
#include "render/stages.hpp"
#include "render/tracer.hpp"
#include "render/world.hpp"
#include "geometry/sphere_formulas.hpp"
#include "scene/scene_json.hpp"
#include "sweep_size.hpp"

namespace {

using namespace promyk;
using namespace lane_worlds_support;

// The example scenes, hard cases and non-finite worlds, and random spheres.
std::vector<NamedWorld> sample_worlds() {
    std::vector<NamedWorld> worlds = article_worlds();
    int s = 0;
    for (const ArticleWorld<double>& world : random_worlds(12)) worlds.push_back({"random " + std::to_string(s++), world, 0});
    return worlds;
}

struct PaneCheck {
    int mismatches = 0, count_mismatches = 0;
    long long disagreeing = 0, non_finite = 0, skipped = 0;
};

bool sampled_in_lanes(const ArticleWorld<double>& world, int w, int i, int spp, std::uint8_t* grey, Formula formula,
                      RowCounts& drawn, double* I_P, std::uint8_t* branches) {
    return sampled_row_in_lanes(world, w, i, spp, grey, formula, drawn, I_P, branches);
}
bool sampled_in_lanes(const ArticleWorld<float>& world, int w, int i, int spp, std::uint8_t* grey, Formula formula,
                      RowCounts& drawn, float* I_P, std::uint8_t* branches) {
    return sampled_float_row_in_lanes(world, w, i, spp, grey, formula, drawn, I_P, branches);
}

// Every pixel of the w x w pane at spp samples: the lanes' row against
// sample_pixel over trace_ray, in double or in float.
template <class Real>
PaneCheck check_sampled_pane(const ArticleWorld<Real>& world, int w, int spp, Formula formula, std::vector<int> rows = {}) {
    PaneCheck check;
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w)), branches(static_cast<std::size_t>(w));
    std::vector<Real> I_P(static_cast<std::size_t>(w));
    if (rows.empty())
        for (int i = 0; i < w; ++i) rows.push_back(i);
    for (const int i : rows) {
        RowCounts drawn;
        REQUIRE(sampled_in_lanes(world, w, i, spp, grey.data(), formula, drawn, I_P.data(), branches.data()));
        RowCounts traced;
        traced.sphere_tests = static_cast<long long>(w) * spp;
        for (int j = 0; j < w; ++j) {
            const SampledPixel<Real> pixel = sample_pixel<Real>(
                w, i, j, spp, world.z_E, [&](int, const Vec3<Real>& E) { return traced_ray(world, E, formula); },
                [](int, const PixelResult<Real>&) {});
            ++traced.branches[static_cast<int>(pixel.branch)];
            if (!pixel.agree()) ++traced.disagreeing;
            if (pixel.branch == Branch::non_finite && traced.first_non_finite_j < 0) traced.first_non_finite_j = j;
            const auto k = static_cast<std::size_t>(j);
            const bool same = same_bits(pixel.I_P, I_P[k]) && static_cast<std::uint8_t>(pixel.branch) == branches[k] &&
                              to_byte(static_cast<double>(pixel.I_P)) == grey[k];
            if (!same && ++check.mismatches <= 3) {
                INFO("pixel (" << i << ", " << j << "), spp " << spp << ": traced " << pixel.I_P << " ("
                               << branch_name(pixel.branch) << "), lanes " << I_P[k] << " ("
                               << branch_name(static_cast<Branch>(branches[k])) << ")");
                CHECK(false);
            }
        }
        for (int b = 0; b < branch_count; ++b) check.count_mismatches += drawn.branches[b] != traced.branches[b];
        check.count_mismatches += drawn.disagreeing != traced.disagreeing;
        check.count_mismatches += drawn.first_non_finite_j != traced.first_non_finite_j;
        // A pixel is either tested, every sample, or skipped as proven background.
        check.count_mismatches += drawn.sphere_tests + static_cast<long long>(drawn.skipped) * spp != traced.sphere_tests;
        check.skipped += drawn.skipped;
        check.disagreeing += traced.disagreeing;
        check.non_finite += traced.branches[static_cast<int>(Branch::non_finite)];
    }
    return check;
}

}  // namespace

TEST_CASE("Sampled rows in lanes: every pixel's mean, branch, grey level and the row's counts bit-identical to the "
          "traced samples, every instruction-set path, each formula",
          "[sample_lanes][isa][hard]") {
    const std::vector<NamedWorld> worlds = sample_worlds();
    REQUIRE(worlds.size() >= 30);
    const std::vector<Isa> paths = supported_isas();
    long long disagreeing = 0, non_finite = 0;
    long long index = 0;  // of the (path, formula, world, run) checked, for in_sweep
    for (const Isa isa : paths) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            ++index;
            for (const NamedWorld& named : worlds) {
                ++index;
                // Panes and cells (n x n a pixel) of a power of two (the
                // reciprocal's multiplication) and not (the division, or two
                // fmas), each with each; whole vectors of 2, 4 and 8 pixels
                // and not; the hard case's own pane (its tangent pixel centres).
                struct Run {
                    int w, spp;
                };
                std::vector<Run> runs = {{64, 4}, {61, 9}, {67, 16}, {32, 16}, {64, 9}, {32, 25}, {8, 1024}, {5, 1024}};
                if (named.w > 0) runs.push_back({named.w, 4}), runs.push_back({named.w, 9});
                for (const Run run : runs) {
                    if (!in_sweep(++index, 3)) continue;
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << run.w
                                       << ", spp " << run.spp);
                    const PaneCheck check = check_sampled_pane(named.world, run.w, run.spp, formula);
                    CHECK(check.mismatches == 0);
                    CHECK(check.count_mismatches == 0);
                    disagreeing += check.disagreeing;
                    // Most of the article's scene is background, skipped
                    // (render/sample_lanes_span.hpp) with every formula.
                    if (named.name == "article.json" && run.w >= 32)
                        CHECK(check.skipped > static_cast<long long>(run.w) * run.w / 3);
                    non_finite += check.non_finite;
                }
            }
        }
    }
    // The comparison met pixels whose samples disagree (silhouettes) and
    // non-finite ones.
    CHECK(disagreeing > 1000);
    CHECK(non_finite > 100);
}

// --real float's samples in float lanes: their points computed in double,
// as many doubles as floats, rounded to float where sample_point rounds;
// the background skipped with float's bounds. The panes are smaller: the
// float lanes are as wide as sixteen, so every path still meets whole
// vectors and a remainder. The article's scene scaled towards the ends of
// float's range tries the proof's underflow and overflow terms.
TEST_CASE("Sampled rows in float lanes: every pixel's mean, branch, grey level and the row's counts bit-identical to "
          "the traced samples in float, every instruction-set path, each formula",
          "[sample_lanes][isa][float]") {
    std::vector<NamedWorld> worlds = sample_worlds();
    for (const double scale : {1e-18, 1e-12, 1e12, 1e17, 1e19})
        worlds.push_back({"article scaled by " + std::to_string(scale),
                          {2 * scale, {0.5 * scale, 0.25 * scale, 6 * scale}, 1.1 * scale, {1.5, 1, 1}, 1, 0.5},
                          0});
    long long disagreeing = 0, non_finite = 0, skipped = 0;
    long long index = 0;  // as above
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            ++index;
            for (const NamedWorld& named : worlds) {
                ++index;
                const ArticleWorld<float> world = world_as<float>(named.world);
                struct Run {
                    int w, spp;
                };
                std::vector<Run> runs = {{64, 4}, {61, 9}, {35, 16}, {32, 16}, {32, 9}, {5, 1024}};
                if (named.w > 0) runs.push_back({named.w, 4});
                for (const Run run : runs) {
                    if (!in_sweep(++index, 3)) continue;
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << run.w
                                       << ", spp " << run.spp);
                    const PaneCheck check = check_sampled_pane(world, run.w, run.spp, formula);
                    CHECK(check.mismatches == 0);
                    CHECK(check.count_mismatches == 0);
                    if (named.name == "article.json" && run.w >= 32)
                        CHECK(check.skipped > static_cast<long long>(run.w) * run.w / 3);
                    skipped += check.skipped;
                    disagreeing += check.disagreeing;
                    non_finite += check.non_finite;
                }
            }
        }
    }
    CHECK(disagreeing > 1000);
    CHECK(non_finite > 100);
    CHECK(skipped > 100000);
}

// 1024 samples that all fail to be finite: float's branch codes have 32
// bits, and the sum of 1024 non-finite codes wraps to the sum of 1024 lit
// ones; both agree, and the pixel's branch is the centre sample's.
TEST_CASE("Sampled rows in float lanes: 1024 non-finite samples a pixel agree and are counted non-finite",
          "[sample_lanes][float]") {
    ArticleWorld<double> base = sample_worlds().front().world;
    for (const NamedWorld& named : sample_worlds())
        if (named.name == "article.json") base = named.world;
    ArticleWorld<float> world = world_as<float>(base);
    world.r = NAN;  // Δ is not a number in every sample: none is a miss, none finite
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        INFO(isa_name(isa));
        const int w = 20;
        const PaneCheck check = check_sampled_pane(world, w, 1024, Formula::article);
        CHECK(check.mismatches == 0);
        CHECK(check.count_mismatches == 0);
        CHECK(check.non_finite == static_cast<long long>(w) * w);
    }
}

// The hash's (j, s) part comes from a table per pane (render/sample_hashes.hpp)
// unless the table would be too large: then each row computes it. Both ways
// give the same samples: rows of a pane too wide for the table at spp 1024.
TEST_CASE("Sampled rows in lanes: a pane too wide for the column hashes' table gives the traced samples too",
          "[sample_lanes][float]") {
    const int w = 1100, spp = 1024;
    CHECK(sample_column_hashes(w, spp).hashes == nullptr);
    CHECK(sample_column_hashes(64, 16).hashes != nullptr);
    ArticleWorld<double> base = sample_worlds().front().world;
    for (const NamedWorld& named : sample_worlds())
        if (named.name == "article.json") base = named.world;
    long long disagreeing = 0;
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        INFO(isa_name(isa));
        // The rows through the sphere's middle and near its top edge.
        const PaneCheck in_double = check_sampled_pane(base, w, spp, Formula::article, {w / 2, w / 4 + 40});
        const PaneCheck in_float = check_sampled_pane(world_as<float>(base), w, spp, Formula::article, {w / 2, w / 4 + 40});
        CHECK(in_double.mismatches == 0);
        CHECK(in_double.count_mismatches == 0);
        CHECK(in_float.mismatches == 0);
        CHECK(in_float.count_mismatches == 0);
        disagreeing += in_double.disagreeing + in_float.disagreeing;
    }
    CHECK(disagreeing > 0);  // the rows cross the silhouette
}

TEST_CASE("Sampled rows in lanes: one sample is not drawn in lanes", "[sample_lanes]") {
    const NamedWorld named = sample_worlds().front();
    std::vector<std::uint8_t> grey(16);
    RowCounts counts;
    CHECK_FALSE(sampled_row_in_lanes(named.world, 16, 3, 1, grey.data(), Formula::article, counts));
    CHECK_FALSE(sampled_float_row_in_lanes(world_as<float>(named.world), 16, 3, 1, grey.data(), Formula::article, counts));
}
