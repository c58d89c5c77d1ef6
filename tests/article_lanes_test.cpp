// The article's rows computed lanes at a time (render/article_row.hpp) give
// every pixel the bits the traced path gives it (trace_ray, the one-pixel
// tracer that tracing records through), in double and in float, with the
// article's, the stable and the geometric formula: on the example scenes the
// article's kernel draws, on every hard case it draws (including the
// silhouettes tangent to pixel centres) and on random spheres.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/article_literal.hpp"
#include "hard_cases_support.hpp"
#include "lane_worlds_support.hpp"
#include "isa_forced.hpp"
#include "render/article_row.hpp"
#include "render/float_row.hpp"
#include "render/isa.hpp"
#include "image/quantize.hpp"
#include "render/pane.hpp"
#include "render/renderer.hpp"
#include "render/skipping.hpp"
#include "render/stages.hpp"
#include "render/tracer.hpp"
#include "render/world.hpp"
#include "geometry/sphere_formulas.hpp"
#include "scene/scene_json.hpp"

namespace {

using namespace promyk;
using namespace lane_worlds_support;

// Every pixel of the w x w pane: the lanes' row, the one-lane template and
// the traced path agree bit for bit, branch and intensity.
template <class Real>
int check_pane(const ArticleWorld<Real>& world, int w, Formula formula = Formula::article) {
    int mismatches = 0;
    std::vector<Real> I_P(static_cast<std::size_t>(w));
    std::vector<std::uint8_t> branches(static_cast<std::size_t>(w));
    for (int i = 0; i < w; ++i) {
        const ArticleRowCounts counts = article_row_intensities(world, w, i, I_P.data(), branches.data(), formula);
        int miss = 0, dark = 0, non_finite = 0;
        for (int j = 0; j < w; ++j) {
            const PixelResult<Real> traced = traced_ray(world, pane_point(i, j, w, world.z_E), formula);
            const PixelResult<Real> one = article_pixel_one_lane(world, w, i, j, formula);
            const auto branch = static_cast<Branch>(branches[static_cast<std::size_t>(j)]);
            miss += traced.branch == Branch::miss;
            dark += traced.branch == Branch::dark;
            non_finite += traced.branch == Branch::non_finite;
            if (same_bits(traced.I_P, I_P[static_cast<std::size_t>(j)]) && same_bits(traced.I_P, one.I_P) &&
                traced.branch == branch && traced.branch == one.branch)
                continue;
            if (++mismatches <= 3) {
                INFO("pixel (" << i << ", " << j << ") of w = " << w << ": traced " << traced.I_P << " ("
                               << branch_name(traced.branch) << "), lanes " << I_P[static_cast<std::size_t>(j)]
                               << " (" << branch_name(branch) << "), one lane " << one.I_P << " ("
                               << branch_name(one.branch) << ")");
                CHECK(false);
            }
        }
        if constexpr (std::is_same_v<Real, double>) {
            // The drawn row: each grey level is to_byte of the traced intensity.
            std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
            const RowCounts drawn = render_row(world, w, i, grey.data(), formula);
            for (int j = 0; j < w; ++j)
                if (grey[static_cast<std::size_t>(j)] != to_byte(static_cast<double>(I_P[static_cast<std::size_t>(j)])))
                    ++mismatches;
            CHECK(drawn.branches[static_cast<int>(Branch::miss)] == miss);
            CHECK(drawn.branches[static_cast<int>(Branch::non_finite)] == non_finite);
        }
        CHECK(counts.miss == miss);
        CHECK(counts.dark == dark);
        CHECK(counts.non_finite == non_finite);
    }
    return mismatches;
}

}  // namespace

TEST_CASE("Article rows in lanes: every pixel bit-identical to the traced path, double and float, each formula",
          "[lanes][hard]") {
    const std::vector<NamedWorld> worlds = article_worlds();
    REQUIRE(worlds.size() >= 20);  // the examples' article scenes, most hard cases, the extremes
    for (const Formula formula : lane_formulas) {
        for (const NamedWorld& named : worlds) {
            // Panes that are and are not whole vectors (2 doubles, 4 floats), and
            // the case's own pane and three times it (the same pixel centres).
            std::vector<int> panes = {61, 64};
            if (named.w > 0) panes.push_back(named.w), panes.push_back(3 * named.w);
            for (const int w : panes) {
                INFO(formula_name(formula) << ", " << named.name << ", w = " << w);
                CHECK(check_pane(named.world, w, formula) == 0);
                CHECK(check_pane(world_as<float>(named.world), w, formula) == 0);
            }
        }
    }
}


