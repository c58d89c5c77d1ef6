// The scene model: the article's world (eye at O, pane at z = z_E) and what
// its closing paragraph invites readers to add: more spheres and lights,
// planes, shadows, shiny (Phong) surfaces and colour. Every default
// reproduces the article: one white, matte (diffuse 1) material, no ambient,
// no specular, no shadows, a grey background.
#pragma once

#include <string>
#include <vector>

#include "math/vec3.hpp"

namespace promyk {

// An RGB colour, each channel in [0, 1]. Grey when the three are equal.
using Colour = Vec3d;

inline constexpr Colour white{1, 1, 1};

constexpr bool is_grey(const Colour& c) { return c.x == c.y && c.y == c.z; }

// How a surface answers light (the k_a, k_d, k_s, n and m).
struct Material {
    double ambient = 0;    // k_a >= 0: light that reaches every point, blocked or not
    double diffuse = 1;    // k_d >= 0: the article's Lambert term
    double specular = 0;   // k_s >= 0: Phong's highlight; 0 means no specular stage
    int exponent = 10;     // n, 1 ... 10 000: Phong's shininess
    Colour colour = white;  // m, per channel
};

inline bool is_default(const Material& m) {
    return m.ambient == 0 && m.diffuse == 1 && m.specular == 0 && m.colour == white;
}

// Objects refer to a material by its index in Scene::materials; no_material
// means the default material (the article's).
inline constexpr int no_material = -1;

struct Sphere {
    Vec3d S;       // centre
    double r = 1;  // radius, > 0
    int material = no_material;
};

// A plane through the point Q with normal n (any length but 0). Planes are
// two-sided: the normal used for shading faces the eye.
struct Plane {
    Vec3d Q;
    Vec3d n{0, 1, 0};
    int material = no_material;
};

struct Light {
    Vec3d L;       // position of the point light
    double I = 1;  // intensity, >= 0
    Colour colour = white;
};

struct Scene {
    std::string name = "untitled";
    double z_E = 2;  // distance of the pane from the eye, > 0
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Light> lights;
    std::vector<Material> materials;
    Colour background{0.5, 0.5, 0.5};  // what a ray that misses every object gives
    bool shadows = false;              // cast shadow rays towards the lights
    std::string source = "built-in";   // the file it was read from, for messages

    int object_count() const { return static_cast<int>(spheres.size() + planes.size()); }
};

// The material an object's index names (the default one for no_material).
inline const Material& material_of(const Scene& scene, int index) {
    static const Material article_material;
    return index == no_material ? article_material : scene.materials.at(static_cast<std::size_t>(index));
}

// True when a colour, not only a grey level, reaches some pixel: a light,
// a material used by an object, or the background that is not grey.
bool is_coloured(const Scene& scene);

// The article's Fig. 5 scene: z_E = 2, S = (0, 0, 3 1/5), r = 1 1/10,
// L = (1 1/2, 1, 1), I = 1, background 1/2.
Scene article_scene();

// A short, stable fingerprint of everything that affects the image
// (FNV-1a 64 of the scene's canonical text), written into trace headers.
std::string scene_hash(const Scene& scene);

}  // namespace promyk
