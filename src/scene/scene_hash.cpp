#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "scene/scene.hpp"

namespace promyk {

namespace {

std::string triple(const Vec3d& v) { return fmt::format("({},{},{})", v.x, v.y, v.z); }

// The scene written as one canonical line: every number as its shortest
// round-trip text, so two scenes hash alike exactly when they render alike.
// A field at its default is left out, so the article scene's text (and hash)
// is what it was before the format grew; any other value is written with a
// tag of its own ("c" colour, "m" material index, ...).
std::string canonical_text(const Scene& scene) {
    const Colour& bg = scene.background;
    std::string text = fmt::format("name={};z_E={};background={}", scene.name, scene.z_E,
                                   is_grey(bg) && std::signbit(bg.x) == std::signbit(bg.y) &&
                                           std::signbit(bg.y) == std::signbit(bg.z)
                                       ? fmt::format("{}", bg.x)
                                       : triple(bg));
    if (scene.shadows) text += ";shadows=1";
    auto material = [](int index) { return index == no_material ? std::string() : fmt::format(",m({})", index); };
    for (const Sphere& s : scene.spheres) text += fmt::format(";sphere=S{},r({}){}", triple(s.S), s.r, material(s.material));
    for (const Plane& p : scene.planes) text += fmt::format(";plane=Q{},n{}{}", triple(p.Q), triple(p.n), material(p.material));
    for (const Light& l : scene.lights)
        text += fmt::format(";light=L{},I({}){}", triple(l.L), l.I, l.colour == white ? "" : ",c" + triple(l.colour));
    for (const Material& m : scene.materials)
        text += fmt::format(";material=a({}),d({}),s({}),n({}),c{}", m.ambient, m.diffuse, m.specular, m.exponent,
                            triple(m.colour));
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
