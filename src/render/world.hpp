// The scene compiled once for the engine: every value in the engine's Real
// type, a plane's unit normal and n_hat.Q computed once, materials resolved to
// the values shading uses, and colours as one grey level when the scene is
// grey (Rgb = false) or as three channels.
#pragma once

#include <cmath>
#include <type_traits>
#include <vector>

#include "geometry/unit_normal.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"
#include "scene/scene.hpp"

namespace promyk {

template <class Real, bool Rgb>
struct World {
    // An intensity: one grey level, or r, g, b.
    using Intensity = std::conditional_t<Rgb, Vec3<Real>, Real>;

    struct Surface {  // a material as shading uses it
        Real k_a, k_d, k_s;
        int n;
        Intensity m;
    };
    struct Ball {
        Vec3<Real> S;
        Real r;
        int material;  // index into materials
    };
    struct Flat {
        Vec3<Real> n_hat;  // n / |n|
        Real NQ;           // n_hat.Q
        int material;
    };
    struct Lamp {
        Vec3<Real> L;
        Real I;
        Intensity c;
    };

    Real z_E;
    std::vector<Ball> spheres;
    std::vector<Flat> planes;
    std::vector<Lamp> lights;
    std::vector<Surface> materials;  // [0] is the default (the article's); scene material k is [k + 1]
    Intensity background;
};

template <class Real, bool Rgb>
typename World<Real, Rgb>::Intensity intensity_of(const Colour& c) {
    if constexpr (Rgb)
        return {Real(c.x), Real(c.y), Real(c.z)};
    else
        return Real(c.x);  // grey: the three channels are equal
}

template <class Real>
Vec3<Real> to_real(const Vec3d& v) {
    return {Real(v.x), Real(v.y), Real(v.z)};
}

template <class Real, bool Rgb>
World<Real, Rgb> compile_world(const Scene& scene) {
    using W = World<Real, Rgb>;
    W world;
    world.z_E = Real(scene.z_E);
    auto surface = [](const Material& m) {
        return typename W::Surface{Real(m.ambient), Real(m.diffuse), Real(m.specular), m.exponent,
                                   intensity_of<Real, Rgb>(m.colour)};
    };
    world.materials.push_back(surface(Material{}));
    for (const Material& m : scene.materials) world.materials.push_back(surface(m));
    for (const Sphere& s : scene.spheres) world.spheres.push_back({to_real<Real>(s.S), Real(s.r), s.material + 1});
    for (const Plane& p : scene.planes) {
        const Vec3<Real> n_hat = unit_normal<Real>(p.n);
        world.planes.push_back({n_hat, dot(n_hat, to_real<Real>(p.Q)), p.material + 1});
    }
    for (const Light& l : scene.lights)
        world.lights.push_back({to_real<Real>(l.L), Real(l.I), intensity_of<Real, Rgb>(l.colour)});
    world.background = intensity_of<Real, Rgb>(scene.background);
    return world;
}

}  // namespace promyk
