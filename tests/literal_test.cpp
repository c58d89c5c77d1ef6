// The tracer equals the article's program compiled literally, bit for bit
// (PRODUCT.md section 8): for every pixel of several pane sizes, every value
// the tracer records, its branch, the keys it records and the intensity of
// both the traced and the untraced (NullRecorder) path are compared with
// tests/article_literal.hpp, a line-by-line transcription of the pseudocode.
// This holds for the article's scene and for scenes that are not the
// article's (tests/reference/scenes/: off-axis centres, I != 1, backgrounds
// != 1/2, z_E != 2, a tangent ray with delta exactly 0, a hit with D exactly 0).
//
// Doubles are compared by their bits (memcmp), not with ==, so that -0.0
// against 0.0 or a NaN anywhere would be caught.
#include <catch2/catch.hpp>

#include <cstring>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "article_literal.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"
#include "same_bits.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "sweep_size.hpp"
#include "trace/keys.hpp"
#include "trace/recorder.hpp"
#include "trace/trace.hpp"

namespace {

using promyk::Branch;
using promyk::Key;
using promyk::Vec3d;
using promyk_literal::LiteralLocals;
using promyk_literal::LiteralReturn;

using promyk::testing::same_bits;

std::string show(double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
}

std::string show(const Vec3d& v) { return "(" + show(v.x) + ", " + show(v.y) + ", " + show(v.z) + ")"; }

std::string show(const promyk::StepValue& v) {
    return std::holds_alternative<double>(v) ? show(std::get<double>(v)) : show(std::get<Vec3d>(v));
}

Branch literal_branch(const LiteralLocals& v) {
    switch (v.returned) {
        case LiteralReturn::half:
            return Branch::miss;
        case LiteralReturn::zero:
            return Branch::dark;
        case LiteralReturn::intensity:
            return Branch::lit;
    }
    return Branch::miss;
}

// The scene's numbers, as the literal program's inputs.
promyk_literal::LiteralScene literal_scene(const promyk::Scene& scene) {
    const promyk::Sphere& sphere = scene.spheres.at(0);
    const promyk::Light& light = scene.lights.at(0);
    promyk_literal::LiteralScene s;
    s.z_E = scene.z_E;
    s.x_S = sphere.S.x, s.y_S = sphere.S.y, s.z_S = sphere.S.z;
    s.r = sphere.r;
    s.x_L = light.L.x, s.y_L = light.L.y, s.z_L = light.L.z;
    s.I = light.I;
    s.background = scene.background.x;
    return s;
}

const std::string reference_scene_dir = PROMYK_SOURCE_DIR "/tests/reference/scenes/";

// The trace's steps that are the program's variables, in the trace's order
// (steps the tracer may add for lessons are skipped: compared by key).
std::vector<promyk::Step> literal_program_steps(const promyk::PixelTrace& trace) {
    std::vector<promyk::Step> steps;
    for (const promyk::Step& step : trace.steps)
        for (const Key key : {Key::E, Key::EE, Key::SS, Key::C, Key::delta, Key::t, Key::P, Key::N, Key::K, Key::KK,
                              Key::D})
            if (step.key == key) steps.push_back(step);
    return steps;
}

// What the literal program computed, as the tracer's steps: a miss stops
// after delta, a dark or lit pixel after D.
std::vector<promyk::Step> literal_steps(const LiteralLocals& v) {
    std::vector<promyk::Step> steps = {
        {Key::E, Vec3d{v.x_E, v.y_E, v.z_E}}, {Key::EE, v.E}, {Key::SS, v.S}, {Key::C, v.C}, {Key::delta, v.Delta},
    };
    if (v.returned == LiteralReturn::half) return steps;
    steps.push_back({Key::t, v.t});
    steps.push_back({Key::P, Vec3d{v.x_P, v.y_P, v.z_P}});
    steps.push_back({Key::N, Vec3d{v.x_N, v.y_N, v.z_N}});
    steps.push_back({Key::K, Vec3d{v.x_K, v.y_K, v.z_K}});
    steps.push_back({Key::KK, v.K});
    steps.push_back({Key::D, v.D});
    return steps;
}

bool same_value(const promyk::StepValue& a, const promyk::StepValue& b) {
    if (a.index() != b.index()) return false;
    if (std::holds_alternative<double>(a)) return same_bits(std::get<double>(a), std::get<double>(b));
    return same_bits(std::get<Vec3d>(a), std::get<Vec3d>(b));
}

// Compares one pixel; returns an empty string when everything agrees.
std::string compare_pixel(const promyk::ArticleWorld<double>& world, const promyk::TraceHeader& header, int i, int j,
                          const LiteralLocals& literal, double literal_t) {
    const int w = header.w;
    std::ostringstream why;
    const auto where = [&] {
        return "w=" + std::to_string(w) + " (" + std::to_string(i) + "," + std::to_string(j) + "): ";
    };

    // The loop's value and the function's result are one number.
    if (!same_bits(literal_t, literal.result)) why << where() << "literal loop and locals disagree\n";

    const promyk::PixelTrace trace = promyk::trace_pixel(world, header, i, j);
    promyk::NullRecorder null_recorder;
    const promyk::PixelResult<double> untraced = promyk::trace_pixel_ray(world, w, i, j, null_recorder);
    const Branch expected_branch = literal_branch(literal);

    if (trace.branch != expected_branch)
        why << where() << "traced branch " << promyk::branch_name(trace.branch) << ", literal "
            << promyk::branch_name(expected_branch) << "\n";
    if (untraced.branch != expected_branch)
        why << where() << "untraced branch " << promyk::branch_name(untraced.branch) << ", literal "
            << promyk::branch_name(expected_branch) << "\n";
    if (!same_bits(trace.result, literal_t))
        why << where() << "traced result " << show(trace.result) << ", literal " << show(literal_t) << "\n";
    if (!same_bits(untraced.I_P, literal_t))
        why << where() << "untraced result " << show(untraced.I_P) << ", literal " << show(literal_t) << "\n";

    const std::vector<promyk::Step> expected = literal_steps(literal);
    const std::vector<promyk::Step> recorded = literal_program_steps(trace);
    if (recorded.size() != expected.size()) {
        why << where() << recorded.size() << " of the program's steps recorded, the literal program reached "
            << expected.size() << "\n";
    }
    const std::size_t n = std::min(recorded.size(), expected.size());
    for (std::size_t k = 0; k < n; ++k) {
        const promyk::Step& got = recorded[k];
        const promyk::Step& want = expected[k];
        if (got.key != want.key) {
            why << where() << "step " << k << " is " << promyk::key_name(got.key) << ", expected "
                << promyk::key_name(want.key) << "\n";
            break;
        }
        if (!same_value(got.value, want.value))
            why << where() << promyk::key_name(got.key) << " = " << show(got.value) << ", literal " << show(want.value)
                << "\n";
    }
    return why.str();
}

}  // namespace

