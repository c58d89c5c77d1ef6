#include "render/scene_report.hpp"

#include <cmath>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "render/stages.hpp"
#include "scene/scene_validate.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/interrupt.hpp"

namespace promyk {

namespace {

// Numbers as the trace's "given" line writes them: the shortest text that
// reads back, U+2212 for a minus, in Polish a decimal comma and so a
// semicolon between a point's coordinates.
std::string number(double value) { return number_text(value, ui_language()); }

std::string point_text(const Vec3d& v) { return promyk::point_text(v, ui_language()); }

std::string colour_shown(const Colour& c) { return is_grey(c) ? number(c.x) : point_text(c); }

std::string material_text(int material) {
    return material == no_material ? "" : ui_message("report_uses_material", {{"m", std::to_string(material)}});
}

// A plane as the engine uses it: n̂ = n/√(n·n), each component divided, and
// NQ = n̂·Q (docs/conventions.md, "The engine's conventions").
struct UnitPlane {
    Vec3d n_hat;
    double NQ;
};

UnitPlane unit_plane(const Plane& plane) {
    const Vec3d n_hat = plane.n / std::sqrt(length_squared(plane.n));
    return {n_hat, dot(n_hat, plane.Q)};
}

// The pane's view is the pyramid of the rays through its square, spanned by
// its corners (±1, ±1, z_E). A ray E meets a plane in front of the eye when
// n̂·E has the sign of NQ (t = NQ/n̂·E > 0), so some ray of the view does
// exactly when a corner does. The eye in the plane (NQ = 0): no ray does.
bool plane_in_view(const UnitPlane& plane, double z_E) {
    bool in_view = false;
    for (const double x : {-1.0, 1.0})
        for (const double y : {-1.0, 1.0}) in_view = in_view || plane.NQ * dot(plane.n_hat, Vec3d{x, y, z_E}) > 0;
    return in_view;
}

// What the pixels of a small pane see, by the engine's rules (the nearest
// hit with t > 0, the far root from inside a sphere, two-sided planes, the
// normal facing the eye), without shadows or shading: which objects some
// pixel sees, which lights some seen point faces (D = N·K > 0), and how
// many pixels meet a non-finite number on the way.
struct Probe {
    std::vector<bool> object_seen;  // spheres, then planes
    std::vector<bool> light_faced;
    long long pixels = 0, hits = 0, non_finite = 0;
};

Probe probe_pane(const Scene& scene, int w) {
    Probe probe;
    probe.object_seen.assign(static_cast<std::size_t>(scene.object_count()), false);
    probe.light_faced.assign(scene.lights.size(), false);
    std::vector<UnitPlane> planes;
    for (const Plane& plane : scene.planes) planes.push_back(unit_plane(plane));
    const double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < w; ++i) {
        // A row costs w × (spheres + lights) tests: a big scene's probe
        // takes a while (1,500 of each: 15 ms, 1.5 s under the sanitizers),
        // and render and scene check run it before anything else.
        throw_if_interrupted();
        for (int j = 0; j < w; ++j) {
            ++probe.pixels;
            const Vec3d E{(2.0 * j + 1) / w - 1, -(2.0 * i + 1) / w + 1, scene.z_E};
            const double EE = length_squared(E);
            bool finite = std::isfinite(EE);
            double best_t = inf;
            std::size_t best = 0;
            bool flip = false;
            for (std::size_t k = 0; k < scene.spheres.size() && finite; ++k) {
                const Sphere& s = scene.spheres[k];
                const double C = dot(E, s.S);
                const double delta = C * C - EE * (length_squared(s.S) - s.r * s.r);
                finite = std::isfinite(delta);
                if (!finite || delta <= 0) continue;  // the roots below are then finite or +inf
                const double near = (C - std::sqrt(delta)) / EE;
                const double t = near > 0 ? near : (C + std::sqrt(delta)) / EE;
                if (t > 0 && t < best_t) best_t = t, best = k, flip = !(near > 0);
            }
            for (std::size_t k = 0; k < planes.size() && finite; ++k) {
                const double NE = dot(planes[k].n_hat, E);
                if (NE == 0) continue;
                const double t = planes[k].NQ / NE;  // NQ finite (the loader checks it), NE finite and not 0
                if (t > 0 && t < best_t) best_t = t, best = scene.spheres.size() + k, flip = NE > 0;
            }
            if (!finite) {
                ++probe.non_finite;
                continue;
            }
            if (best_t == inf) continue;  // a miss
            ++probe.hits;
            probe.object_seen[best] = true;
            const Vec3d P = best_t * E;
            Vec3d N = best < scene.spheres.size() ? P - scene.spheres[best].S
                                                  : planes[best - scene.spheres.size()].n_hat;
            if (flip) N = -1.0 * N;
            for (std::size_t l = 0; l < scene.lights.size(); ++l) {
                const double D = dot(N, scene.lights[l].L - P);
                if (!std::isfinite(D)) {
                    ++probe.non_finite;
                    break;
                }
                if (D > 0) probe.light_faced[l] = true;
            }
        }
    }
    return probe;
}

void add_contents(const Scene& scene, SceneReport& report) {
    report.contents.push_back(ui_message(
        "report_name", {{"name", scene.name}, {"z_E", number(scene.z_E)}, {"background", colour_shown(scene.background)}}));
    const auto count = [](std::size_t n, std::string_view id) { return counted(static_cast<long long>(n), id); };
    report.contents.push_back(ui_message("report_counts",
                                         {{"spheres", count(scene.spheres.size(), "report_spheres")},
                                          {"planes", count(scene.planes.size(), "report_planes")},
                                          {"lights", count(scene.lights.size(), "report_lights")},
                                          {"materials", count(scene.materials.size(), "report_materials")},
                                          {"shadows", ui_message(scene.shadows ? "report_shadows_on" : "report_shadows_off")}}));
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        throw_if_interrupted();  // a line an object: a scene may hold thousands
        report.contents.push_back(ui_message("report_sphere", {{"k", std::to_string(k)},
                                                               {"S", point_text(scene.spheres[k].S)},
                                                               {"r", number(scene.spheres[k].r)},
                                                               {"material", material_text(scene.spheres[k].material)}}));
    }
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        throw_if_interrupted();
        report.contents.push_back(ui_message("report_plane", {{"k", std::to_string(k)},
                                                              {"Q", point_text(scene.planes[k].Q)},
                                                              {"n", point_text(scene.planes[k].n)},
                                                              {"material", material_text(scene.planes[k].material)}}));
    }
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        throw_if_interrupted();
        const Light& light = scene.lights[k];
        report.contents.push_back(ui_message(
            "report_light",
            {{"k", std::to_string(k)},
             {"L", point_text(light.L)},
             {"I", number(light.I)},
             {"colour", light.colour == white ? "" : ui_message("report_light_colour", {{"colour", point_text(light.colour)}})}}));
    }
    for (std::size_t k = 0; k < scene.materials.size(); ++k) {
        const Material& m = scene.materials[k];
        report.contents.push_back(ui_message("report_material", {{"k", std::to_string(k)},
                                                                 {"ambient", number(m.ambient)},
                                                                 {"diffuse", number(m.diffuse)},
                                                                 {"specular", number(m.specular)},
                                                                 {"exponent", number(m.exponent)},
                                                                 {"colour", point_text(m.colour)}}));
    }
    bool any_default = false;
    for (const Sphere& s : scene.spheres) any_default = any_default || s.material == no_material;
    for (const Plane& p : scene.planes) any_default = any_default || p.material == no_material;
    if (any_default)
        report.contents.push_back(ui_message(scene.materials.empty() ? "report_default_every" : "report_default_some"));
}

