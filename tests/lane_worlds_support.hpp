// What the lane kernels' tests share (tests/article_lanes_test.cpp for the
// rows, tests/sample_lanes_test.cpp for the sampled rows): the scenes the
// article's kernel draws (the examples, the hard cases, non-finite worlds),
// random spheres, the formulas with lanes and the traced path to compare with.
#pragma once

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/sphere_formulas.hpp"
#include "hard_cases_support.hpp"
#include "render/stages.hpp"
#include "render/tracer.hpp"
#include "render/world.hpp"
#include "scene/scene_json.hpp"

namespace lane_worlds_support {

using namespace promyk;

struct NamedWorld {
    std::string name;
    ArticleWorld<double> world;
    int w;  // the scene's own pane (the hard case's), or 0
};

template <class Real>
bool same_bits(Real a, Real b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

inline std::vector<NamedWorld> article_worlds() {
    std::vector<NamedWorld> worlds;
    auto add = [&](const std::string& name, const Scene& scene, int w) {
        if (!plan_stages(scene).article) return;  // another kernel draws it
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
    // A background of -0 (0 + x would make it +0) and overflows: I D
    // infinite (non-finite after the dark test), and a sphere so far that
    // |K|^2 overflows (non-finite before it).
    ArticleWorld<double> base = worlds.front().world;
    for (const auto& named : worlds)
        if (named.name == "article.json") base = named.world;
    ArticleWorld<double> negative_zero = base;
    negative_zero.background = -0.0;
    worlds.push_back({"background -0", negative_zero, 0});
    ArticleWorld<double> bright = base;
    bright.I = 1e308;
    worlds.push_back({"I = 1e308", bright, 0});
    ArticleWorld<double> far_light = base;
    far_light.L = {1e200, 1e200, 1e200};
    worlds.push_back({"light at 1e200", far_light, 0});
    return worlds;
}

// The formulas with a lane kernel.
inline constexpr Formula lane_formulas[] = {Formula::article, Formula::stable, Formula::geometric, Formula::fma};

// The traced path's pixel with the formula.
template <class Real>
PixelResult<Real> traced_ray(const ArticleWorld<Real>& world, const Vec3<Real>& E, Formula formula) {
    NullRecorder none;
    switch (formula) {
        case Formula::stable:
            return trace_ray<SphereFormula<Formula::stable>>(world, E, none);
        case Formula::geometric:
            return trace_ray<SphereFormula<Formula::geometric>>(world, E, none);
        case Formula::fma:
            return trace_ray<SphereFormula<Formula::fma>>(world, E, none);
        case Formula::article:
            break;
    }
    return trace_ray(world, E, none);
}

// Random spheres: in front of the eye and behind it, small and far, large and
// near, and around the eye (the far root: the stable and geometric formulas
// take it), with the light anywhere.
inline std::vector<ArticleWorld<double>> random_worlds(int n) {
    std::mt19937_64 random(18);
    std::uniform_real_distribution<double> position(-3, 3), depth(-4, 14), light(-6, 6), unit(0, 1);
    std::vector<ArticleWorld<double>> worlds;
    for (int s = 0; s < n; ++s) {
        ArticleWorld<double> world{2, {position(random), position(random), depth(random)}, 0, {}, 1, 0.25};
        world.r = s % 5 == 0 ? std::pow(10.0, -3 * unit(random)) : 0.05 + 3 * unit(random);
        world.L = {light(random), light(random), light(random)};
        if (s % 7 == 0) world.S = {position(random) / 8, position(random) / 8, position(random) / 8};  // around the eye
        worlds.push_back(world);
    }
    return worlds;
}

}  // namespace lane_worlds_support