TEST_CASE("Rows in lanes, each formula: random spheres bit-identical to the traced path", "[lanes]") {
    for (const Formula formula : lane_formulas) {
        int s = 0;
        long long far_roots = 0;  // pixels whose ray leaves the sphere (the eye inside): they must be met
        for (const ArticleWorld<double>& world : random_worlds(60)) {
            const int w = 9 + (s++ % 23);
            NullRecorder none;
            for (int i = 0; i < w; ++i)
                for (int j = 0; j < w; ++j) {
                    const auto root = intersect_sphere_with(formula, pane_point(i, j, w, world.z_E), world.S, world.r, none);
                    far_roots += root && root->inside;
                }
            INFO(formula_name(formula) << ", sphere " << s << " at (" << world.S.x << ", " << world.S.y << ", "
                                       << world.S.z << "), r = " << world.r << ", w = " << w);
            CHECK(check_pane(world, w, formula) == 0);
            CHECK(check_pane(world_as<float>(world), w, formula) == 0);
        }
        if (formula != Formula::article) CHECK(far_roots > 100);
    }
}

TEST_CASE("Article rows in lanes: the branches the panes above cover", "[lanes]") {
    // The comparison above must meet every branch somewhere, or it proves little.
    for (const Formula formula : lane_formulas) {
        INFO(formula_name(formula));
        std::uint8_t seen = 0;
        for (const NamedWorld& named : article_worlds()) {
            std::vector<double> I_P(64);
            std::vector<std::uint8_t> branches(64);
            for (int i = 0; i < 64; ++i) {
                article_row_intensities(named.world, 64, i, I_P.data(), branches.data(), formula);
                for (const std::uint8_t b : branches) seen = static_cast<std::uint8_t>(seen | (1u << b));
            }
        }
        CHECK((seen & (1u << static_cast<int>(Branch::miss))) != 0);
        CHECK((seen & (1u << static_cast<int>(Branch::dark))) != 0);
        CHECK((seen & (1u << static_cast<int>(Branch::lit))) != 0);
        CHECK((seen & (1u << static_cast<int>(Branch::non_finite))) != 0);
    }
}

namespace {

// The article's literal program (bench/article_literal.hpp) on a world.
std::vector<std::uint8_t> literal_grey(const ArticleWorld<double>& world, int w) {
    const bench::LiteralScene scene{world.S.x, world.S.y, world.S.z, world.r, world.L.x,
                                    world.L.y, world.L.z, world.I,   world.z_E, world.background};
    std::vector<double> t;
    bench::literal_render(scene, w, t);
    std::vector<std::uint8_t> grey(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) grey[k] = to_byte(t[k]);
    return grey;
}

// Row i of the w x w pane through the traced path, pixel by pixel: each
// pixel's grey level (to_byte of its intensity, read as a double) and
// branch, and the row's counts as a drawn row gives them.
struct TracedRow {
    std::vector<std::uint8_t> grey;
    std::vector<Branch> branch;
    RowCounts counts;
};
template <class Real>
TracedRow traced_row(const ArticleWorld<Real>& world, int w, int i, Formula formula) {
    TracedRow row;
    for (int j = 0; j < w; ++j) {
        const PixelResult<Real> pixel = traced_ray(world, pane_point(i, j, w, world.z_E), formula);
        row.grey.push_back(to_byte(static_cast<double>(pixel.I_P)));
        row.branch.push_back(pixel.branch);
        ++row.counts.branches[static_cast<int>(pixel.branch)];
        if (pixel.branch == Branch::non_finite && row.counts.first_non_finite_j < 0) row.counts.first_non_finite_j = j;
    }
    return row;
}

}  // namespace

