#include <fmt/format.h>

#include "render/tracer.hpp"
#include "util/errors.hpp"

namespace promyk {

ArticleWorld<double> article_world(const Scene& scene) {
    // The scene loader already rejects these with the field's JSON pointer;
    // this guards scenes built in code.
    if (scene.spheres.size() != 1)
        throw InputError(
            scene.source, "/spheres",
            fmt::format("this version traces exactly one sphere (the article's), got {}", scene.spheres.size()));
    if (scene.lights.size() != 1)
        throw InputError(
            scene.source, "/lights",
            fmt::format("this version traces exactly one light (the article's), got {}", scene.lights.size()));
    const Sphere& sphere = scene.spheres.front();
    const Light& light = scene.lights.front();
    if (length_squared(sphere.S) - sphere.r * sphere.r <= 0)
        throw InputError(scene.source, "/spheres/0",
                         "the eye (at the origin) is inside or on the sphere; the article's program does not "
                         "handle that");
    return {scene.z_E, sphere.S, sphere.r, light.L, light.I, scene.background.x};
}

}  // namespace promyk
