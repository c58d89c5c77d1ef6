// The general tracer's sampled rows in lanes (render/general_sample_lanes.hpp)
// give every pixel the bits and the branch that sample_pixel over
// trace_general gives it (the traced path's samples, one pixel at a time),
// and count each row's branches, disagreeing pixels, first non-finite
// column, shadow rays and tests as GeneralKernel counts them: on every
// instruction-set path this processor has, at spp 4 (a cell of a power of
// two) and 9 (not), on the scenes tests/general_lanes_test.cpp draws at one
// sample; at spp 1024 (the samples' 11-bit fields full) on a few pixels.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "general_scenes_support.hpp"
#include "geometry/sphere_formulas.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/general_kernel.hpp"
#include "render/general_row.hpp"
#include "render/general_tracer.hpp"
#include "render/isa.hpp"
#include "render/sample_hashes.hpp"
#include "render/sampling.hpp"
#include "render/stages.hpp"
#include "render/world.hpp"
#include "same_bits.hpp"
#include "trace/recorder.hpp"

namespace {

using namespace promyk;
using namespace general_scenes_support;

template <bool Rgb>
using IntensityOf = typename World<double, Rgb>::Intensity;

// What sample_pixel over trace_general gives a pane: each pixel, and each
// row's counts as GeneralKernel's one-pixel loop counts them.
template <bool Rgb>
struct Sampled {
    std::vector<SampledPixel<IntensityOf<Rgb>>> pixels;
    std::vector<RowCounts> rows;
};

template <class Sw, bool Rgb>
Sampled<Rgb> sampled_pane(const World<double, Rgb>& world, int w, int spp) {
    Sampled<Rgb> sampled;
    NullRecorder none;
    for (int i = 0; i < w; ++i) {
        RowCounts counts;
        WorkCounts work;
        for (int j = 0; j < w; ++j) {
            const auto pixel = sample_pixel<IntensityOf<Rgb>>(
                w, i, j, spp, world.z_E,
                [&](int, const Vec3d& E) { return trace_general<Sw, SphereFormula<Formula::article>>(world, E, work, none); },
                [](int, const auto&) {});
            ++counts.branches[static_cast<int>(pixel.branch)];
            if (!pixel.agree()) ++counts.disagreeing;
            if (pixel.branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
            sampled.pixels.push_back(pixel);
        }
        counts.shadow_rays = work.shadow_rays;
        counts.sphere_tests = work.sphere_tests;
        counts.plane_tests = work.plane_tests;
        sampled.rows.push_back(counts);
    }
    return sampled;
}

// The sampled pane with the scene's stages as template arguments.
template <bool Rgb>
Sampled<Rgb> sampled_pane(const World<double, Rgb>& world, const Stages& s, int w, int spp) {
    return with_stage_switches(s, [&](auto sw) { return sampled_pane<decltype(sw)>(world, w, spp); });
}

using promyk::testing::same_bits;

struct SampleMismatches {
    int bits = 0, branches = 0, bytes = 0, counts = 0, kernel = 0;
};

int count_mismatches(const RowCounts& drawn, const RowCounts& want) {
    int found = 0;
    for (int b = 0; b < branch_count; ++b) found += drawn.branches[b] != want.branches[b];
    found += drawn.disagreeing != want.disagreeing;
    found += drawn.first_non_finite_j != want.first_non_finite_j;
    found += drawn.shadow_rays != want.shadow_rays;
    found += drawn.sphere_tests != want.sphere_tests;
    found += drawn.plane_tests != want.plane_tests;
    found += drawn.skipped != 0;
    return found;
}

// Every row of the pane on the path in use, against the sampled pane: the
// lanes' own row (means and branches), and the kernel's row (its bytes and
// counts: GeneralKernel::row draws it in lanes).
template <bool Rgb>
SampleMismatches compare_sampled_pane(const Scene& scene, const World<double, Rgb>& world, const Stages& stages, int w, int spp,
                              const Sampled<Rgb>& sampled) {
    SampleMismatches found;
    const GeneralLaneStages lane_stages{stages.shadows, stages.ambient, stages.objects, stages.phong};
    const std::unique_ptr<Kernel> kernel = make_general_kernel(scene, RealType::double_, Formula::article, spp);
    const int channels = Rgb ? 3 : 1;
    std::vector<IntensityOf<Rgb>> I_P(static_cast<std::size_t>(w));
    std::vector<std::uint8_t> branches(static_cast<std::size_t>(w)), out(static_cast<std::size_t>(w * channels)),
        kernel_out(out.size());
    for (int i = 0; i < w; ++i) {
        RowCounts drawn;
        REQUIRE(general_sampled_row_intensities(world, lane_stages, w, i, spp, out.data(), drawn, I_P.data(),
                                                branches.data()));
        const RowCounts from_kernel = kernel->row(w, i, kernel_out.data());
        for (int j = 0; j < w; ++j) {
            const auto& want = sampled.pixels[static_cast<std::size_t>(i) * w + j];
            found.bits += !same_bits(I_P[j], want.I_P);
            found.branches += branches[j] != static_cast<std::uint8_t>(want.branch);
            double channel[3];
            if constexpr (Rgb)
                channel[0] = want.I_P.x, channel[1] = want.I_P.y, channel[2] = want.I_P.z;
            else
                channel[0] = want.I_P;
            for (int c = 0; c < channels; ++c) {
                const std::size_t at = static_cast<std::size_t>(channels * j + c);
                found.bytes += out[at] != to_byte(channel[c]);
                found.kernel += kernel_out[at] != to_byte(channel[c]);
            }
        }
        const RowCounts& want = sampled.rows[static_cast<std::size_t>(i)];
        found.counts += count_mismatches(drawn, want);
        found.kernel += count_mismatches(from_kernel, want);
    }
    return found;
}

// Checks the scene at each spp on every path.
template <bool Rgb>
void check_sampled_scene(const NamedScene& named, const std::vector<int>& spps, const std::vector<int>& panes) {
    const Stages stages = plan_stages(named.scene);
    const World<double, Rgb> world = compile_world<double, Rgb>(named.scene);
    for (const int spp : spps) {
        for (const int w : panes) {
            const Sampled<Rgb> sampled = sampled_pane(world, stages, w, spp);
            for (const Isa isa : supported_isas()) {
                PathForced forced(isa);
                INFO(named.name << ", w = " << w << ", spp = " << spp << ", " << isa_name(isa));
                const SampleMismatches found = compare_sampled_pane(named.scene, world, stages, w, spp, sampled);
                CHECK(found.bits == 0);
                CHECK(found.branches == 0);
                CHECK(found.bytes == 0);
                CHECK(found.counts == 0);
                CHECK(found.kernel == 0);
            }
        }
    }
}

void check_sampled_scene(const NamedScene& named, const std::vector<int>& spps, const std::vector<int>& panes) {
    if (plan_stages(named.scene).colour)
        check_sampled_scene<true>(named, spps, panes);
    else
        check_sampled_scene<false>(named, spps, panes);
}

void check_sampled_scene(const NamedScene& named, const std::vector<int>& spps) {
    check_sampled_scene(named, spps, named.panes);
}

// Panes of two vectors and more (the loop that keeps two in flight) and
// of less than one, none a whole number of them.
const std::vector<int> sample_panes = {7, 19};

}  // namespace

TEST_CASE("General sampled rows in lanes: one sphere and one light, plain or not, hostile too, every path, "
          "bit-identical to the traced path's samples",
          "[sample_lanes][lanes][isa][non-finite]") {
    for (const NamedScene& named : one_sphere_scenes(24)) check_sampled_scene(named, {4, 9}, sample_panes);
}

TEST_CASE("General sampled rows in lanes: the example scenes, every path, bit-identical to the traced path's samples",
          "[sample_lanes][lanes][isa]") {
    int checked = 0;
    for (const NamedScene& named : example_scenes()) check_sampled_scene(named, {4, 9}, {19, 24}), ++checked;
    CHECK(checked >= 10);
}

TEST_CASE("General sampled rows in lanes: the hard cases, hostile and random scenes, ties and an eye inside, every "
          "path, bit-identical to the traced path's samples",
          "[sample_lanes][lanes][isa][hard][non-finite]") {
    int checked = 0;
    for (const NamedScene& named : hard_case_scenes()) check_sampled_scene(named, {4}, sample_panes), ++checked;
    CHECK(checked >= 10);
    for (const NamedScene& named : hostile_scenes(24)) check_sampled_scene(named, {4, 9}, {5, 9});
    for (const NamedScene& named : random_scenes(24)) check_sampled_scene(named, {4, 9}, sample_panes);
    for (const NamedScene& named : tie_scenes()) check_sampled_scene(named, {4, 9}, sample_panes);
}

// w a power of two: with n one too, the points computed without dividing
// (SampleGrid::whole); with n = 3 or 5, scaled by 2 / w (w_exact: no
// products by 2 and 1 / w, sample_point_lanes).
// Two in-flight vectors and less than one.
TEST_CASE("General sampled rows in lanes: panes of a power of two, whole grids (n a power of two too) or not, every "
          "path, bit-identical to the traced path's samples",
          "[sample_lanes][lanes][isa]") {
    int checked = 0;
    for (const NamedScene& named : example_scenes()) check_sampled_scene(named, {4, 9, 16}, {2, 32}), ++checked;
    CHECK(checked >= 10);
    for (const NamedScene& named : one_sphere_scenes(24)) check_sampled_scene(named, {4, 25, 64}, {4, 16});
    for (const NamedScene& named : random_scenes(24)) check_sampled_scene(named, {16}, {16});
    for (const NamedScene& named : tie_scenes()) check_sampled_scene(named, {4}, {16});
}

TEST_CASE("General sampled rows in lanes: 1024 samples a pixel, every branch's field full, every path",
          "[sample_lanes][lanes][isa]") {
    // A floor in the shadow of a sphere far above it, seen through a narrow
    // pane (z_E = 20): the bottom row's 1024 samples are all shadowed
    // (the field's sum 1024), the other rows' split between misses, the
    // sphere's dark underside, the lit floor and its shadow.
    Scene scene;
    scene.z_E = 20;
    scene.shadows = true;
    scene.spheres = {Sphere{{0, 60, 60}, 58}};
    scene.planes = {Plane{{0, -1, 0}, {0, 1, 0}}};
    scene.lights = {Light{{0, 1000, 60}, 1}};
    const NamedScene shade{"floor under a sphere, shadows", scene, {3}};
    const World<double, false> world = compile_world<double, false>(scene);
    const Sampled<false> sampled = sampled_pane(world, plan_stages(scene), 3, 1024);
    const auto& bottom = sampled.pixels[7];
    CHECK(bottom.branches[static_cast<int>(Branch::shadowed)] == 1024);
    CHECK(sampled.rows[0].disagreeing == 3);
    CHECK(sampled.rows[1].disagreeing > 0);
    check_sampled_scene(shade, {1024});
    const std::vector<NamedScene> one = one_sphere_scenes(0);
    check_sampled_scene(one[1], {1024}, {2});   // shadows
    check_sampled_scene(one[17], {1024}, {2});  // the eye inside, shadows
}

// The widest panes whose column hashes still fit the table: there the
// baseline path finds a pair of vectors' points from the jitter's bits
// (render/sample_lanes.hpp's magic_pair_points, on whole grids), exact only
// while n w stays small; the CLI's widest pane (32768) at 4 and 16 samples,
// and 512 at 1024 (n = 32). Some columns of a few rows, with and without
// counting (the counted rows also order the samples by their distance from
// the pixel's centre), against sample_pixel over trace_general.
TEST_CASE("General sampled rows in lanes: the widest panes with the column table, whole grids, every path",
          "[sample_lanes][lanes][isa]") {
    const std::vector<NamedScene> one = one_sphere_scenes(0);
    struct Pane {
        int w, spp;
    };
    long long checked = 0;
    for (const Pane pane : {Pane{32768, 4}, Pane{32768, 16}, Pane{512, 1024}}) {
        REQUIRE(sample_column_hashes(pane.w, pane.spp).hashes != nullptr);
        for (const NamedScene* named : {&one[8], &one[4]}) {  // the matte white (plain), and coloured
            const bool rgb = plan_stages(named->scene).colour;
            const World<double, false> grey = compile_world<double, false>(named->scene);
            const World<double, true> colour = compile_world<double, true>(named->scene);
            const Stages stages = plan_stages(named->scene);
            const GeneralLaneStages lane_stages{stages.shadows, stages.ambient, stages.objects, stages.phong};
            const int w = pane.w, channels = rgb ? 3 : 1;
            std::vector<int> columns = {0, 1, 2, 3, 4, 5, 6, 7, w - 8, w - 7, w - 6, w - 5, w - 4, w - 3, w - 2, w - 1};
            for (int k = 1; k < 40; ++k) columns.push_back(k * (w / 40));
            for (const int i : {0, w / 2 - 1, w / 2 + 7, w - 1}) {
                // The traced path's samples of the row's chosen columns.
                std::vector<SampledPixel<Vec3d>> want_rgb;
                std::vector<SampledPixel<double>> want_grey;
                NullRecorder none;
                WorkCounts work;
                const auto traced = [&](const auto& world, int j) {  // grey or colour
                    using Intensity = typename std::decay_t<decltype(world)>::Intensity;
                    return sample_pixel<Intensity>(
                        w, i, j, pane.spp, world.z_E,
                        [&](int, const Vec3d& E) {
                            return with_stage_switches(stages, [&](auto sw) {
                                return trace_general<decltype(sw), SphereFormula<Formula::article>>(world, E, work,
                                                                                                    none);
                            });
                        },
                        [](int, const auto&) {});
                };
                for (const int j : columns) {
                    if (rgb)
                        want_rgb.push_back(traced(colour, j));
                    else
                        want_grey.push_back(traced(grey, j));
                }
                for (const Isa isa : supported_isas()) {
                    PathForced forced(isa);
                    INFO(named->name << ", w = " << w << ", spp = " << pane.spp << ", row " << i << ", "
                                     << isa_name(isa));
                    std::vector<std::uint8_t> out(static_cast<std::size_t>(w * channels)), uncounted(out.size()),
                        branches(static_cast<std::size_t>(w));
                    std::vector<double> I_grey(static_cast<std::size_t>(w));
                    std::vector<Vec3d> I_rgb(static_cast<std::size_t>(w));
                    RowCounts drawn, drawn_uncounted;
                    if (rgb) {
                        REQUIRE(general_sampled_row_intensities(colour, lane_stages, w, i, pane.spp, out.data(), drawn,
                                                                I_rgb.data(), branches.data()));
                        REQUIRE(general_sampled_row_in_lanes(colour, lane_stages, w, i, pane.spp, uncounted.data(),
                                                             drawn_uncounted, false));
                    } else {
                        REQUIRE(general_sampled_row_intensities(grey, lane_stages, w, i, pane.spp, out.data(), drawn,
                                                                I_grey.data(), branches.data()));
                        REQUIRE(general_sampled_row_in_lanes(grey, lane_stages, w, i, pane.spp, uncounted.data(),
                                                             drawn_uncounted, false));
                    }
                    int bits = 0, branch = 0, bytes = 0;
                    for (std::size_t k = 0; k < columns.size(); ++k) {
                        const int j = columns[k];
                        const Branch want_branch = rgb ? want_rgb[k].branch : want_grey[k].branch;
                        double channel[3];
                        if (rgb) {
                            bits += !same_bits(I_rgb[j], want_rgb[k].I_P);
                            channel[0] = want_rgb[k].I_P.x, channel[1] = want_rgb[k].I_P.y,
                            channel[2] = want_rgb[k].I_P.z;
                        } else {
                            bits += !same_bits(I_grey[j], want_grey[k].I_P);
                            channel[0] = want_grey[k].I_P;
                        }
                        branch += branches[j] != static_cast<std::uint8_t>(want_branch);
                        for (int c = 0; c < channels; ++c) {
                            const std::size_t at = static_cast<std::size_t>(channels * j + c);
                            bytes += out[at] != to_byte(channel[c]);
                            bytes += uncounted[at] != to_byte(channel[c]);
                        }
                        ++checked;
                    }
                    CHECK(bits == 0);
                    CHECK(branch == 0);
                    CHECK(bytes == 0);
                }
            }
        }
    }
    CHECK(checked > 1000);
}
