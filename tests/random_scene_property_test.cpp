// Properties over random scenes (issue 19, "Hostile runs as tests"): a few
// thousand scenes from fixed seeds, each with random spheres, planes, lights,
// materials (Phong, colour), shadows on or off, a random pane, pixel, real
// type, formula and samples per pixel. For each:
//
// 1. traced equals untraced: the trace's branch, intensity (bit for bit) and
//    grey level or colour are the renderer's (Kernel::intensity and row);
// 2. no step of a trace is NaN or infinite unless its branch is non-finite;
// 3. every unit vector is unit within a few ulps: a plane's n_hat, Phong's
//    V_hat, each light's K_P; a sphere's N_P = N / r is unit up to P's own
//    distance from the surface (the error of t, bounded in 4) and the few
//    ulps of P - S;
// 4. the geometric formula's t is within its stated bound against quad: the
//    closed form of tests/hard_cases_formulas_test.cpp,
//    (24 k_g + 8 k_c + 16) u |t|, wherever its first order
//    R_1 = (19 k_g + 3 k_c + 11) u is at most 1/16 and the eye is not on the
//    surface (k_c finite); float, double and long double.
//
// Coordinates are drawn either freely or on a grid of eighths (about one
// value in three), so that ties, tangents, D = 0 and lights on surfaces come
// up. A failure names the seed, writes the scene to a temporary file and
// prints the promyk command that traces the same pixel.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <quadmath.h>

#include "geometry/sphere_geometric.hpp"
#include "math/real.hpp"
#include "render/kernel.hpp"
#include "render/pane.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/recorder.hpp"

using namespace promyk;

