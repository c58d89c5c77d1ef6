// The scenes the general tracer's lanes are tested on, one sample a pixel
// (tests/general_lanes_test.cpp) and several (general_sample_lanes_test.cpp):
// the example scenes, the hard cases, hostile scenes (values near the double
// range's ends), random scenes of several objects and lights, exact ties and
// an eye inside a sphere, and one sphere and one light of every kind, each
// with the panes it is drawn on.
#pragma once

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hard_cases_support.hpp"
#include "render/general_tracer.hpp"
#include "render/stages.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"

namespace general_scenes_support {

using namespace promyk;

// f(Switches<...>{}) with the scene's stages as template arguments.
template <bool Shadows, bool Phong, class F>
decltype(auto) with_ambient_switches(const Stages& s, F&& f) {
    if (s.ambient)
        return s.objects ? f(Switches<Shadows, Phong, true, true>{}) : f(Switches<Shadows, Phong, true, false>{});
    return s.objects ? f(Switches<Shadows, Phong, false, true>{}) : f(Switches<Shadows, Phong, false, false>{});
}
template <class F>
decltype(auto) with_stage_switches(const Stages& s, F&& f) {
    if (s.shadows)
        return s.phong ? with_ambient_switches<true, true>(s, f) : with_ambient_switches<true, false>(s, f);
    return s.phong ? with_ambient_switches<false, true>(s, f) : with_ambient_switches<false, false>(s, f);
}

struct NamedScene {
    std::string name;
    Scene scene;
    std::vector<int> panes;
    // On a pane wider than 256, the rows checked (empty: all of them). A
    // hard case's pane of 2049 would be four million traced pixels on every
    // path; its pixel's rows and the pane's first and last stand for it.
    std::vector<int> wide_rows = {};
};

// The rows of a w × w pane that are checked for the scene.
inline std::vector<int> rows_checked(const NamedScene& named, int w) {
    std::vector<int> rows;
    if (w > 256 && !named.wide_rows.empty()) {
        for (const int i : named.wide_rows)
            if (i >= 0 && i < w) rows.push_back(i);
        return rows;
    }
    for (int i = 0; i < w; ++i) rows.push_back(i);
    return rows;
}

// Panes that are and are not whole vectors of 2, 4 and 8 doubles.
inline const std::vector<int> small_panes = {29, 32, 35};

inline std::vector<NamedScene> example_scenes() {
    std::vector<NamedScene> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find("schema") != std::string::npos) continue;
        scenes.push_back({entry.path().filename().string(), load_scene_file(path), {61, 64, 67}});
    }
    return scenes;
}

inline std::vector<NamedScene> hard_case_scenes() {
    std::vector<NamedScene> scenes;
    for (const auto& c : hard_cases_support::hard_cases_reference().at("cases")) {
        const std::string id = c.at("id").get<std::string>();
        const int w = c.at("pixel").at("w").get<int>(), i = c.at("pixel").at("i").get<int>();
        std::vector<int> rows = {0, w - 1};
        for (int k = i - 8; k <= i + 8; ++k) rows.push_back(k);
        scenes.push_back({"hard case " + id, parse_scene(c.at("scene").dump(), id), {w, 35}, rows});
    }
    return scenes;
}

// tests/non_finite_test.cpp's general scenes, without Phong: numbers from
// 1e-300 to 1e300, so deltas, |K|^2, D, shadow tests and results overflow.
inline std::vector<NamedScene> hostile_scenes(int count) {
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
        // Phong on every other scene: its k_s the 0.5 of a real one or up to
        // 1e300 (the highlight overflows), on the sphere and the plane.
        const double k_s = n % 2 == 1 ? (n % 4 == 1 ? 0.5 : 1e300) : 0.0;
        scene.materials = {Material{n % 3 == 0 ? 0.1 : 0.0, 0.8, k_s, 1 + 7 * n, {1, 0.5, 0.25}}};
        scene.spheres[0].material = 0;
        scene.planes[0].material = 0;
        scenes.push_back({"hostile " + std::to_string(n), scene, {9, 11}});
    }
    return scenes;
}

