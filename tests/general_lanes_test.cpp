// The general tracer's rows in lanes (render/general_row.hpp) give every
// pixel the bits and the branch the traced path gives it (trace_general
// with a recording recorder), and count each row's branches, first
// non-finite column, shadow rays and tests as the traced path does: on every
// instruction-set path this processor has, for the example scenes (the
// article's forced through the general tracer), the hard cases, hostile
// scenes (values near the double range's ends), random scenes of several
// objects and lights, exact ties and an eye inside a sphere, and scenes of
// one sphere and one light (their own kernel) of every kind. Phong scenes
// are not in lanes (their rows stay one pixel at a time) and are skipped.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "geometry/sphere_formulas.hpp"
#include "hard_cases_support.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/general_kernel.hpp"
#include "render/general_row.hpp"
#include "render/general_tracer.hpp"
#include "render/isa.hpp"
#include "render/pane.hpp"
#include "render/stages.hpp"
#include "render/world.hpp"
#include "scene/scene_json.hpp"
#include "trace/recorder.hpp"

namespace {

using namespace promyk;

struct NamedScene {
    std::string name;
    Scene scene;
    std::vector<int> panes;
};

// What the traced path gives a pane: each pixel's intensity and branch, and
// each row's counts.
struct Traced {
    std::vector<Vec3d> I_P;  // grey: the level in x
    std::vector<Branch> branch;
    std::vector<RowCounts> rows;
};

template <class Sw, bool Rgb>
Traced traced_pane(const World<double, Rgb>& world, int w) {
    Traced traced;
    for (int i = 0; i < w; ++i) {
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
Traced traced_pane(const World<double, Rgb>& world, const Stages& s, int w) {
    if (s.shadows) {
        if (s.ambient)
            return s.objects ? traced_pane<Switches<true, false, true, true>>(world, w)
                             : traced_pane<Switches<true, false, true, false>>(world, w);
        return s.objects ? traced_pane<Switches<true, false, false, true>>(world, w)
                         : traced_pane<Switches<true, false, false, false>>(world, w);
    }
    if (s.ambient)
        return s.objects ? traced_pane<Switches<false, false, true, true>>(world, w)
                         : traced_pane<Switches<false, false, true, false>>(world, w);
    return s.objects ? traced_pane<Switches<false, false, false, true>>(world, w)
                     : traced_pane<Switches<false, false, false, false>>(world, w);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Mismatches {
    int bits = 0, branches = 0, bytes = 0, counts = 0;
};

// Every row of the pane on the path in use, against the traced pane.
template <bool Rgb>
Mismatches compare_pane(const Scene& scene, const World<double, Rgb>& world, const Stages& stages, int w,
                        const Traced& traced) {
    Mismatches found;
    const GeneralLaneStages lane_stages{stages.shadows, stages.ambient, stages.objects};
    const std::unique_ptr<Kernel> kernel = make_general_kernel(scene);
    const int channels = Rgb ? 3 : 1;
    REQUIRE(kernel->channels() == channels);
    using Intensity = std::conditional_t<Rgb, Vec3d, double>;
    std::vector<Intensity> I_P(static_cast<std::size_t>(w));
    std::vector<std::uint8_t> branches(static_cast<std::size_t>(w)), out(static_cast<std::size_t>(w * channels));
    for (int i = 0; i < w; ++i) {
        REQUIRE(general_row_intensities(world, lane_stages, w, i, I_P.data(), branches.data()));
        const RowCounts drawn = kernel->row(w, i, out.data());  // GeneralKernel::row: the lanes
        for (int j = 0; j < w; ++j) {
            const std::size_t at = static_cast<std::size_t>(i) * w + j;
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
        const RowCounts& want = traced.rows[static_cast<std::size_t>(i)];
        for (int b = 0; b < branch_count; ++b) found.counts += drawn.branches[b] != want.branches[b];
        found.counts += drawn.first_non_finite_j != want.first_non_finite_j;
        found.counts += drawn.shadow_rays != want.shadow_rays;
        found.counts += drawn.sphere_tests != want.sphere_tests;
        found.counts += drawn.plane_tests != want.plane_tests;
        found.counts += drawn.skipped != 0;
    }
    return found;
}

// Checks the scene on every path; false when its stages are not in lanes.
template <bool Rgb>
bool check_scene(const NamedScene& named) {
    const Stages stages = plan_stages(named.scene);
    if (stages.phong) return false;
    const World<double, Rgb> world = compile_world<double, Rgb>(named.scene);
    for (const int w : named.panes) {
        const Traced traced = traced_pane(world, stages, w);
        for (const Isa isa : supported_isas()) {
            PathForced forced(isa);
            INFO(named.name << ", w = " << w << ", " << isa_name(isa));
            const Mismatches found = compare_pane(named.scene, world, stages, w, traced);
            CHECK(found.bits == 0);
            CHECK(found.branches == 0);
            CHECK(found.bytes == 0);
            CHECK(found.counts == 0);
        }
    }
    return true;
}

bool check_scene(const NamedScene& named) {
    return plan_stages(named.scene).colour ? check_scene<true>(named) : check_scene<false>(named);
}

// Panes that are and are not whole vectors of 2, 4 and 8 doubles.
const std::vector<int> small_panes = {29, 32, 35};

std::vector<NamedScene> example_scenes() {
    std::vector<NamedScene> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find("schema") != std::string::npos) continue;
        scenes.push_back({entry.path().filename().string(), load_scene_file(path), {61, 64, 67}});
    }
    return scenes;
}

std::vector<NamedScene> hard_case_scenes() {
    std::vector<NamedScene> scenes;
    for (const auto& c : hard_cases_support::hard_cases_reference().at("cases")) {
        const std::string id = c.at("id").get<std::string>();
        const int w = c.at("pixel").at("w").get<int>();
        scenes.push_back({"hard case " + id, parse_scene(c.at("scene").dump(), id), {w, 35}});
    }
    return scenes;
}

// tests/non_finite_test.cpp's general scenes, without Phong: numbers from
// 1e-300 to 1e300, so deltas, |K|^2, D, shadow tests and results overflow.
std::vector<NamedScene> hostile_scenes(int count) {
    std::mt19937_64 random(20261202);
    std::uniform_real_distribution<double> exponent(-300, 300), unit(-1, 1), positive(0.1, 1);
    auto big = [&] { return (unit(random) < 0 ? -1 : 1) * std::pow(10.0, exponent(random) * positive(random)); };
    auto point = [&] { return Vec3d{big(), big(), big()}; };
    std::vector<NamedScene> scenes;
    for (int n = 0; n < count; ++n) {
        Scene scene;
        scene.z_E = std::abs(big());
        scene.shadows = n % 2 == 0;
        scene.spheres = {Sphere{point(), std::abs(big())}, Sphere{point(), std::abs(big())}};
        scene.planes = {Plane{point(), {unit(random), unit(random), unit(random) + 2}}};
        scene.lights = {Light{point(), std::abs(big())}, Light{point(), 1}};
        scene.materials = {Material{n % 3 == 0 ? 0.1 : 0.0, 0.8, 0, 1, {1, 0.5, 0.25}}};
        scene.spheres[0].material = 0;
        scenes.push_back({"hostile " + std::to_string(n), scene, {9, 11}});
    }
    return scenes;
}

// Several spheres and planes in front of the eye (some around it), one to
// three lights, with or without shadows, ambient and colour.
std::vector<NamedScene> random_scenes(int count) {
    std::mt19937_64 random(18);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0, 1);
    std::vector<NamedScene> scenes;
    for (int n = 0; n < count; ++n) {
        Scene scene;
        scene.z_E = 1 + positive(random);
        scene.shadows = n % 2 == 0;
        const bool coloured = n % 3 == 1;
        const int materials = 1 + n % 3;
        for (int k = 0; k < materials; ++k) {
            Material m;
            m.ambient = n % 4 < 2 ? 0.2 * positive(random) : 0;
            m.diffuse = positive(random);
            if (coloured) m.colour = {positive(random), positive(random), positive(random)};
            scene.materials.push_back(m);
        }
        const int spheres = 1 + n % 4, planes = n % 3;
        for (int k = 0; k < spheres; ++k) {
            Sphere s{{2 * unit(random), 2 * unit(random), 3 + 4 * positive(random)}, 0.3 + 1.5 * positive(random)};
            if (k == 1 && n % 5 == 0) s = {{0.2 * unit(random), 0.2 * unit(random), 0.5}, 4};  // the eye inside
            s.material = k % (materials + 1) - 1;
            scene.spheres.push_back(s);
        }
        for (int k = 0; k < planes; ++k)
            scene.planes.push_back({{unit(random), -1 - positive(random), 5 * positive(random)},
                                    {0.3 * unit(random), 1, 0.3 * unit(random)},
                                    k % materials});
        for (int k = 0; k < 1 + n % 3; ++k)
            scene.lights.push_back({{4 * unit(random), 1 + 3 * positive(random), 4 * unit(random)},
                                    0.5 + positive(random),
                                    coloured ? Colour{positive(random), 1, positive(random)} : white});
        if (coloured) scene.background = {0.1, 0.2, 0.3};
        scenes.push_back({"random " + std::to_string(n), scene, small_panes});
    }
    return scenes;
}

// Exact ties (the same sphere or plane twice, each with its own material:
// the earlier wins) and an eye inside a sphere (the far root), also inside
// two equal spheres.
std::vector<NamedScene> tie_scenes() {
    std::vector<NamedScene> scenes;
    Scene twins;
    twins.materials = {Material{0, 0.9, 0, 10, {1, 1, 1}}, Material{0, 0.3, 0, 10, {1, 1, 1}}};
    twins.spheres = {Sphere{{0, 0, 3.2}, 1.1, 0}, Sphere{{0, 0, 3.2}, 1.1, 1}};
    twins.lights = {Light{{1.5, 1, 1}, 1}};
    scenes.push_back({"twin spheres", twins, small_panes});
    Scene twins_shadows = twins;
    twins_shadows.shadows = true;
    twins_shadows.planes = {Plane{{0, -1, 0}, {0, 1, 0}, 1}, Plane{{0, -1, 0}, {0, 1, 0}, 0}};
    scenes.push_back({"twin spheres and planes, shadows", twins_shadows, small_panes});
    Scene inside;
    inside.materials = twins.materials;
    inside.spheres = {Sphere{{0, 0, 0.5}, 3, 0}};
    inside.lights = {Light{{0.5, 0.5, 1}, 1}};
    scenes.push_back({"eye inside", inside, small_panes});
    Scene inside_twins = inside;
    inside_twins.shadows = true;
    inside_twins.spheres.push_back(Sphere{{0, 0, 0.5}, 3, 1});
    inside_twins.spheres.push_back(Sphere{{0.5, 0, 1.5}, 0.4, -1});
    scenes.push_back({"eye inside twins, shadows", inside_twins, small_panes});
    return scenes;
}

// One sphere and one light (render/general_row_one_sphere.hpp), every
// combination of its switches: shadows, ambient, colour, plain (k_d, m and
// c exactly 1) or not, the eye outside or inside; and hostile ones (numbers
// from 1e-300 to 1e300: deltas, roots, |K|^2, D and results overflow), some
// of them plain.
std::vector<NamedScene> one_sphere_scenes(int hostile) {
    std::vector<NamedScene> scenes;
    for (int n = 0; n < 32; ++n) {
        Scene scene;
        scene.shadows = n & 1;
        const bool ambient = n & 2, coloured = n & 4, plain = n & 8, inside = n & 16;
        Material m;
        m.ambient = ambient ? 0.25 : 0;
        if (!plain) m.diffuse = 0.7, m.colour = coloured ? Colour{1, 0.5, 0.25} : Colour{0.6, 0.6, 0.6};
        scene.materials = {m};
        scene.spheres = {inside ? Sphere{{0.1, -0.2, 0.5}, 3, 0} : Sphere{{0.2, 0.1, 3.2}, 1.1, 0}};
        scene.lights = {Light{{1.5, 1, inside ? 1.0 : 1.2}, 1.25, plain ? white : Colour{0.9, 0.9, 0.9}}};
        if (coloured) scene.background = {0.1, 0.2, 0.3};
        scenes.push_back({"one sphere " + std::to_string(n), scene, small_panes});
    }
    std::mt19937_64 random(20261203);
    std::uniform_real_distribution<double> exponent(-300, 300), unit(-1, 1), positive(0.1, 1);
    auto big = [&] { return (unit(random) < 0 ? -1 : 1) * std::pow(10.0, exponent(random) * positive(random)); };
    auto point = [&] { return Vec3d{big(), big(), big()}; };
    for (int n = 0; n < hostile; ++n) {
        Scene scene;
        scene.z_E = std::abs(big());
        scene.shadows = n % 2 == 0;
        const bool plain = n % 3 != 0;
        scene.materials = {plain ? Material{n % 4 == 0 ? 0.1 : 0.0, 1, 0, 1, white}
                                 : Material{n % 4 == 0 ? 0.1 : 0.0, std::abs(big()), 0, 1, {1, 0.5, 0.25}}};
        scene.spheres = {Sphere{point(), std::abs(big()), 0}};
        scene.lights = {Light{point(), std::abs(big()), plain ? white : Colour{0.5, 1, 1}}};
        if (n % 5 == 0) scene.background = {0.1, 0.2, 0.3};
        scenes.push_back({"hostile one sphere " + std::to_string(n), scene, {9, 11}});
    }
    return scenes;
}

}  // namespace

TEST_CASE("General rows in lanes: one sphere and one light, plain or not, hostile too, every path, bit-identical to "
          "the traced path",
          "[lanes][isa][non-finite]") {
    for (const NamedScene& named : one_sphere_scenes(60)) CHECK(check_scene(named));
}

TEST_CASE("General rows in lanes: the example scenes, every path, bit-identical to the traced path", "[lanes][isa]") {
    int checked = 0;
    bool article = false;
    for (const NamedScene& named : example_scenes()) {
        const bool in_lanes = check_scene(named);
        checked += in_lanes;
        article = article || (named.name == "article.json" && in_lanes);
    }
    CHECK(article);  // forced through the general tracer
    CHECK(checked >= 8);
}

TEST_CASE("General rows in lanes: the hard cases and hostile scenes, every path, bit-identical to the traced path",
          "[lanes][isa][hard][non-finite]") {
    int checked = 0;
    for (const NamedScene& named : hard_case_scenes()) checked += check_scene(named);
    CHECK(checked >= 10);
    for (const NamedScene& named : hostile_scenes(60)) CHECK(check_scene(named));
}

TEST_CASE("General rows in lanes: random scenes, ties and an eye inside, every path, bit-identical to the traced path",
          "[lanes][isa]") {
    for (const NamedScene& named : random_scenes(36)) CHECK(check_scene(named));
    for (const NamedScene& named : tie_scenes()) CHECK(check_scene(named));
}
