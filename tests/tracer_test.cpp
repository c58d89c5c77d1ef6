#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "render/quantize.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "trace/recorder.hpp"
#include "util/errors.hpp"

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

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("the article's three pixels at w = 8 take the three branches", "[tracer]") {
    const Scene scene = article_scene();
    const std::vector<std::string> miss_keys = {"E", "EE", "SS", "C", "delta"};
    const std::vector<std::string> hit_keys = {"E", "EE", "SS", "C", "delta", "t", "P", "N", "K", "KK", "D"};

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
    CHECK(std::get<Vec3d>(lit.steps[0].value) == Vec3d{0.125, 0.125, 2});
    CHECK(std::get<double>(lit.steps[1].value) == 4.03125);  // 1/64 + 1/64 + 4
    CHECK(std::get<double>(lit.steps[2].value) == 3.2 * 3.2);
    CHECK(std::get<double>(lit.steps[3].value) == 2 * 3.2);
}

TEST_CASE("traced and untraced pixels are identical bit for bit", "[tracer]") {
    const Scene scene = article_scene();
    const ArticleWorld<double> world = article_world(scene);
    for (const int w : {1, 5, 64}) {
        std::vector<std::uint8_t> row(static_cast<std::size_t>(w));
        for (int i = 0; i < w; ++i) {
            render_row(world, w, i, row.data());
            for (int j = 0; j < w; ++j) {
                NullRecorder none;
                const double untraced = trace_pixel_ray(world, w, i, j, none).I_P;
                const PixelTrace traced = trace_pixel(scene, w, i, j);
                INFO("w = " << w << ", pixel (" << i << ", " << j << ")");
                CHECK(same_bits(untraced, traced.result));
                CHECK(row[static_cast<std::size_t>(j)] == to_byte(traced.result));
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

CollectingSink render_to_memory(int w, int threads, const PixelSelection& traced) {
    CollectingSink sink;
    sink.w = w;
    render(article_scene(), {w, threads}, traced, sink);
    return sink;
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
        // w = 2048: bands of 512 rows, so the failure comes while helpers compute the next band.
        CHECK_THROWS_AS(render(article_scene(), {2048, threads}, PixelSelection{}, sink), OutputError);
        CHECK(sink.bands == 2);
    }
}
