// The scene model: the article's world (eye at O, pane at z = z_E, spheres,
// point lights, background). Spheres and lights are arrays from the first
// version so scene files never have to change shape as the format grows; the
// engine of this version simulates the article's case, one sphere and one light.
#pragma once

#include <string>
#include <vector>

#include "math/vec3.hpp"

namespace promyk {

struct Sphere {
    Vec3d S;       // centre
    double r = 1;  // radius, > 0
};

struct Light {
    Vec3d L;       // position of the point light
    double I = 1;  // intensity, >= 0
};

struct Scene {
    std::string name = "untitled";
    double z_E = 2;  // distance of the pane from the eye, > 0
    std::vector<Sphere> spheres;
    std::vector<Light> lights;
    double background = 0.5;          // intensity of a ray that misses every object
    std::string source = "built-in";  // the file it was read from, for messages
};

// The article's Fig. 5 scene: z_E = 2, S = (0, 0, 3 1/5), r = 1 1/10,
// L = (1 1/2, 1, 1), I = 1, background 1/2.
Scene article_scene();

// A short, stable fingerprint of everything that affects the image
// (FNV-1a 64 of the scene's canonical text), written into trace headers.
std::string scene_hash(const Scene& scene);

}  // namespace promyk