namespace {

// How often each property was tested: a run that tests nothing must not pass.
struct Counts {
    int unit_vectors = 0, sphere_normals = 0, geometric_roots = 0, steps = 0;
    int branches[branch_count] = {};
};
Counts run_counts;  // of the current run

constexpr std::uint64_t first_seed = 20261201;
constexpr int scene_count = 3000;  // the release pass; the sanitizer pass runs the first 300

// splitmix64: the same numbers on every platform and library.
struct Random {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    bool chance(double p) { return unit() < p; }
    // In [lo, hi): free, or on the grid of eighths about one time in three.
    double in(double lo, double hi) {
        const double x = lo + (hi - lo) * unit();
        return chance(1.0 / 3) ? std::round(x * 8) / 8 : x;
    }
    Vec3d vec(double lo, double hi) { return {in(lo, hi), in(lo, hi), in(lo, hi)}; }
    Colour colour() { return {unit(), unit(), unit()}; }
};

struct Drawn {
    Scene scene;
    int w = 8, i = 0, j = 0, spp = 1;
    RealType real = RealType::double_;
    Formula formula = Formula::article;
};

Drawn draw(std::uint64_t seed) {
    Random random{seed};
    Drawn d;
    Scene& s = d.scene;
    s.name = "random " + std::to_string(seed);
    s.z_E = random.in(0.5, 4);
    if (s.z_E <= 0) s.z_E = 1;
    const int materials = random.below(3);
    for (int k = 0; k < materials; ++k) {
        Material m;
        m.ambient = random.chance(0.3) ? random.in(0, 0.3) : 0;
        m.diffuse = random.in(0, 1);
        m.specular = random.chance(0.5) ? random.in(0, 1) : 0;
        m.exponent = 1 + random.below(200);
        m.colour = random.chance(0.5) ? random.colour() : white;
        s.materials.push_back(m);
    }
    auto material = [&] { return random.below(materials + 1) - 1; };  // -1: the default
    // The pane and pixel first: most spheres are put on or near the pixel's
    // ray, so that the ray meets them.
    d.w = 1 + random.below(48);
    d.i = random.below(d.w);
    d.j = random.below(d.w);
    const Vec3d E = pane_point(d.i, d.j, d.w, s.z_E);
    const int spheres = random.below(5);
    const int planes = spheres == 0 ? 1 + random.below(2) : random.below(3);
    for (int k = 0; k < spheres; ++k) {
        Sphere sphere;
        sphere.r = random.in(0.125, 4);
        if (sphere.r <= 0) sphere.r = 0.125;
        if (random.chance(0.6))
            sphere.S = random.in(-2, 8) * E + sphere.r * random.vec(-1, 1);
        else
            sphere.S = {random.in(-6, 6), random.in(-6, 6), random.in(-4, 16)};
        sphere.material = material();
        s.spheres.push_back(sphere);
    }
    for (int k = 0; k < planes; ++k) {
        Plane plane;
        plane.Q = random.vec(-6, 6);
        do plane.n = random.vec(-1, 1);
        while (plane.n == Vec3d{0, 0, 0});
        // A normal of any length: scaled by up to 2^+-300 now and then.
        if (random.chance(0.2)) plane.n = std::ldexp(1.0, random.below(601) - 300) * plane.n;
        plane.material = material();
        s.planes.push_back(plane);
    }
    const int lights = 1 + random.below(3);
    for (int k = 0; k < lights; ++k) {
        Light light;
        light.L = {random.in(-8, 8), random.in(-8, 8), random.in(-4, 16)};
        light.I = random.in(0, 2);
        if (random.chance(0.02)) light.I = 1e308;  // I D overflows: a non-finite pixel
        if (random.chance(0.3)) light.colour = random.colour();
        s.lights.push_back(light);
    }
    if (random.chance(0.3)) {
        const double grey = random.unit();
        s.background = random.chance(0.5) ? Colour{grey, grey, grey} : random.colour();
    }
    s.shadows = random.chance(0.5);
    d.spp = random.chance(0.25) ? (random.chance(0.5) ? 4 : 9) : 1;
    const RealType reals[] = {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_};
    d.real = reals[random.below(4)];
    d.formula = all_formulas[random.below(4)];
    return d;
}

// A number in its own type's exact text (real_text), or the double.
quad value_in(const Step& step, double value, std::size_t component) {
    if (step.real_text.size() <= component) return quad(value);
    const char* text = step.real_text[component].c_str();
    return strtoflt128(text, nullptr);
}

bool finite_q(quad x) { return x == x && x - x == 0; }

quad abs_q(quad x) { return x < 0 ? -x : x; }

std::string random_show(quad x) {
    char buffer[64];
    quadmath_snprintf(buffer, sizeof buffer, "%.36Qg", x);
    return buffer;
}

Vec3<quad> vector_in(const Step& step) {
    const Vec3d& v = std::get<Vec3d>(step.value);
    return {value_in(step, v.x, 0), value_in(step, v.y, 1), value_in(step, v.z, 2)};
}

quad length_q(const Vec3<quad>& v) { return sqrtq(v.x * v.x + v.y * v.y + v.z * v.z); }

int significand_bits(RealType real) {
    switch (real) {
        case RealType::float_:
            return 24;
        case RealType::double_:
            return 53;
        case RealType::long_double:
            return 64;
        case RealType::quad_:
            return 113;
    }
    return 53;
}

// The value of a double scene number in the chosen real type, exactly.
quad random_rounded(double x, RealType real) {
    switch (real) {
        case RealType::float_:
            return quad(static_cast<float>(x));
        case RealType::long_double:
            return quad(static_cast<long double>(x));
        default:
            return quad(x);
    }
}

// Property 4 in type Real: the geometric formula's root for the pixel's
// centre ray against each sphere, against the same formula in quad.
template <class Real>
void geometric_bound(const Drawn& d, std::vector<std::string>& failures) {
    const Vec3<Real> E = pane_point(d.i, d.j, d.w, Real(d.scene.z_E));
    const quad u = quad(std::ldexp(1.0, -significand_bits(RealTraits<Real>::type)));
    const Vec3<quad> Eq{quad(E.x), quad(E.y), quad(E.z)};
    NullRecorder none;
    for (std::size_t k = 0; k < d.scene.spheres.size(); ++k) {
        const Sphere& sphere = d.scene.spheres[k];
        const Vec3<Real> S{Real(sphere.S.x), Real(sphere.S.y), Real(sphere.S.z)};
        const Real r = Real(sphere.r);
        const Vec3<quad> Sq{quad(S.x), quad(S.y), quad(S.z)};
        const quad rq = quad(r);
        const quad EE = Eq.x * Eq.x + Eq.y * Eq.y + Eq.z * Eq.z;
        const quad SS = Sq.x * Sq.x + Sq.y * Sq.y + Sq.z * Sq.z;
        const quad C = Eq.x * Sq.x + Eq.y * Sq.y + Eq.z * Sq.z;
        const quad c_0 = SS - rq * rq;
        const quad delta_g = (C * C - EE * c_0) / EE;
        const quad big = SS + rq * rq;
        // Only a clear hit, with the eye clearly off the surface (k_c finite).
        if (!(delta_g > big * quad(0x1p-100)) || !(abs_q(c_0) > big * quad(0x1p-100))) continue;
        const auto exact = intersect_sphere_geometric(Eq, Sq, rq, none);
        const auto root = intersect_sphere_geometric(E, S, r, none);
        if (!exact || !root) continue;  // behind the eye, or lost: a branch, not this bound
        const quad a = c_0 + delta_g;
        const quad D = sqrtq(delta_g * (a > 0 ? a + delta_g : delta_g));
        const quad k_g = (rq * rq + rq * sqrtq(SS) + 6 * u * SS) / D;
        const quad k_c = big / abs_q(c_0);
        const quad first_order = (19 * k_g + 3 * k_c + 11) * u;
        if (first_order > quad(0.0625)) continue;
        const quad t_exact = exact->t;
        // The bound, plus the quad reference's own (its u is 2^-113).
        const quad bound = (24 * k_g + 8 * k_c + 16) * (u + quad(0x1p-113)) * abs_q(t_exact);
        const quad error = abs_q(quad(root->t) - t_exact);
        ++run_counts.geometric_roots;
        if (!(error <= bound)) {
            std::ostringstream out;
            out << "geometric t of sphere " << k << ": " << random_show(quad(root->t)) << ", quad " << random_show(t_exact)
                << ", error " << random_show(error) << " > bound " << random_show(bound) << " (k_g " << random_show(k_g) << ", k_c "
                << random_show(k_c) << ")";
            failures.push_back(out.str());
        }
    }
}

// Every property for one scene; what failed, one line each.
std::vector<std::string> check_random_scene(const Drawn& d) {
    std::vector<std::string> failures;
    auto fail = [&](const std::string& what) { failures.push_back(what); };
    const auto kernel = make_kernel(d.scene, d.real, d.formula, d.spp);
    const TraceHeader header = trace_header(d.scene, d.w);
    const PixelTrace trace = kernel->trace(header, d.i, d.j);

    // 1. Traced equals untraced.
    Branch branch;
    const Vec3d untraced = kernel->intensity(d.w, d.i, d.j, &branch);
    if (trace.branch != branch)
        fail(std::string("branch: traced ") + std::string(branch_name(trace.branch)) + ", rendered " +
             std::string(branch_name(branch)));
    const Vec3d traced = trace.result_rgb ? *trace.result_rgb : Vec3d{trace.result, trace.result, trace.result};
    if (std::memcmp(&traced, &untraced, sizeof traced) != 0) {
        std::ostringstream out;
        out.precision(17);
        out << "intensity: traced (" << traced.x << ", " << traced.y << ", " << traced.z << "), rendered ("
            << untraced.x << ", " << untraced.y << ", " << untraced.z << ")";
        fail(out.str());
    }
    std::vector<std::uint8_t> row(static_cast<std::size_t>(d.w) * kernel->channels());
    kernel->row(d.w, d.i, row.data());
    const std::size_t at = static_cast<std::size_t>(d.j) * kernel->channels();
    const bool same_bytes = kernel->channels() == 1
                                ? row[at] == trace.grey
                                : row[at] == trace.rgb[0] && row[at + 1] == trace.rgb[1] && row[at + 2] == trace.rgb[2];
    if (!same_bytes) fail("the rendered row's pixel differs from the trace's grey level or colour");

    // 2. No NaN or infinity outside the non-finite branch.
    ++run_counts.branches[static_cast<int>(trace.branch)];
    if (trace.branch != Branch::non_finite) {
        for (const Step& step : trace.steps) {
            ++run_counts.steps;
            bool finite = true;
            if (const double* x = std::get_if<double>(&step.value)) finite = finite_q(value_in(step, *x, 0));
            if (std::holds_alternative<Vec3d>(step.value)) {
                const Vec3<quad> v = vector_in(step);
                finite = finite_q(v.x) && finite_q(v.y) && finite_q(v.z);
            }
            if (!finite) fail("step " + std::string(key_name(step.key)) + " is not finite in a " +
                              std::string(branch_name(trace.branch)) + " trace");
        }
    }

    // 3. Unit vectors (every sample's: steps with these keys at any depth).
    const quad u = quad(std::ldexp(1.0, -significand_bits(d.real)));
    const Step* P = nullptr;
    for (const Step& step : trace.steps) {
        if (step.key == Key::P && step.group < 0) P = &step;
        const bool unit = step.key == Key::N_plane || step.key == Key::V_hat || step.key == Key::K_P;
        if (unit) {
            ++run_counts.unit_vectors;
            const quad error = abs_q(length_q(vector_in(step)) - 1);
            if (!(error <= 8 * u))
                fail("|" + std::string(key_name(step.key)) + "| - 1 = " + random_show(error) + ", more than 8 ulps");
        }
        // A sphere's N_P (one sample: the object hit is the pixel's).
        if (step.key == Key::N_P && step.group < 0 && d.spp == 1 && P != nullptr) {
            int k = 0;
            if (!trace.hit_object.empty() && std::sscanf(trace.hit_object.c_str(), "sphere %d", &k) != 1) continue;
            const Sphere& sphere = d.scene.spheres.at(static_cast<std::size_t>(k));
            const Vec3<quad> Pq = vector_in(*P);
            const Vec3<quad> Sq{random_rounded(sphere.S.x, d.real), random_rounded(sphere.S.y, d.real),
                                random_rounded(sphere.S.z, d.real)};
            const quad r = random_rounded(sphere.r, d.real);
            const quad off_surface = abs_q(length_q(Pq - Sq) - r) / r;
            const quad error = abs_q(length_q(vector_in(step)) - 1);
            ++run_counts.sphere_normals;
            const quad allowed = off_surface + 8 * u * (1 + (length_q(Pq) + length_q(Sq)) / r);
            if (!(error <= allowed))
                fail("|N_P| - 1 = " + random_show(error) + ", more than P's distance from the surface / r (" +
                     random_show(off_surface) + ") and a few ulps");
        }
    }

    // 4. The geometric formula's t within its bound.
    if (d.formula == Formula::geometric) {
        if (d.real == RealType::float_) geometric_bound<float>(d, failures);
        if (d.real == RealType::double_) geometric_bound<double>(d, failures);
        if (d.real == RealType::long_double) geometric_bound<long double>(d, failures);
    }
    return failures;
}

// Writes the scene where a person can trace it again; returns the command.
std::string reproduction(const Drawn& d, std::uint64_t seed) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("promyk_random_scene_" + std::to_string(seed) + ".json");
    std::ofstream(file) << scene_to_json(d.scene);
    std::ostringstream out;
    out << "promyk trace --scene " << file.string() << " --pixel " << d.i << ',' << d.j << " --w " << d.w
        << " --real " << real_type_name(d.real) << " --formula " << formula_name(d.formula) << " --spp " << d.spp;
    return out.str();
}

