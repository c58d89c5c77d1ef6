#include "scene/scene.hpp"

namespace promyk {

Scene article_scene() {
    Scene scene;
    scene.name = "article";
    scene.z_E = 2;
    scene.spheres = {Sphere{{0, 0, 3.2}, 1.1}};
    scene.lights = {Light{{1.5, 1, 1}, 1}};
    scene.background = {0.5, 0.5, 0.5};
    return scene;
}

}  // namespace promyk
