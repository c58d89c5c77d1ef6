// Scenes of every size a double can hold (issue 19, underflow): a scene
// scaled by s from the largest doubles down to the subnormals is either
// refused by the loader (exit 3: a number too small or too large) or gives
// unit vectors within a few ulps at every pixel that is not non-finite: each
// light's K_P, Phong's V_hat, a plane's N (N_plane), and a sphere's N_P up
// to P's own distance from the surface (t's rounding, the same at every
// scale). Near
// 1e-160 |K|² used to be a subnormal number, and K_P and V_hat came out
// several percent short of unit length.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "render/scene_report.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_validate.hpp"
#include "trace/trace.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

// A scene with every stage that normalises: two spheres, a tilted plane,
// two lights (one of them near the surfaces), Phong and shadows; every
// position and length is `s` times the number written here. The pane
// (z_E) stays: the eye at the origin sees the same picture at every scale.
std::string scaled_scene(double s, double light_offset) {
    const auto x = [s](double value) { return fmt::format("{:.17g}", value * s); };
    return fmt::format(R"({{
  "z_E": 2,
  "shadows": true,
  "materials": [{{"diffuse": 0.7, "specular": 0.5, "exponent": 20}}],
  "spheres": [{{"S": [{}, {}, {}], "r": {}, "material": 0}}, {{"S": [{}, {}, {}], "r": {}}}],
  "planes": [{{"Q": [{}, {}, {}], "n": [0.25, 1, -0.5], "material": 0}}],
  "lights": [{{"L": [{}, {}, {}], "I": 1}}, {{"L": [{}, {}, {}], "I": 0.5}}]
}})",
                       x(0.3), x(-0.2), x(3.2), x(1.1), x(-1.4), x(0.9), x(4.5), x(0.6), x(0), x(-1.5), x(2),
                       x(1.5), x(1), x(1), x(-0.7 + light_offset), x(0.25), x(2.05));
}

struct MagnitudeTally {
    int refused = 0, accepted = 0, unit_vectors = 0, sphere_normals = 0, non_finite = 0;
};

long double length_ld(const Vec3d& v) {
    return std::sqrt(static_cast<long double>(v.x) * v.x + static_cast<long double>(v.y) * v.y +
                     static_cast<long double>(v.z) * v.z);
}

// The unit vectors of one trace; failures as text.
void check_units(const Scene& scene, const PixelTrace& trace, MagnitudeTally& tally, std::vector<std::string>& failures) {
    const double u = std::ldexp(1.0, -53);
    if (trace.branch == Branch::non_finite) {
        ++tally.non_finite;
        return;
    }
    const Vec3d* P = nullptr;
    for (const Step& step : trace.steps) {
        const Vec3d* v = std::get_if<Vec3d>(&step.value);
        if (v == nullptr) continue;
        if (step.key == Key::P && step.group < 0) P = v;
        const bool unit = step.key == Key::K_P || step.key == Key::V_hat || step.key == Key::N_plane;
        const bool sphere_normal = step.key == Key::N_P && step.group < 0;
        if (!unit && !sphere_normal) continue;
        // Each component's square is exact in long double for these sizes.
        const double error = static_cast<double>(std::fabs(length_ld(*v) - 1));
        double allowed = 8 * u;
        if (sphere_normal) {
            // N_P = (P − S) / r is unit only as far as P lies on the surface
            // (t's rounding), which is the same at every scale.
            int k = 0;
            if (P == nullptr || std::sscanf(trace.hit_object.c_str(), "sphere %d", &k) != 1) continue;
            const Sphere& sphere = scene.spheres.at(static_cast<std::size_t>(k));
            const Vec3d d = *P - sphere.S;
            allowed += static_cast<double>(std::fabs(length_ld(d) - sphere.r) / sphere.r);
            ++tally.sphere_normals;
        } else {
            ++tally.unit_vectors;
        }
        if (!(error <= allowed))
            failures.push_back(fmt::format("pixel ({}, {}): |{}| - 1 = {:.3g}, more than {:.3g}", trace.header.i,
                                           trace.header.j, key_name(step.key), error, allowed));
    }
}

}  // namespace

