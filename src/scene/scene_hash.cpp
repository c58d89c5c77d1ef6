#include <cstdint>

#include <fmt/format.h>

#include "scene/scene.hpp"

namespace promyk {

namespace {

// The scene written as one canonical line: every number as its shortest
// round-trip text, so two scenes hash alike exactly when they render alike.
std::string canonical_text(const Scene& scene) {
    std::string text = fmt::format("name={};z_E={};background={}", scene.name, scene.z_E, scene.background.x);
    for (const Sphere& s : scene.spheres) text += fmt::format(";sphere=S({},{},{}),r({})", s.S.x, s.S.y, s.S.z, s.r);
    for (const Light& l : scene.lights) text += fmt::format(";light=L({},{},{}),I({})", l.L.x, l.L.y, l.L.z, l.I);
    return text;
}

}  // namespace

std::string scene_hash(const Scene& scene) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
    for (unsigned char c : canonical_text(scene)) {
        h ^= c;
        h *= 1099511628211ull;  // FNV-1a 64 prime
    }
    return fmt::format("fnv1a64:{:016x}", h);
}

}  // namespace promyk