// Runs the properties over `count` scenes from first_seed on; how many failed.
int run_random_scenes(int count) {
    run_counts = Counts{};
    int failed = 0;
    for (int n = 0; n < count; ++n) {
        const std::uint64_t seed = first_seed + static_cast<std::uint64_t>(n);
        Drawn d = draw(seed);
        // The scene as its file reads back: what the printed command traces.
        d.scene = parse_scene(scene_to_json(d.scene), "random scene " + std::to_string(seed));
        const std::vector<std::string> failures = check_random_scene(d);
        if (failures.empty()) continue;
        ++failed;
        std::ostringstream message;
        message << "seed " << seed << " (scene " << n << " of " << count << "):\n";
        for (std::size_t k = 0; k < failures.size() && k < 8; ++k) message << "  " << failures[k] << '\n';
        if (failures.size() > 8) message << "  (" << failures.size() - 8 << " more)\n";
        message << "reproduce: " << reproduction(d, seed);
        // Also unwrapped on stderr: Catch wraps its messages at 80 columns,
        // which would break the command.
        std::cerr << message.str() << '\n';
        FAIL_CHECK(message.str());
        if (failed >= 5) break;  // enough to go on
    }
    return failed;
}

}  // namespace

// The first 300 scenes, in every pass (under the sanitizers too).
TEST_CASE("random scenes, the first 300: traced equals untraced, no stray NaN, unit normals, geometric t bounded",
          "[random-scenes-short]") {
    CHECK(run_random_scenes(300) == 0);
    CHECK(run_counts.geometric_roots > 20);
    CHECK(run_counts.sphere_normals > 20);
}

// All of them: hidden from the default run and from CTest's discovery, run
// in the release pass only as the CTest test random_scenes
// (promyk_tests "[random-scenes]"; about 3 s in release).
TEST_CASE("random scenes: traced equals untraced, no stray NaN, unit normals, geometric t within its bound",
          "[.][random-scenes]") {
    CHECK(run_random_scenes(scene_count) == 0);
    // Each property was tested often, and every branch came up.
    INFO(run_counts.geometric_roots << " geometric roots bounded, " << run_counts.unit_vectors << " unit vectors, "
                                << run_counts.sphere_normals << " sphere normals, " << run_counts.steps << " steps");
    CHECK(run_counts.geometric_roots > scene_count / 8);
    CHECK(run_counts.unit_vectors > scene_count);
    CHECK(run_counts.sphere_normals > scene_count / 8);
    for (int b = 0; b < branch_count; ++b) {
        INFO("pixels in branch " << branch_name(static_cast<Branch>(b)) << ": " << run_counts.branches[b]);
        CHECK(run_counts.branches[b] > 0);
    }
}