TEST_CASE("a scene of any size is refused or gives unit vectors within a few ulps", "[scene][magnitude]") {
    constexpr int w = 6;
    MagnitudeTally tally;
    std::vector<std::string> failures;
    std::uint64_t state = 20261202;
    // Scales 2^e · m from the largest doubles to the smallest subnormals.
    for (int e = 1023; e >= -1074; e -= 5) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const double m = 1 + static_cast<double>(state >> 11) * 0x1p-53;
        const double s = std::ldexp(m, e);
        if (!std::isfinite(s) || s == 0) continue;
        // The second light near a surface at one scale in two.
        const double offset = e % 2 ? 0 : 1e-9;
        const std::string text = scaled_scene(s, offset);
        Scene scene;
        try {
            scene = load_scene_text(text, "scaled.json");
        } catch (const InputError& refused) {
            ++tally.refused;
            // Refused only where some number other than 0 is out of range.
            const bool tiny = 0.2 * s < scene_detail::min_scene_magnitude;  // sphere 0's y, the smallest
            const bool huge = s > 1e152;  // sphere 1's |S|² − r² overflows from about 2.8e153
            INFO("scale " << s << ": " << refused.what());
            CHECK((tiny || huge));
            continue;
        }
        ++tally.accepted;
        const std::size_t before = failures.size();
        for (int i = 0; i < w; ++i)
            for (int j = 0; j < w; ++j) check_units(scene, trace_pixel(scene, w, i, j), tally, failures);
        if (failures.size() != before) {
            INFO("scale " << s << "\n" << text);
            for (std::size_t k = before; k < failures.size() && k < before + 5; ++k) FAIL_CHECK(failures[k]);
        }
    }
    INFO(tally.refused << " refused, " << tally.accepted << " accepted, " << tally.unit_vectors << " unit vectors, "
                       << tally.sphere_normals << " sphere normals, " << tally.non_finite << " non-finite");
    // The sweep tested something at both ends and in the middle.
    CHECK(tally.refused > 100);  // below about 1e-49 and above about 1e153
    CHECK(tally.accepted > 100);  // 1e-49 .. 1e153: about 670 binary orders of magnitude
    CHECK(tally.unit_vectors > 10000);
    CHECK(tally.sphere_normals > 1000);
    CHECK(failures.empty());
}

TEST_CASE("numbers of mixed sizes in one scene: refused or unit vectors", "[scene][magnitude]") {
    // Each coordinate on its own scale, 10^-80 to 10^160 (or 0): every
    // accepted scene still gives unit vectors.
    MagnitudeTally tally;
    std::vector<std::string> failures;
    std::uint64_t state = 977;
    const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return state >> 11;
    };
    const auto any = [&] {
        const std::uint64_t r = next();
        if (r % 7 == 0) return 0.0;
        const double m = (r % 2 ? -1.0 : 1.0) * (1 + static_cast<double>(next()) * 0x1p-53);
        return m * std::pow(10.0, static_cast<double>(static_cast<int>(next() % 241) - 80));
    };
    for (int n = 0; n < 1500; ++n) {
        const std::string text = fmt::format(
            R"({{"z_E": {:.17g}, "materials": [{{"specular": 0.5, "exponent": 7}}],
  "spheres": [{{"S": [{:.17g}, {:.17g}, {:.17g}], "r": {:.17g}, "material": 0}}],
  "planes": [{{"Q": [{:.17g}, {:.17g}, {:.17g}], "n": [{:.17g}, {:.17g}, 1], "material": 0}}],
  "lights": [{{"L": [{:.17g}, {:.17g}, {:.17g}]}}]}})",
            std::fabs(any()) + 1e-300, any(), any(), std::fabs(any()) + 1, std::fabs(any()) + 1e-300, any(), any(),
            any(), any(), any(), any(), any(), any());
        Scene scene;
        try {
            scene = load_scene_text(text, "mixed.json");
        } catch (const InputError&) {
            ++tally.refused;
            continue;
        }
        ++tally.accepted;
        const std::size_t before = failures.size();
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) check_units(scene, trace_pixel(scene, 4, i, j), tally, failures);
        if (failures.size() != before) {
            INFO(text);
            FAIL_CHECK(failures[before]);
        }
    }
    INFO(tally.refused << " refused, " << tally.accepted << " accepted, " << tally.unit_vectors << " unit vectors");
    CHECK(tally.accepted > 20);
    CHECK(tally.refused > 100);
    CHECK(tally.unit_vectors > 100);
    CHECK(failures.empty());
}

TEST_CASE("scene check warns when a scene's numbers are too small for float, and only then", "[scene][magnitude]") {
    // The loader refuses below 1e-50 (double's bound); float's is 1e-12.
    const auto warned = [](const std::string& text) {
        const SceneReport report = report_scene(load_scene_text(text, "s.json"), 8);
        for (const std::string& warning : report.warnings)
            if (warning.find("in float (--real float)") != std::string::npos) return warning;
        return std::string();
    };
    const std::string tiny = warned(scaled_scene(1e-20, 0));
    INFO(tiny);
    CHECK(tiny.find("e-21 (/spheres/0/S/1)") != std::string::npos);  // −0.2 × 1e-20, sphere 0's y
    CHECK(tiny.find("at least 1e-12") != std::string::npos);
    CHECK(warned(scaled_scene(1e-11, 0)).empty());  // 2e-12 and up: fine in float too
    CHECK(!warned(scaled_scene(1e-13, 0)).empty());
    CHECK(warned(scaled_scene(1, 0)).empty());
    CHECK(warned(scaled_scene(1e100, 0)).empty());
}