void add_stages(const Scene& scene, SceneReport& report) {
    const Stages stages = plan_stages(scene);
    report.stages.push_back(ui_message("report_stage_pane"));
    if (stages.article) report.stages.push_back(ui_message("report_stage_article"));
    for (const StageNote& note : stage_notes(scene, stages)) {
        const std::string why = ui_message(note.reason);
        if (note.runs)
            report.stages.push_back(note.id + ": " + why + " (" + ui_message("stage_formula_" + note.id) + ")");
        else
            report.skipped.push_back(note.id + ": " + why);
    }
}

// Warnings are in the run's language (render prints them on stderr).
std::string warning(std::string_view id, const MessageArgs& args) { return ui_message(id, args); }

std::string index(std::size_t k) { return std::to_string(k); }

void add_geometry_warnings(const Scene& scene, SceneReport& report) {
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        throw_if_interrupted();  // spheres × lights: like the probe, long for a big scene
        const Sphere& s = scene.spheres[k];
        const double outside = length_squared(s.S) - s.r * s.r;  // as the article's program computes it
        if (outside < 0)
            report.warnings.push_back(warning("scene_warn_eye_inside", {{"k", index(k)}}));
        else if (outside == 0)
            report.warnings.push_back(warning("scene_warn_eye_on", {{"k", index(k)}}));
        if (s.S.z + s.r <= 0) report.warnings.push_back(warning("scene_warn_behind", {{"k", index(k)}}));
        for (std::size_t l = 0; l < scene.lights.size(); ++l)
            if (length_squared(scene.lights[l].L - s.S) < s.r * s.r)
                report.warnings.push_back(warning("scene_warn_light_inside", {{"l", index(l)}, {"k", index(k)}}));
    }
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        const UnitPlane plane = unit_plane(scene.planes[k]);
        if (plane.NQ == 0)
            report.warnings.push_back(warning("scene_warn_eye_in_plane", {{"k", index(k)}}));
        else if (!plane_in_view(plane, scene.z_E))
            report.warnings.push_back(warning("scene_warn_plane_out", {{"k", index(k)}}));
    }
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        if (scene.lights[l].I == 0) report.warnings.push_back(warning("scene_warn_dark_light", {{"l", index(l)}}));
}