// Every path this processor has draws each pixel as to_byte of the traced
// path's intensity, and counts its branches as the traced path does, with
// each formula that has lanes; with the article's formula on the article's
// scenes that is also the literal program's image (which differs from the
// engine's by design elsewhere: a sphere behind the eye, say).
TEST_CASE("Drawn article rows: every instruction-set path this processor has, each formula, bit-identical to the "
          "traced path and the literal program",
          "[lanes][isa][hard]") {
    std::vector<NamedWorld> worlds = article_worlds();
    int article_scenes = 0;
    for (const NamedWorld& named : worlds) article_scenes += named.name == "article.json" || named.name == "far_sphere.json";
    REQUIRE(article_scenes == 2);
    int s = 0;
    for (const ArticleWorld<double>& world : random_worlds(24)) worlds.push_back({"random " + std::to_string(s++), world, 0});
    const std::vector<Isa> paths = supported_isas();
    REQUIRE(paths.front() == Isa::baseline);
    for (const Isa isa : paths) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            for (const NamedWorld& named : worlds) {
                // Panes that are and are not whole vectors of 2, 4 and 8 doubles.
                std::vector<int> panes = {61, 64, 67};
                if (named.w > 0) panes.push_back(named.w), panes.push_back(3 * named.w);
                const bool article = named.name == "article.json" || named.name == "far_sphere.json";
                if (article) panes.push_back(301);
                const bool literal_too = article && formula == Formula::article;
                for (const int w : panes) {
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << w);
                    const std::vector<std::uint8_t> literal =
                        literal_too ? literal_grey(named.world, w) : std::vector<std::uint8_t>{};
                    int literal_mismatches = 0;
                    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
                    int mismatches = 0, count_mismatches = 0;
                    long long skipped = 0;
                    for (int i = 0; i < w; ++i) {
                        const RowCounts drawn = render_row(named.world, w, i, grey.data(), formula);
                        const TracedRow traced_pixels = traced_row(named.world, w, i, formula);
                        const RowCounts& traced = traced_pixels.counts;
                        for (int j = 0; j < w; ++j) {
                            const std::uint8_t drawn_grey = grey[static_cast<std::size_t>(j)];
                            mismatches += drawn_grey != traced_pixels.grey[static_cast<std::size_t>(j)];
                            if (literal_too)
                                literal_mismatches += drawn_grey != literal[static_cast<std::size_t>(i) * w + j];
                        }
                        for (int b = 0; b < branch_count; ++b)
                            count_mismatches += drawn.branches[b] != traced.branches[b];
                        count_mismatches += drawn.first_non_finite_j != traced.first_non_finite_j;
                        // A pixel is either tested or skipped as proven background.
                        count_mismatches += drawn.sphere_tests + drawn.skipped != w;
                        skipped += drawn.skipped;
                    }
                    CHECK(mismatches == 0);
                    CHECK(literal_mismatches == 0);
                    // The path's intensities and branches, bit for bit.
                    CHECK(check_pane(named.world, w, formula) == 0);
                    CHECK(count_mismatches == 0);
                    // The article's scene leaves most of the pane to the background:
                    // most of it is skipped (render/silhouette.hpp) with every formula
                    // (the article's, stable and fma: the same delta within the
                    // same bound; geometric: its delta_g, with a margin).
                    if (named.name == "article.json") CHECK(skipped > static_cast<long long>(w) * w / 2);
                }
            }
        }
    }
}

// Without background skipping (bench speed's second threaded run, and any
// row whose silhouette proves nothing) a row is mostly whole vectors of
// misses, which the drawn row stores as the background's bytes: every pixel
// and count against the traced path, counting and not, on every path.
TEST_CASE("Drawn article rows without background skipping: every path, bit-identical to the traced path",
          "[lanes][isa]") {
    struct SkippingOff {
        bool before = background_skipping();
        SkippingOff() { set_background_skipping(false); }
        ~SkippingOff() { set_background_skipping(before); }
    } off;
    std::vector<NamedWorld> worlds = article_worlds();
    int s = 0;
    for (const ArticleWorld<double>& world : random_worlds(12)) worlds.push_back({"random " + std::to_string(s++), world, 0});
    long long whole_vectors_missed = 0, non_finite = 0;
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            for (const NamedWorld& named : worlds) {
                for (const int w : {67, 128}) {
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << w);
                    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w)), uncounted(grey.size());
                    int mismatches = 0, count_mismatches = 0;
                    for (int i = 0; i < w; ++i) {
                        const RowCounts drawn = render_row(named.world, w, i, grey.data(), formula);
                        const RowCounts quiet = render_row(named.world, w, i, uncounted.data(), formula, false);
                        const TracedRow traced_pixels = traced_row(named.world, w, i, formula);
                        const RowCounts& traced = traced_pixels.counts;
                        for (std::size_t j = 0; j < grey.size(); ++j) mismatches += grey[j] != traced_pixels.grey[j];
                        // Eight columns in a row that all miss: a whole vector on every path.
                        for (int j = 0; j + 8 <= w; j += 8) {
                            bool all_missed = true;
                            for (int k = j; k < j + 8; ++k)
                                all_missed = all_missed && traced_pixels.branch[static_cast<std::size_t>(k)] == Branch::miss;
                            whole_vectors_missed += all_missed;
                        }
                        for (int b = 0; b < branch_count; ++b)
                            count_mismatches += drawn.branches[b] != traced.branches[b];
                        count_mismatches += drawn.first_non_finite_j != traced.first_non_finite_j;
                        count_mismatches += drawn.skipped != 0 || drawn.sphere_tests != w;
                        const int nf = static_cast<int>(Branch::non_finite);
                        count_mismatches += quiet.branches[nf] != traced.branches[nf];
                        count_mismatches += quiet.first_non_finite_j != traced.first_non_finite_j;
                        mismatches += uncounted != grey;
                        non_finite += traced.branches[nf];
                    }
                    CHECK(mismatches == 0);
                    CHECK(count_mismatches == 0);
                }
            }
        }
    }
    // The comparison met what it is for: whole vectors of misses, and
    // non-finite pixels among them.
    CHECK(whole_vectors_missed > 10000);
    CHECK(non_finite > 100);
}

