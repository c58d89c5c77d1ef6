#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "article_literal.hpp"
#include "image/quantize.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/recorder.hpp"
#include "util/errors.hpp"
#include "same_bits.hpp"

using namespace promyk;

// Compile-time: the recorder rendering uses holds nothing and says it records nothing,
// so every call on it is removed by the compiler.
static_assert(std::is_empty_v<NullRecorder>, "NullRecorder must be empty");
static_assert(!NullRecorder::records && RecordingRecorder::records);
static_assert(std::is_trivially_copyable_v<NullRecorder>);

namespace {

std::vector<std::string> keys_of(const PixelTrace& trace) {
    std::vector<std::string> keys;
    for (const Step& step : trace.steps) keys.emplace_back(key_name(step.key));
    return keys;
}

using promyk::testing::same_bits;

// A step's value by its key (the first step with that key); fails if absent.
const StepValue& step(const PixelTrace& trace, Key key) {
    for (const Step& s : trace.steps)
        if (s.key == key) return s.value;
    FAIL("no step " << key_name(key));
    throw std::logic_error("unreachable");
}

bool has_step(const PixelTrace& trace, Key key) {
    for (const Step& s : trace.steps)
        if (s.key == key) return true;
    return false;
}

double scalar(const PixelTrace& trace, Key key) { return std::get<double>(step(trace, key)); }
Vec3d tracer_vector(const PixelTrace& trace, Key key) { return std::get<Vec3d>(step(trace, key)); }

Scene one_sphere_scene(double z_E, Vec3d S, double r, Vec3d L, double I, double background) {
    Scene scene;
    scene.name = "test";
    scene.z_E = z_E;
    scene.spheres = {Sphere{S, r}};
    scene.lights = {Light{L, I}};
    scene.background = {background, background, background};
    return scene;
}

// The rule of docs/conventions.md, round(clamp(v, 0, 1) * 255), halves up, by std::lround:
// independent of the engine's to_byte.
std::uint8_t independent_byte(double v) {
    return static_cast<std::uint8_t>(std::lround(std::min(std::max(v, 0.0), 1.0) * 255));
}

promyk_literal::LiteralScene literal_of(const Scene& scene) {
    promyk_literal::LiteralScene s;
    s.z_E = scene.z_E;
    s.x_S = scene.spheres[0].S.x, s.y_S = scene.spheres[0].S.y, s.z_S = scene.spheres[0].S.z;
    s.r = scene.spheres[0].r;
    s.x_L = scene.lights[0].L.x, s.y_L = scene.lights[0].L.y, s.z_L = scene.lights[0].L.z;
    s.I = scene.lights[0].I;
    s.background = scene.background.x;
    return s;
}

}  // namespace

TEST_CASE("a ray tangent to the sphere (delta exactly 0) misses and returns the scene's background", "[tracer]") {
    struct Tangent {
        const char* what;
        Scene scene;
        int w, i, j;
        double C, EE, SS;  // by hand
    };
    const std::vector<Tangent> cases = {
        // E = (0, 0, 2) touches S = (1, 0, 4), r = 1 at (0, 0, 4):
        // C = 8, EE = 4, SS = 17, delta = 64 - 4 (17 - 1) = 0.
        {"along x", one_sphere_scene(2, {1, 0, 4}, 1, {-1, 0.5, 1}, 0.75, 0.625), 1, 0, 0, 8, 4, 17},
        // E = (0, 0, 1.5) touches S = (0, -1.5, 5), r = 1.5:
        // C = 7.5, EE = 2.25, SS = 27.25, delta = 56.25 - 2.25 (27.25 - 2.25) = 0.
        {"along y, z_E = 1.5", one_sphere_scene(1.5, {0, -1.5, 5}, 1.5, {1, 1, 1}, 2, 0.125), 1, 0, 0, 7.5, 2.25,
         27.25},
        // w = 2, pixel (0, 1): E = (0.5, 0.5, 2); S = 4E + (1, 1, -0.5), the
        // offset perpendicular to E with length 1.5 = r:
        // C = 18, EE = 4.5, SS = 74.25, delta = 324 - 4.5 (74.25 - 2.25) = 0.
        {"off axis", one_sphere_scene(2, {3, 3, 7.5}, 1.5, {4, -1, 2}, 2, 0.375), 2, 0, 1, 18, 4.5, 74.25},
    };
    for (const Tangent& c : cases) {
        INFO(c.what);
        const PixelTrace trace = trace_pixel(c.scene, c.w, c.i, c.j);
        CHECK(scalar(trace, Key::C) == c.C);
        CHECK(scalar(trace, Key::EE) == c.EE);
        CHECK(scalar(trace, Key::SS) == c.SS);
        CHECK(same_bits(scalar(trace, Key::delta), 0.0));
        CHECK(trace.branch == Branch::miss);  // the article: if delta <= 0 then return 1/2
        CHECK(same_bits(trace.result, c.scene.background.x));
        CHECK_FALSE(has_step(trace, Key::t));
        NullRecorder none;
        const PixelResult<double> untraced = trace_pixel_ray(article_world(c.scene), c.w, c.i, c.j, none);
        CHECK(untraced.branch == Branch::miss);
        CHECK(same_bits(untraced.I_P, c.scene.background.x));
    }
}

