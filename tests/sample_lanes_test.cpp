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

#include "hard_cases_support.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/article_row.hpp"
#include "render/isa.hpp"
#include "render/sampling.hpp"
#include "render/stages.hpp"
#include "render/tracer.hpp"
#include "render/world.hpp"
#include "geometry/sphere_formulas.hpp"
#include "scene/scene_json.hpp"

namespace {

using namespace promyk;

struct NamedWorld {
    std::string name;
    ArticleWorld<double> world;
    int w;  // the hard case's own pane, or 0
};

std::vector<NamedWorld> sample_worlds() {
    std::vector<NamedWorld> worlds;
    auto add = [&](const std::string& name, const Scene& scene, int w) {
        if (!plan_stages(scene).article) return;
        worlds.push_back({name, article_world(scene), w});
    };
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find("schema") != std::string::npos) continue;
        add(entry.path().filename().string(), load_scene_file(path), 0);
    }
    for (const auto& c : hard_cases_support::hard_cases_reference().at("cases")) {
        const std::string id = c.at("id").get<std::string>();
        add("hard case " + id, parse_scene(c.at("scene").dump(), id), c.at("pixel").at("w").get<int>());
    }
    ArticleWorld<double> base = worlds.front().world;
    for (const auto& named : worlds)
        if (named.name == "article.json") base = named.world;
    ArticleWorld<double> negative_zero = base;
    negative_zero.background = -0.0;
    worlds.push_back({"background -0", negative_zero, 0});
    ArticleWorld<double> bright = base;
    bright.I = 1e308;  // I D overflows: non-finite samples, and means
    worlds.push_back({"I = 1e308", bright, 0});
    ArticleWorld<double> far_light = base;
    far_light.L = {1e200, 1e200, 1e200};  // |K|^2 overflows
    worlds.push_back({"light at 1e200", far_light, 0});
    std::mt19937_64 random(18);
    std::uniform_real_distribution<double> position(-3, 3), depth(-4, 14), light(-6, 6), unit(0, 1);
    for (int s = 0; s < 12; ++s) {
        ArticleWorld<double> world{2, {position(random), position(random), depth(random)}, 0, {}, 1, 0.25};
        world.r = s % 5 == 0 ? std::pow(10.0, -3 * unit(random)) : 0.05 + 3 * unit(random);
        world.L = {light(random), light(random), light(random)};
        if (s % 4 == 0) world.S = {position(random) / 8, position(random) / 8, position(random) / 8};
        worlds.push_back({"random " + std::to_string(s), world, 0});
    }
    return worlds;
}

constexpr Formula lane_formulas[] = {Formula::article, Formula::stable, Formula::geometric, Formula::fma};

PixelResult<double> traced_ray(const ArticleWorld<double>& world, const Vec3<double>& E, Formula formula) {
    NullRecorder none;
    switch (formula) {
        case Formula::stable:
            return trace_ray<SphereFormula<Formula::stable>>(world, E, none);
        case Formula::geometric:
            return trace_ray<SphereFormula<Formula::geometric>>(world, E, none);
        case Formula::fma:
            return trace_ray<SphereFormula<Formula::fma>>(world, E, none);
        default:
            return trace_ray(world, E, none);
    }
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct PaneCheck {
    int mismatches = 0, count_mismatches = 0;
    long long disagreeing = 0, non_finite = 0, skipped = 0;
};

// Every pixel of the w x w pane at spp samples: the lanes' row against
// sample_pixel over trace_ray.
PaneCheck check_pane(const ArticleWorld<double>& world, int w, int spp, Formula formula) {
    PaneCheck check;
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w)), branches(static_cast<std::size_t>(w));
    std::vector<double> I_P(static_cast<std::size_t>(w));
    for (int i = 0; i < w; ++i) {
        RowCounts drawn;
        REQUIRE(sampled_row_in_lanes(world, w, i, spp, grey.data(), formula, drawn, I_P.data(), branches.data()));
        RowCounts traced;
        traced.sphere_tests = static_cast<long long>(w) * spp;
        for (int j = 0; j < w; ++j) {
            const SampledPixel<double> pixel = sample_pixel<double>(
                w, i, j, spp, world.z_E, [&](int, const Vec3<double>& E) { return traced_ray(world, E, formula); },
                [](int, const PixelResult<double>&) {});
            ++traced.branches[static_cast<int>(pixel.branch)];
            if (!pixel.agree()) ++traced.disagreeing;
            if (pixel.branch == Branch::non_finite && traced.first_non_finite_j < 0) traced.first_non_finite_j = j;
            const auto k = static_cast<std::size_t>(j);
            const bool same = same_bits(pixel.I_P, I_P[k]) && static_cast<std::uint8_t>(pixel.branch) == branches[k] &&
                              to_byte(pixel.I_P) == grey[k];
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
    for (const Isa isa : paths) {
        PathForced forced(isa);
        for (const Formula formula : lane_formulas) {
            for (const NamedWorld& named : worlds) {
                // Panes and cells (n x n a pixel) of a power of two (the
                // reciprocal's multiplication) and not (the division, or two
                // fmas), each with each; whole vectors of 2, 4 and 8 pixels
                // and not; the hard case's own pane (its tangent pixel centres).
                struct Run {
                    int w, spp;
                };
                std::vector<Run> runs = {{64, 4}, {61, 9}, {67, 16}, {32, 16}, {64, 9}, {8, 1024}, {5, 1024}};
                if (named.w > 0) runs.push_back({named.w, 4}), runs.push_back({named.w, 9});
                for (const Run run : runs) {
                    INFO(isa_name(isa) << ", " << formula_name(formula) << ", " << named.name << ", w = " << run.w
                                       << ", spp " << run.spp);
                    const PaneCheck check = check_pane(named.world, run.w, run.spp, formula);
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

TEST_CASE("Sampled rows in lanes: one sample is not drawn in lanes", "[sample_lanes]") {
    const NamedWorld named = sample_worlds().front();
    std::vector<std::uint8_t> grey(16);
    RowCounts counts;
    CHECK_FALSE(sampled_row_in_lanes(named.world, 16, 3, 1, grey.data(), Formula::article, counts));
}