TEST_CASE("Instruction-set paths: names, and the widest this processor has is the default", "[isa]") {
    for (const Isa isa : {Isa::baseline, Isa::avx2, Isa::avx512}) CHECK(isa_from_name(isa_name(isa)) == isa);
    CHECK_FALSE(isa_from_name("AVX2"));
    CHECK_FALSE(isa_from_name("sse2"));
    CHECK(isa_supported(Isa::baseline));
#if defined(__x86_64__)
    // The processor's own word (gcc's), independent of render/isa.cpp.
    CHECK(isa_supported(Isa::avx2) == static_cast<bool>(__builtin_cpu_supports("avx2")));
    CHECK(isa_supported(Isa::avx512) == static_cast<bool>(__builtin_cpu_supports("avx512f")));
#endif
}

// --real float drawn in float lanes (render/float_row.hpp): every pixel's
// grey level, each row's counts, on every path, against trace_ray<float>.
TEST_CASE("Drawn float rows: every instruction-set path, each formula, bit-identical to the traced path in float",
          "[lanes][isa][float]") {
    std::vector<NamedWorld> worlds = article_worlds();
    int s = 0;
    for (const ArticleWorld<double>& world : random_worlds(24)) worlds.push_back({"random " + std::to_string(s++), world, 0});
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            for (const NamedWorld& named : worlds) {
                const ArticleWorld<float> world = world_as<float>(named.world);
                // Panes that are and are not whole vectors of 4, 8 and 16 floats.
                std::vector<int> panes = {61, 64, 67};
                if (named.w > 0) panes.push_back(named.w), panes.push_back(3 * named.w);
                if (named.name == "article.json" || named.name == "far_sphere.json") panes.push_back(301);
                for (const int w : panes) {
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << w);
                    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w));
                    int mismatches = 0, count_mismatches = 0, rows_in_lanes = 0;
                    long long skipped = 0;
                    for (int i = 0; i < w; ++i) {
                        RowCounts drawn;
                        rows_in_lanes += float_row_in_lanes(world, w, i, grey.data(), formula, drawn);
                        const TracedRow traced_pixels = traced_row(world, w, i, formula);
                        RowCounts traced = traced_pixels.counts;
                        traced.sphere_tests = w;
                        for (std::size_t j = 0; j < grey.size(); ++j) mismatches += grey[j] != traced_pixels.grey[j];
                        for (int b = 0; b < branch_count; ++b)
                            count_mismatches += drawn.branches[b] != traced.branches[b];
                        count_mismatches += drawn.first_non_finite_j != traced.first_non_finite_j;
                        // Each pixel tested or skipped as proven background.
                        count_mismatches += drawn.sphere_tests + drawn.skipped != traced.sphere_tests;
                        skipped += drawn.skipped;
                    }
                    // Most of the article's scene is background, skipped in
                    // float too (render/silhouette.hpp, float's bounds).
                    if (named.name == "article.json") CHECK(skipped > static_cast<long long>(w) * w / 3);
                    CHECK(rows_in_lanes == w);
                    CHECK(mismatches == 0);
                    CHECK(count_mismatches == 0);
                }
            }
        }
    }
}