TEST_CASE("the literal transcription holds the article's numbers", "[literal]") {
    const promyk_literal::LiteralScene literal;
    const promyk::Scene scene = promyk::article_scene();
    REQUIRE(scene.spheres.size() == 1);
    REQUIRE(scene.lights.size() == 1);
    CHECK(same_bits(scene.z_E, literal.z_E));
    CHECK(same_bits(scene.spheres[0].S, Vec3d{literal.x_S, literal.y_S, literal.z_S}));
    CHECK(same_bits(scene.spheres[0].r, literal.r));
    CHECK(same_bits(scene.lights[0].L, Vec3d{literal.x_L, literal.y_L, literal.z_L}));
    CHECK(same_bits(scene.lights[0].I, literal.I));
    CHECK(same_bits(scene.background.x, 0.5));  // the article's "return 1/2"
    CHECK(same_bits(literal.background, scene.background.x));
}

namespace {

// Compares every pixel of a w x w pane of the scene with the literal program;
// returns the branch counts (miss, dark, lit).
std::vector<int> check_every_pixel(const promyk::Scene& scene, int w) {
    const promyk::ArticleWorld<double> world = promyk::article_world(scene);
    const promyk::TraceHeader header = promyk::trace_header(scene, w);

    std::vector<LiteralLocals> locals;
    const std::vector<double> t = promyk_literal::literal_program(w, literal_scene(scene), &locals);

    std::string first_mismatches;
    int mismatched_pixels = 0;
    std::vector<int> counts = {0, 0, 0};
    for (int i = 0; i < w; ++i) {
        for (int j = 0; j < w; ++j) {
            const std::size_t index = static_cast<std::size_t>(i) * static_cast<std::size_t>(w) + j;
            ++counts[static_cast<std::size_t>(literal_branch(locals[index]))];
            const std::string why = compare_pixel(world, header, i, j, locals[index], t[index]);
            if (!why.empty()) {
                if (++mismatched_pixels <= 5) first_mismatches += why;
            }
        }
    }
    INFO("scene " << scene.name << ", w = " << w << ": " << counts[0] << " miss, " << counts[1] << " dark, "
                  << counts[2] << " lit");
    INFO(first_mismatches);
    CHECK(mismatched_pixels == 0);
    return counts;
}

}  // namespace