TEST_CASE("a hit whose N.K is exactly 0 is dark, and I scales a lit one", "[tracer]") {
    // E = (0, 0, 2), S = (0, 0, 4), r = 1: C = 8, EE = 4, SS = 16,
    // delta = 64 - 4 * 15 = 4, t = (8 - 2) / 4 = 1.5, P = (0, 0, 3), N = (0, 0, -1).
    struct Case {
        Vec3d L;
        double I;
        Vec3d K;
        double KK, D;
        Branch branch;
        double result;
    };
    const std::vector<Case> cases = {
        {{2, 1, 3}, 1.5, {2, 1, 0}, 5, 0, Branch::dark, 0},    // K perpendicular to N
        {{-1, 3, 3}, 3, {-1, 3, 0}, 10, 0, Branch::dark, 0},   // likewise
        {{2, 1, 2.5}, 1.5, {2, 1, -0.5}, 5.25, 0.5, Branch::lit, 1.5 * 0.5 / (1 * std::sqrt(5.25))},
        {{0, 0, 1}, 0.75, {0, 0, -2}, 4, 2, Branch::lit, 0.75},  // I D / (r sqrt(KK)) = 0.75 * 2 / 2
        {{0, 0, 1}, 3, {0, 0, -2}, 4, 2, Branch::lit, 3},         // above 1: clamped only when quantised
    };
    for (const Case& c : cases) {
        INFO("L = (" << c.L.x << ", " << c.L.y << ", " << c.L.z << "), I = " << c.I);
        const Scene scene = one_sphere_scene(2, {0, 0, 4}, 1, c.L, c.I, 0.25);
        const PixelTrace trace = trace_pixel(scene, 1, 0, 0);
        CHECK(scalar(trace, Key::delta) == 4);
        CHECK(scalar(trace, Key::t) == 1.5);
        CHECK(tracer_vector(trace, Key::P) == Vec3d{0, 0, 3});
        CHECK(tracer_vector(trace, Key::N) == Vec3d{0, 0, -1});
        CHECK(tracer_vector(trace, Key::K) == c.K);
        CHECK(scalar(trace, Key::KK) == c.KK);
        CHECK(same_bits(scalar(trace, Key::D), c.D));
        CHECK(trace.branch == c.branch);
        CHECK(same_bits(trace.result, c.result));
    }
}

TEST_CASE("the article's three pixels at w = 8 take the three branches", "[tracer]") {
    const Scene scene = article_scene();
    // The program's 11 steps in its order, with the lessons' quantities
    // where the derivation introduces them (Delta after delta, N_P after N, ...).
    const std::vector<std::string> miss_keys = {"E", "EE", "SS", "C", "delta", "Delta"};
    const std::vector<std::string> hit_keys = {"E",  "EE", "SS",    "C",   "delta", "Delta", "sqrt_Delta", "t", "P",
                                               "N",  "N_P", "K",    "KK",  "K_len", "K_P",   "D",          "cos_alpha"};

    const PixelTrace miss = trace_pixel(scene, 8, 0, 0);
    CHECK(miss.branch == Branch::miss);
    CHECK(keys_of(miss) == miss_keys);
    CHECK(miss.result == 0.5);

    const PixelTrace dark = trace_pixel(scene, 8, 5, 1);
    CHECK(dark.branch == Branch::dark);
    CHECK(keys_of(dark) == hit_keys);
    CHECK(dark.result == 0.0);

    const PixelTrace lit = trace_pixel(scene, 8, 3, 4);
    CHECK(lit.branch == Branch::lit);
    CHECK(keys_of(lit) == hit_keys);
    CHECK(lit.result > 0.0);
    CHECK(lit.result <= 1.0);
}