// Several spheres and planes in front of the eye (some around it), one to
// three lights, with or without shadows, ambient, Phong and colour (Phong
// with materials of other exponents, or none, each lane its hit's).
inline std::vector<NamedScene> random_scenes(int count) {
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
            if (n % 4 == 1 || n % 4 == 2) {  // Phong; one material of three without it
                m.specular = k == 2 ? 0.0 : 0.3 + 0.1 * k;
                m.exponent = k == 1 ? 10000 : 1 + (n * 13 + k * 7) % 90;
            }
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
inline std::vector<NamedScene> tie_scenes() {
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
    // Phong: the twins' highlights differ (k_s and n), the earlier wins.
    Scene shiny_twins = twins_shadows;
    shiny_twins.materials = {Material{0, 0.9, 0.6, 25, {1, 1, 1}}, Material{0.1, 0.3, 0.2, 3, {1, 1, 1}}};
    scenes.push_back({"shiny twin spheres and planes, shadows", shiny_twins, small_panes});
    return scenes;
}

// One sphere and one light (render/general_row_one_sphere.hpp), every
// combination of its switches: shadows, ambient, colour, plain (k_d, m and
// c exactly 1) or not, the eye outside or inside, Phong or not (scenes 32 to
// 63); and hostile ones (numbers
// from 1e-300 to 1e300: deltas, roots, |K|^2, D and results overflow), some
// of them plain.
inline std::vector<NamedScene> one_sphere_scenes(int hostile) {
    std::vector<NamedScene> scenes;
    for (int n = 0; n < 64; ++n) {
        Scene scene;
        scene.shadows = n & 1;
        const bool ambient = n & 2, coloured = n & 4, plain = n & 8, inside = n & 16, phong = n & 32;
        Material m;
        m.ambient = ambient ? 0.25 : 0;
        if (phong) m.specular = 0.5, m.exponent = 1 + (n * 5) % 40;
        if (!plain) m.diffuse = 0.7, m.colour = coloured ? Colour{1, 0.5, 0.25} : Colour{0.6, 0.6, 0.6};
        scene.materials = {m};
        scene.spheres = {inside ? Sphere{{0.1, -0.2, 0.5}, 3, 0} : Sphere{{0.2, 0.1, 3.2}, 1.1, 0}};
        scene.lights = {Light{{1.5, 1, inside ? 1.0 : 1.2}, 1.25, plain ? white : Colour{0.9, 0.9, 0.9}}};
        if (coloured) scene.background = {0.1, 0.2, 0.3};
        scenes.push_back({"one sphere " + std::to_string(n), scene, small_panes});
    }
    // The article's matte white with a light of intensity -0 (which passes
    // a scene file's I >= 0) or negative, or a sphere of negative radius (a
    // scene built in code): the diffuse term is then -0 or negative, and
    // trace_general's 0 + it turns -0 into 0, which the plain rows
    // (render/general_row_one_sphere.hpp) must not leave out.
    const std::pair<double, double> signs[] = {{-0.0, 1.1}, {0.0, -1.1}, {1.25, -1.1}, {-0.0, -1.1}, {-1.25, 1.1}};
    for (const auto& [I, r] : signs) {
        Scene scene;
        scene.materials = {Material{}};
        scene.spheres = {Sphere{{0.2, 0.1, 3.2}, r, 0}};
        scene.lights = {Light{{1.5, 1, 1.2}, I, white}};
        scenes.push_back({fmt::format("one sphere, I {}, r {}", I, r), scene, small_panes});
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
        const double k_s = n % 4 == 3 ? 0.5 : n % 4 == 1 ? 1e300 : 0.0;  // Phong, its highlight overflowing
        scene.materials = {plain ? Material{n % 4 == 0 ? 0.1 : 0.0, 1, k_s, 1 + n, white}
                                 : Material{n % 4 == 0 ? 0.1 : 0.0, std::abs(big()), k_s, 1 + n, {1, 0.5, 0.25}}};
        scene.spheres = {Sphere{point(), std::abs(big()), 0}};
        scene.lights = {Light{point(), std::abs(big()), plain ? white : Colour{0.5, 1, 1}}};
        if (n % 5 == 0) scene.background = {0.1, 0.2, 0.3};
        scenes.push_back({"hostile one sphere " + std::to_string(n), scene, {9, 11}});
    }
    return scenes;
}

}  // namespace general_scenes_support