TEST_CASE("every pixel equals the article's literal program bit for bit", "[literal]") {
    const int w = GENERATE(1, 2, 3, 7, 8, 63, 64, 100, sweep_size(512, 128));
    const std::vector<int> counts = check_every_pixel(promyk::article_scene(), w);
    if (w >= 8) {
        // The scene has all three branches at these sizes.
        CHECK(counts[0] > 0);
        CHECK(counts[1] > 0);
        CHECK(counts[2] > 0);
    }
}

TEST_CASE("scenes that are not the article's equal the literal program bit for bit", "[literal]") {
    const std::string file = GENERATE(as<std::string>{}, "off_axis_far.json", "off_axis_near.json",
                                      "tangent_axis.json", "tangent_off_axis.json", "dark_exact.json");
    const promyk::Scene scene = promyk::load_scene_file(reference_scene_dir + file);
    std::vector<int> total = {0, 0, 0};
    for (const int w : {1, 2, 3, 7, 8, 64, 101}) {
        const std::vector<int> counts = check_every_pixel(scene, w);
        for (std::size_t k = 0; k < 3; ++k) total[k] += counts[k];
    }
    INFO("scene " << file);
    CHECK(total[0] > 0);  // every scene has misses, which return its background
    if (file.rfind("off_axis", 0) == 0) {
        // S with distinct non-zero x, y, z, so a C that mixes up E's and S's
        // components is seen; I != 1 and a lit side, so a lost I is seen.
        CHECK(total[1] > 0);
        CHECK(total[2] > 0);
    }
}

TEST_CASE("the yardstick's pixels with delta or D exactly 0 are where the scene files say", "[literal]") {
    // The scene files were built so that these pixels hit a test's boundary
    // exactly in double (small dyadic numbers); the literal program confirms it.
    struct Exact {
        const char* file;
        int w, i, j;
        bool delta_zero;  // else D is zero
    };
    for (const Exact& e : {Exact{"tangent_axis.json", 1, 0, 0, true}, Exact{"tangent_axis.json", 3, 1, 1, true},
                           Exact{"tangent_off_axis.json", 2, 0, 1, true}, Exact{"dark_exact.json", 1, 0, 0, false},
                           Exact{"dark_exact.json", 3, 1, 1, false}}) {
        INFO(e.file << " w = " << e.w << " (" << e.i << ", " << e.j << ")");
        const promyk::Scene scene = promyk::load_scene_file(reference_scene_dir + e.file);
        std::vector<LiteralLocals> locals;
        const std::vector<double> t = promyk_literal::literal_program(e.w, literal_scene(scene), &locals);
        const std::size_t index = static_cast<std::size_t>(e.i * e.w + e.j);
        const LiteralLocals& v = locals[index];
        const promyk::PixelTrace trace = promyk::trace_pixel(scene, e.w, e.i, e.j);
        if (e.delta_zero) {
            CHECK(same_bits(v.Delta, 0.0));
            CHECK(v.returned == LiteralReturn::half);
            CHECK(same_bits(t[index], scene.background.x));
            CHECK(trace.branch == Branch::miss);
            CHECK(same_bits(trace.result, scene.background.x));
        } else {
            CHECK(v.Delta > 0);
            CHECK(same_bits(v.D, 0.0));
            CHECK(v.returned == LiteralReturn::zero);
            CHECK(same_bits(t[index], 0.0));
            CHECK(trace.branch == Branch::dark);
            CHECK(same_bits(trace.result, 0.0));
        }
    }
}

TEST_CASE("the three named pixels of w = 8 take their named branches", "[literal]") {
    const promyk::Scene scene = promyk::article_scene();
    std::vector<LiteralLocals> locals;
    promyk_literal::literal_program(8, {}, &locals);

    struct Named {
        int i, j;
        Branch branch;
    };
    for (const Named named : {Named{0, 0, Branch::miss}, Named{5, 1, Branch::dark}, Named{3, 4, Branch::lit}}) {
        INFO("pixel (" << named.i << ", " << named.j << ")");
        CHECK(promyk::trace_pixel(scene, 8, named.i, named.j).branch == named.branch);
        CHECK(literal_branch(locals[static_cast<std::size_t>(named.i * 8 + named.j)]) == named.branch);
    }
}