TEST_CASE("pixel (3, 4) at w = 8: the first steps by hand", "[tracer]") {
    const PixelTrace lit = trace_pixel(article_scene(), 8, 3, 4);
    // x_E = 9/8 - 1, y_E = -7/8 + 1: exact in binary.
    CHECK(tracer_vector(lit, Key::E) == Vec3d{0.125, 0.125, 2});
    CHECK(scalar(lit, Key::EE) == 4.03125);  // 1/64 + 1/64 + 4
    CHECK(scalar(lit, Key::SS) == 3.2 * 3.2);
    CHECK(scalar(lit, Key::C) == 2 * 3.2);
}

TEST_CASE("traced and untraced pixels are identical bit for bit", "[tracer]") {
    const Scene scene = article_scene();
    const ArticleWorld<double> world = article_world(scene);
    for (const int w : {1, 5, 64}) {
        std::vector<std::uint8_t> row(static_cast<std::size_t>(w));
        const std::vector<double> literal = promyk_literal::literal_program(w, literal_of(scene));
        for (int i = 0; i < w; ++i) {
            render_row(world, w, i, row.data());
            for (int j = 0; j < w; ++j) {
                NullRecorder none;
                const double untraced = trace_pixel_ray(world, w, i, j, none).I_P;
                const PixelTrace traced = trace_pixel(scene, w, i, j);
                INFO("w = " << w << ", pixel (" << i << ", " << j << ")");
                CHECK(same_bits(untraced, traced.result));
                CHECK(row[static_cast<std::size_t>(j)] == to_byte(traced.result));
                // Beside the engine against itself: the literal program's
                // value, rounded independently.
                const double expected = literal[static_cast<std::size_t>(i * w + j)];
                CHECK(same_bits(traced.result, expected));
                CHECK(row[static_cast<std::size_t>(j)] == independent_byte(expected));
            }
        }
    }
}

TEST_CASE("the engine refuses scenes the article's program cannot trace", "[tracer]") {
    Scene scene = article_scene();
    scene.spheres[0].r = 4;  // |S| = 3.2 < r: the eye inside
    CHECK_THROWS_AS(article_world(scene), InputError);
    scene.spheres[0].r = 3.2;  // the eye on the sphere
    CHECK_THROWS_AS(article_world(scene), InputError);
    scene = article_scene();
    scene.lights.push_back(scene.lights[0]);
    CHECK_THROWS_AS(article_world(scene), InputError);
    scene = article_scene();
    scene.spheres.clear();
    CHECK_THROWS_AS(article_world(scene), InputError);
}

namespace {

struct CollectingSink final : RenderSink {
    std::vector<std::uint8_t> pixels;
    std::string traces;
    int last_progress = 0;
    void image_rows(const std::uint8_t* rows, int count) override {
        pixels.insert(pixels.end(), rows, rows + static_cast<std::size_t>(count) * w);
    }
    void trace_lines(std::string_view lines) override { traces += lines; }
    void progress(int done, int) override { last_progress = done; }
    int w = 0;
};

CollectingSink render_to_memory(int w, int threads, const PixelSelection& traced,
                                const Scene& scene = article_scene()) {
    CollectingSink sink;
    sink.w = w;
    render(scene, {w, threads}, traced, sink);
    return sink;
}

// The literal program's image of the scene, rounded independently.
std::vector<std::uint8_t> literal_image(const Scene& scene, int w) {
    std::vector<std::uint8_t> image;
    for (const double v : promyk_literal::literal_program(w, literal_of(scene))) image.push_back(independent_byte(v));
    return image;
}

}  // namespace

TEST_CASE("render gives the same image and traces whatever the thread count", "[render]") {
    PixelSelection traced;
    traced.add_region({2, 3, 40, 5});
    traced.add_pixel(90, 1);
    traced.add_pixel(0, 0);
    const CollectingSink one = render_to_memory(97, 1, traced);
    REQUIRE(one.pixels.size() == 97u * 97u);
    CHECK(one.last_progress == 97);
    CHECK(one.pixels == literal_image(article_scene(), 97));  // not only the engine against itself
    for (const int threads : {2, 3, 8}) {
        const CollectingSink many = render_to_memory(97, threads, traced);
        CHECK(many.pixels == one.pixels);
        CHECK(many.traces == one.traces);
    }
    // 39 rows x 3 columns of the region, and two single pixels, one line each, row by row.
    std::size_t lines = 0, at = 0, next = 0;
    std::string previous;
    while ((next = one.traces.find('\n', at)) != std::string::npos) {
        ++lines;
        at = next + 1;
    }
    CHECK(lines == 39 * 3 + 2);
    CHECK(one.traces.rfind("{\"schema\":1,", 0) == 0);
    CHECK(one.traces.find("\"pixel\":{\"i\":0,\"j\":0}") < one.traces.find("\"pixel\":{\"i\":2,\"j\":3}"));
    CHECK(one.traces.find("\"pixel\":{\"i\":40,\"j\":5}") < one.traces.find("\"pixel\":{\"i\":90,\"j\":1}"));
}

