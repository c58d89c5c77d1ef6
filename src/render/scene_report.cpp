#include "render/scene_report.hpp"

#include <fmt/format.h>

#include "render/renderer.hpp"

namespace promyk {

namespace {

std::string point_text(const Vec3d& v) { return fmt::format("({}, {}, {})", v.x, v.y, v.z); }

struct CountingSink final : RenderSink {
    void image_rows(const std::uint8_t*, int) override {}
};

}  // namespace

SceneReport report_scene(const Scene& scene, int probe_w) {
    SceneReport report;
    report.contents.push_back(fmt::format("name \"{}\", pane at z_E = {}, background {}", scene.name, scene.z_E,
                                          scene.background.x));
    for (std::size_t k = 0; k < scene.spheres.size(); ++k)
        report.contents.push_back(fmt::format("sphere {}: S = {}, r = {}", k + 1, point_text(scene.spheres[k].S),
                                              scene.spheres[k].r));
    for (std::size_t k = 0; k < scene.lights.size(); ++k)
        report.contents.push_back(
            fmt::format("light {}: L = {}, I = {}", k + 1, point_text(scene.lights[k].L), scene.lights[k].I));

    // This version's engine is the article's program: the same stages for
    // every scene it accepts.
    report.stages = {
        "pane: E = ((2j+1)/w − 1, −(2i+1)/w + 1, z_E) for each pixel",
        "sphere: the article's quadratic, Δ/4 = C² − |E|²(|S|² − r²), the nearer root t",
        "hit: P = tE, N = P − S",
        "Lambert shading for one light: I·D / (r·√|K|²) where D = N·K > 0",
    };
    report.skipped = {
        "no loop over objects: the scene has one sphere",
        "no shadow rays: this version of the scene format has no shadows",
        "no specular (Phong) term: this version of the scene format has no materials",
        "no colour channels: the scene is grey",
    };

    const Sphere& sphere = scene.spheres.front();
    const Light& light = scene.lights.front();
    const Vec3d to_light = light.L - sphere.S;
    if (length_squared(to_light) < sphere.r * sphere.r)
        report.warnings.push_back("the light is inside the sphere: no point of its surface faces it from outside");
    if (sphere.S.z + sphere.r < 0)
        report.warnings.push_back(
            "the sphere lies behind the eye (z_S + r < 0); the article's program, which never checks t > 0, "
            "still draws it");
    if (light.I == 0) report.warnings.push_back("the light's intensity I is 0: every hit is black");

    // What the pixels of a small pane see.
    CountingSink sink;
    RenderStats stats;
    render(scene, {probe_w, 0}, PixelSelection{}, sink, &stats);
    const long long hits = stats.count(Branch::dark) + stats.count(Branch::lit);
    if (hits == 0 && stats.count(Branch::non_finite) == 0)
        report.warnings.push_back(fmt::format(
            "no pixel of a {0} × {0} pane sees the sphere: it is outside the pane's view, or too small", probe_w));
    else if (stats.count(Branch::lit) == 0 && stats.count(Branch::non_finite) == 0)
        report.warnings.push_back(fmt::format(
            "no visible point of the sphere faces the light (a {0} × {0} pane has {1} dark pixels, 0 lit)", probe_w,
            stats.count(Branch::dark)));
    if (const long long n = stats.count(Branch::non_finite))
        report.warnings.push_back(fmt::format(
            "{} of {} pixels of a {} × {} pane are non-finite: the numbers leave the range of a double", n,
            stats.primary_rays, probe_w, probe_w));
    return report;
}

}  // namespace promyk
