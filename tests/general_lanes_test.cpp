// The general tracer's rows in lanes (render/general_row.hpp) give every
// pixel the bits and the branch the traced path gives it (trace_general
// with a recording recorder), and count each row's branches, first
// non-finite column, shadow rays and tests as the traced path does: on every
// instruction-set path this processor has, for the example scenes (the
// article's forced through the general tracer), the hard cases, hostile
// scenes (values near the double range's ends), random scenes of several
// objects and lights, exact ties and an eye inside a sphere, and scenes of
// one sphere and one light (their own kernel) of every kind, Phong's
// highlights among them (each lane its hit's k_s and n).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "general_scenes_support.hpp"
#include "geometry/sphere_formulas.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/general_kernel.hpp"
#include "render/general_row.hpp"
#include "render/general_tracer.hpp"
#include "render/isa.hpp"
#include "render/pane.hpp"
#include "render/stages.hpp"
#include "render/world.hpp"
#include "same_bits.hpp"
#include "scene/scene_json.hpp"
#include "sweep_size.hpp"
#include "trace/recorder.hpp"

namespace {

using namespace promyk;
using namespace general_scenes_support;

// What the traced path gives a pane's rows (rows_checked): each pixel's
// intensity and branch, and each row's counts.
struct Traced {
    std::vector<Vec3d> I_P;  // grey: the level in x
    std::vector<Branch> branch;
    std::vector<RowCounts> rows;
};

template <class Sw, bool Rgb>
Traced traced_pane(const World<double, Rgb>& world, int w, const std::vector<int>& rows) {
    Traced traced;
    for (const int i : rows) {
        RowCounts counts;
        WorkCounts work;
        for (int j = 0; j < w; ++j) {
            RecordingRecorder recorder;
            const auto pixel = trace_general<Sw, SphereFormula<Formula::article>>(
                world, pane_point(i, j, w, world.z_E), work, recorder);
            if constexpr (Rgb)
                traced.I_P.push_back(pixel.I_P);
            else
                traced.I_P.push_back({pixel.I_P, 0, 0});
            traced.branch.push_back(pixel.branch);
            ++counts.branches[static_cast<int>(pixel.branch)];
            if (pixel.branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
        }
        counts.shadow_rays = work.shadow_rays;
        counts.sphere_tests = work.sphere_tests;
        counts.plane_tests = work.plane_tests;
        traced.rows.push_back(counts);
    }
    return traced;
}

// The traced pane with the scene's stages as template arguments.
template <bool Rgb>
Traced traced_pane(const World<double, Rgb>& world, const Stages& s, int w, const std::vector<int>& rows) {
    return with_stage_switches(s, [&](auto sw) { return traced_pane<decltype(sw)>(world, w, rows); });
}

using promyk::testing::same_bits;

struct Mismatches {
    int bits = 0, branches = 0, bytes = 0, counts = 0;
};

// The pane's rows on the path in use, against the traced pane's.
template <bool Rgb>
Mismatches compare_pane(const Scene& scene, const World<double, Rgb>& world, const Stages& stages, int w,
                        const std::vector<int>& rows, const Traced& traced) {
    Mismatches found;
    const GeneralLaneStages lane_stages{stages.shadows, stages.ambient, stages.objects, stages.phong};
    const std::unique_ptr<Kernel> kernel = make_general_kernel(scene);
    const int channels = Rgb ? 3 : 1;
    REQUIRE(kernel->channels() == channels);
    using Intensity = std::conditional_t<Rgb, Vec3d, double>;
    std::vector<Intensity> I_P(static_cast<std::size_t>(w));
    std::vector<std::uint8_t> branches(static_cast<std::size_t>(w)), out(static_cast<std::size_t>(w * channels));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const int i = rows[r];
        REQUIRE(general_row_intensities(world, lane_stages, w, i, I_P.data(), branches.data()));
        const RowCounts drawn = kernel->row(w, i, out.data());  // GeneralKernel::row: the lanes
        for (int j = 0; j < w; ++j) {
            const std::size_t at = r * static_cast<std::size_t>(w) + j;
            const Vec3d& want = traced.I_P[at];
            if constexpr (Rgb)
                found.bits += !same_bits(I_P[j].x, want.x) || !same_bits(I_P[j].y, want.y) ||
                              !same_bits(I_P[j].z, want.z);
            else
                found.bits += !same_bits(I_P[j], want.x);
            found.branches += branches[j] != static_cast<std::uint8_t>(traced.branch[at]);
            const double channel[3] = {want.x, want.y, want.z};
            for (int c = 0; c < channels; ++c)
                found.bytes += out[static_cast<std::size_t>(channels * j + c)] != to_byte(channel[c]);
        }
        const RowCounts& want = traced.rows[r];
        for (int b = 0; b < branch_count; ++b) found.counts += drawn.branches[b] != want.branches[b];
        found.counts += drawn.first_non_finite_j != want.first_non_finite_j;
        found.counts += drawn.shadow_rays != want.shadow_rays;
        found.counts += drawn.sphere_tests != want.sphere_tests;
        found.counts += drawn.plane_tests != want.plane_tests;
        found.counts += drawn.skipped != 0;
    }
    return found;
}

// Checks the scene on every path.
template <bool Rgb>
void check_scene(const NamedScene& named) {
    const Stages stages = plan_stages(named.scene);
    const World<double, Rgb> world = compile_world<double, Rgb>(named.scene);
    for (const int w : named.panes) {
        const std::vector<int> rows = rows_checked(named, w);
        const Traced traced = traced_pane(world, stages, w, rows);
        for (const Isa isa : supported_isas()) {
            PathForced forced(isa);
            INFO(named.name << ", w = " << w << ", " << isa_name(isa));
            const Mismatches found = compare_pane(named.scene, world, stages, w, rows, traced);
            CHECK(found.bits == 0);
            CHECK(found.branches == 0);
            CHECK(found.bytes == 0);
            CHECK(found.counts == 0);
        }
    }
}

void check_scene(const NamedScene& named) {
    if (plan_stages(named.scene).colour)
        check_scene<true>(named);
    else
        check_scene<false>(named);
}

}  // namespace

TEST_CASE("General rows in lanes: one sphere and one light, plain or not, hostile too, every path, bit-identical to "
          "the traced path",
          "[lanes][isa][non-finite]") {
    for (const NamedScene& named : one_sphere_scenes(sweep_size(60, 15))) check_scene(named);
}

TEST_CASE("General rows in lanes: the example scenes, every path, bit-identical to the traced path", "[lanes][isa]") {
    int checked = 0;
    bool article = false, phong = false;
    for (const NamedScene& named : example_scenes()) {
        check_scene(named);
        ++checked;
        article = article || named.name == "article.json";
        phong = phong || named.name == "phong.json";
    }
    CHECK(article);  // forced through the general tracer
    CHECK(phong);
    CHECK(checked >= 10);
}

TEST_CASE("General rows in lanes: the hard cases and hostile scenes, every path, bit-identical to the traced path",
          "[lanes][isa][hard][non-finite]") {
    int checked = 0;
    for (const NamedScene& named : hard_case_scenes()) check_scene(named), ++checked;
    CHECK(checked >= 10);
    for (const NamedScene& named : hostile_scenes(sweep_size(60, 15))) check_scene(named);
}

TEST_CASE("General rows in lanes: random scenes, ties and an eye inside, every path, bit-identical to the traced path",
          "[lanes][isa]") {
    for (const NamedScene& named : random_scenes(sweep_size(36, 12))) check_scene(named);
    for (const NamedScene& named : tie_scenes()) check_scene(named);
}