// The smallest size of a number other than 0 among the positions and
// lengths (as the loader checks them against min_scene_magnitude), with its
// JSON pointer; below min_float_magnitude float's unit vectors come out short.
std::optional<std::string> float_range_warning_of(const Scene& scene) {
    double smallest = scene.z_E;
    std::string where = "/z_E";
    const auto consider = [&](double x, const std::string& pointer) {
        if (x != 0 && std::fabs(x) < std::fabs(smallest)) {
            smallest = x;
            where = pointer;
        }
    };
    const auto consider_point = [&](const Vec3d& p, const std::string& pointer) {
        consider(p.x, pointer + "/0");
        consider(p.y, pointer + "/1");
        consider(p.z, pointer + "/2");
    };
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        consider_point(scene.spheres[k].S, "/spheres/" + index(k) + "/S");
        consider(scene.spheres[k].r, "/spheres/" + index(k) + "/r");
    }
    for (std::size_t k = 0; k < scene.planes.size(); ++k) consider_point(scene.planes[k].Q, "/planes/" + index(k) + "/Q");
    for (std::size_t l = 0; l < scene.lights.size(); ++l) consider_point(scene.lights[l].L, "/lights/" + index(l) + "/L");
    if (!(std::fabs(smallest) < scene_detail::min_float_magnitude)) return std::nullopt;
    return warning("scene_warn_float_small", {{"value", fmt::format("{}", smallest)},
                                              {"where", where},
                                              {"limit", fmt::format("{}", scene_detail::min_float_magnitude)}});
}

void add_float_range_warning(const Scene& scene, SceneReport& report) {
    if (std::optional<std::string> text = float_range_warning_of(scene)) report.warnings.push_back(std::move(*text));
}

void add_probe_warnings(const Scene& scene, int probe_w, SceneReport& report) {
    const Probe probe = probe_pane(scene, probe_w);
    const std::string w = std::to_string(probe_w);
    if (probe.non_finite > 0) {
        report.warnings.push_back(warning("scene_warn_non_finite", {{"count", std::to_string(probe.non_finite)},
                                                                    {"pixels", std::to_string(probe.pixels)},
                                                                    {"w", w}}));
        return;  // what the other pixels see says little
    }
    for (std::size_t k = 0; k < probe.object_seen.size(); ++k) {
        if (probe.object_seen[k]) continue;
        // A sphere behind the eye and a plane out of view were named above.
        const bool sphere = k < scene.spheres.size();
        if (sphere ? scene.spheres[k].S.z + scene.spheres[k].r <= 0
                   : !plane_in_view(unit_plane(scene.planes[k - scene.spheres.size()]), scene.z_E))
            continue;
        report.warnings.push_back(warning(sphere ? "scene_warn_unseen_sphere" : "scene_warn_unseen_plane",
                                          {{"w", w}, {"k", index(sphere ? k : k - scene.spheres.size())}}));
    }
    if (probe.hits == 0) return;
    for (std::size_t l = 0; l < probe.light_faced.size(); ++l)
        if (!probe.light_faced[l])
            report.warnings.push_back(
                warning("scene_warn_unfaced", {{"l", index(l)}, {"hits", std::to_string(probe.hits)}, {"w", w}}));
}

}  // namespace

SceneReport report_scene(const Scene& scene, int probe_w) {
    SceneReport report;
    add_contents(scene, report);
    add_stages(scene, report);
    add_geometry_warnings(scene, report);
    add_float_range_warning(scene, report);
    add_probe_warnings(scene, probe_w, report);
    return report;
}

std::optional<std::string> float_range_warning(const Scene& scene) { return float_range_warning_of(scene); }

}  // namespace promyk