TEST_CASE("render of scenes that are not the article's equals the literal program, whatever the thread count",
          "[render]") {
    for (const char* file : {"off_axis_far.json", "off_axis_near.json", "tangent_axis.json"}) {
        const Scene scene = load_scene_file(std::string(PROMYK_SOURCE_DIR "/tests/reference/scenes/") + file);
        for (const int w : {3, 61}) {
            const std::vector<std::uint8_t> expected = literal_image(scene, w);
            for (const int threads : {1, 3}) {
                INFO(file << ", w = " << w << ", threads = " << threads);
                CHECK(render_to_memory(w, threads, PixelSelection{}, scene).pixels == expected);
            }
        }
    }
}

TEST_CASE("pixel selections", "[render]") {
    PixelSelection s;
    CHECK(s.empty());
    s.add_pixel(3, 4);
    s.add_pixel(3, 4);
    s.add_region({10, 10, 12, 11});
    CHECK(s.contains(3, 4));
    CHECK_FALSE(s.contains(4, 3));
    CHECK(s.contains(12, 11));
    CHECK_FALSE(s.contains(12, 12));
    CHECK(s.row_has_any(3));
    CHECK(s.row_has_any(11));
    CHECK_FALSE(s.row_has_any(4));
    CHECK(PixelSelection::all().contains(1000, 1000));
}

namespace {

// A sink that fails on its second band, as a full disk would.
struct FailingSink final : RenderSink {
    int bands = 0;
    void image_rows(const std::uint8_t*, int) override {
        if (++bands == 2) throw OutputError("disk full");
    }
};

}  // namespace

TEST_CASE("a sink failure stops the render and reaches the caller, whatever the thread count", "[render]") {
    for (const int threads : {1, 2, 4}) {
        FailingSink sink;
        // w = 2048: bands of 256 rows, so the failure comes while helpers draw the next bands.
        CHECK_THROWS_AS(render(article_scene(), {2048, threads}, PixelSelection{}, sink), OutputError);
        CHECK(sink.bands == 2);
    }
}

namespace {

// A sink that takes its time over every band and notes the progress it is told.
struct SlowSink final : RenderSink {
    int w = 0;
    std::vector<std::uint8_t> pixels;
    std::string traces;
    std::vector<int> progress_seen;
    void image_rows(const std::uint8_t* rows, int count) override {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        pixels.insert(pixels.end(), rows, rows + static_cast<std::size_t>(count) * w);
    }
    void trace_lines(std::string_view lines) override { traces += lines; }
    void progress(int done, int) override { progress_seen.push_back(done); }
};

}  // namespace

TEST_CASE("every band reaches the sink once and in order, however slow the sink and many the threads", "[render]") {
    // w = 2048: 8 bands untraced, and bands of a few rows when tracing, so the
    // ring of band buffers is reused many times while the sink sleeps.
    const int w = 2048;
    PixelSelection traced;
    for (int i = 0; i < w; i += 97) traced.add_pixel(i, (i * 7) % w);
    const std::vector<std::uint8_t> expected = literal_image(article_scene(), w);
    std::string traces_one_thread;
    for (const bool tracing : {false, true})
        for (const int threads : {1, 2, 3, 8}) {
            INFO("threads = " << threads << ", tracing = " << tracing);
            SlowSink sink;
            sink.w = w;
            render(article_scene(), {w, threads}, tracing ? traced : PixelSelection{}, sink);
            CHECK(sink.pixels == expected);
            REQUIRE_FALSE(sink.progress_seen.empty());
            CHECK(sink.progress_seen.back() == w);
            CHECK(std::is_sorted(sink.progress_seen.begin(), sink.progress_seen.end(), std::less_equal<int>()));
            CHECK(std::adjacent_find(sink.progress_seen.begin(), sink.progress_seen.end()) ==
                  sink.progress_seen.end());  // strictly increasing: no band twice
            if (!tracing) continue;
            CHECK(sink.traces.size() > 0);
            if (threads == 1) traces_one_thread = sink.traces;
            else CHECK(sink.traces == traces_one_thread);
        }
}
