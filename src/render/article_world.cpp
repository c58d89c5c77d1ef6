#include <fmt/format.h>

#include "render/tracer.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

ArticleWorld<double> article_world(const Scene& scene) {
    // The scene loader already rejects these with the field's JSON pointer;
    // this guards scenes built in code.
    if (scene.spheres.size() != 1)
        throw InputError(scene.source, "/spheres",
                         ui_message("world_one_sphere", {{"count", std::to_string(scene.spheres.size())}}));
    if (scene.lights.size() != 1)
        throw InputError(scene.source, "/lights",
                         ui_message("world_one_light", {{"count", std::to_string(scene.lights.size())}}));
    const Sphere& sphere = scene.spheres.front();
    const Light& light = scene.lights.front();
    if (length_squared(sphere.S) - sphere.r * sphere.r <= 0)
        throw InputError(scene.source, "/spheres/0", ui_message("world_eye_inside"));
    return {scene.z_E, sphere.S, sphere.r, light.L, light.I, scene.background.x};
}

}  // namespace promyk
