// What render() counts, and that a signal stops the work inside a band.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <csignal>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "child_process.hpp"
#include "general_scenes_support.hpp"
#include "geometry/formula.hpp"
#include "image/quantize.hpp"
#include "isa_forced.hpp"
#include "render/general_kernel.hpp"
#include "render/isa.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"

using namespace promyk;

namespace {

struct NullSink final : RenderSink {
    int rows = 0;
    void image_rows(const std::uint8_t*, int count) override { rows += count; }
};

}  // namespace

TEST_CASE("render counts pixels by branch, rays and sphere tests", "[render-stats]") {
    // Counts of the article's program run by hand (Python floats, see
    // tests/reference): w = 8: 32 miss, 10 dark, 22 lit; w = 64: 2380, 342, 1374.
    struct Expected {
        int w;
        long long miss, dark, lit;
    };
    for (const Expected e : {Expected{8, 32, 10, 22}, Expected{64, 2380, 342, 1374}}) {
        for (const int threads : {1, 2}) {
            NullSink sink;
            RenderStats stats;
            render(article_scene(), {e.w, threads}, PixelSelection{}, sink, &stats);
            INFO("w = " << e.w << ", threads = " << threads);
            CHECK(stats.count(Branch::miss) == e.miss);
            CHECK(stats.count(Branch::dark) == e.dark);
            CHECK(stats.count(Branch::lit) == e.lit);
            CHECK(stats.count(Branch::non_finite) == 0);
            CHECK(stats.first_non_finite_i == -1);
            CHECK(stats.primary_rays == static_cast<long long>(e.w) * e.w);
            // Each pixel is tested, or skipped as proven background (only misses are).
            CHECK(stats.sphere_tests + stats.skipped == static_cast<long long>(e.w) * e.w);
            CHECK(stats.skipped > 0);
            CHECK(stats.skipped <= e.miss);
            CHECK(stats.rows_computed == e.w);
            CHECK(sink.rows == e.w);
        }
    }
}

TEST_CASE("render reports the first non-finite pixel in row order", "[render-stats]") {
    Scene scene = article_scene();
    scene.lights.front().I = std::numeric_limits<double>::max();  // I·D overflows where D > 1
    NullSink sink;
    RenderStats stats;
    render(scene, {8, 2}, PixelSelection{}, sink, &stats);
    long long traced_non_finite = 0;
    int first_i = -1, first_j = -1;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            if (trace_pixel(scene, 8, i, j).branch == Branch::non_finite) {
                ++traced_non_finite;
                if (first_i < 0) first_i = i, first_j = j;
            }
    CHECK(stats.count(Branch::non_finite) == traced_non_finite);
    CHECK(traced_non_finite > 0);
    CHECK(stats.count(Branch::lit) + stats.count(Branch::non_finite) == 22);  // the lit pixels of w = 8
    CHECK(stats.count(Branch::miss) == 32);
    CHECK(stats.first_non_finite_i == first_i);
    CHECK(stats.first_non_finite_j == first_j);
}

TEST_CASE("a signal stops the threads inside a band, before its rows are computed", "[render-stats]") {
    // In a child process, since the signal flag stays set: a SIGINT already
    // received when render() starts must stop it before it computes a row of
    // the first band (w = 64 is one band). The child's exit code is the rows
    // computed, or 100 + something for an unexpected outcome.
    const int status = promyk::testing::child_status([] {
        install_interrupt_handlers();
        std::raise(SIGINT);
        NullSink sink;
        RenderStats stats;
        const int code = promyk::testing::interrupted_code(SIGINT, [&] {
            render(article_scene(), {64, 1}, PixelSelection{}, sink, &stats);
        });
        return code == 0 ? static_cast<int>(stats.rows_computed) : code;
    });
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

namespace {

// Two spheres on a floor, two lights: every kind of work and branch.
Scene busy_scene(bool shadows) {
    Scene scene;
    scene.name = "busy";
    scene.shadows = shadows;
    scene.spheres = {Sphere{{-0.5, -0.3, 3.2}, 0.8}, Sphere{{0.8, 0.2, 4.5}, 1.1}};
    scene.planes = {Plane{{0, -1.1, 0}, {0, 1, 0}}};
    scene.lights = {Light{{1.5, 3, 1}, 0.7}, Light{{-3, 1, 2}, 0.4}};
    return scene;
}

}  // namespace

TEST_CASE("render counts shadow rays and tests by shape exactly, as the traces account for them",
          "[render-stats][effects]") {
    for (const bool shadows : {false, true}) {
        const Scene scene = busy_scene(shadows);
        constexpr int w = 24;
        // Expected from the traces: one shadow ray for every light a hit faces
        // (D > 0 in its light group), and every ray tests every object.
        long long faced = 0;
        long long branches[branch_count] = {};
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                const PixelTrace trace = trace_pixel(scene, w, i, j);
                ++branches[static_cast<int>(trace.branch)];
                for (const Step& step : trace.steps)
                    if (step.key == Key::D && step.group >= 0 && trace.groups[step.group].kind == "light" &&
                        std::get<double>(step.value) > 0)
                        ++faced;
            }
        }
        for (const int threads : {1, 2}) {
            NullSink sink;
            RenderStats stats;
            render(scene, {w, threads}, PixelSelection{}, sink, &stats);
            INFO("shadows " << shadows << ", threads " << threads);
            const long long pixels = w * w;
            CHECK(stats.primary_rays == pixels);
            CHECK(stats.shadow_rays == (shadows ? faced : 0));
            CHECK(stats.sphere_tests == (stats.primary_rays + stats.shadow_rays) * 2);
            CHECK(stats.plane_tests == (stats.primary_rays + stats.shadow_rays) * 1);
            for (int b = 0; b < branch_count; ++b) CHECK(stats.branches[b] == branches[b]);
        }
        CHECK(faced > 200);
        CHECK(branches[static_cast<int>(Branch::shadowed)] > (shadows ? 10 : -1));
        if (!shadows) CHECK(branches[static_cast<int>(Branch::shadowed)] == 0);
        CHECK(branches[static_cast<int>(Branch::miss)] > 0);
        CHECK(branches[static_cast<int>(Branch::dark)] > 0);
    }
}

namespace {

struct BytesSink final : RenderSink {
    std::vector<std::uint8_t> bytes;
    void image_rows(const std::uint8_t* rows, int count) override {
        bytes.insert(bytes.end(), rows, rows + static_cast<std::ptrdiff_t>(count) * w);
    }
    explicit BytesSink(int w_) : w(w_) {}
    int w;
};

}  // namespace

// render without --stats draws the article's rows, and its sampled rows in
// double and in float, without counting each pixel's branch
// (RenderSettings::count_branches): the image must not change, and the
// non-finite pixels (render's warning) are still counted, the first one
// found, on every instruction-set path this processor has (a sampled
// pixel uncounted is non-finite when its mean is).
TEST_CASE("render without branch counting: the same image, the non-finite pixels still counted", "[render-stats][isa]") {
    Scene overflowing = article_scene();
    overflowing.lights.front().I = std::numeric_limits<double>::max();  // I·D overflows where D > 1
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const Scene& scene : {article_scene(), overflowing})
            for (const RealType real : {RealType::double_, RealType::float_})
                for (const int spp : {1, 4, 9})
                    for (const Formula formula : {Formula::article, Formula::stable, Formula::geometric})
                        for (const int w : {8, 61, 200}) {
                            // float at spp 1 draws its rows counting (only double's skip it)
                            const bool uncounted_path = real == RealType::double_ || spp > 1;
                            INFO(isa_name(isa) << ", I = " << scene.lights.front().I << ", "
                                               << (real == RealType::double_ ? "double" : "float") << ", spp "
                                               << spp << ", " << formula_name(formula) << ", w = " << w);
                            RenderSettings counted{w, 1, real, formula, spp, true};
                            RenderSettings uncounted = counted;
                            uncounted.count_branches = false;
                            BytesSink with(w), without(w);
                            RenderStats with_stats, without_stats;
                            render(scene, counted, PixelSelection{}, with, &with_stats);
                            render(scene, uncounted, PixelSelection{}, without, &without_stats);
                            REQUIRE(with.bytes.size() == static_cast<std::size_t>(w) * w);
                            CHECK(with.bytes == without.bytes);
                            CHECK(without_stats.count(Branch::non_finite) == with_stats.count(Branch::non_finite));
                            CHECK(without_stats.first_non_finite_i == with_stats.first_non_finite_i);
                            CHECK(without_stats.first_non_finite_j == with_stats.first_non_finite_j);
                            // Only what was asked: no lit or dark pixel counted.
                            if (uncounted_path) {
                                CHECK(without_stats.count(Branch::lit) == 0);
                                CHECK(without_stats.count(Branch::dark) == 0);
                                CHECK(without_stats.disagreeing == 0);
                            }
                            CHECK(with_stats.count(Branch::lit) + with_stats.count(Branch::non_finite) > 0);
                            if (scene.lights.front().I > 1) CHECK(with_stats.count(Branch::non_finite) > 0);
                            if (spp > 1 && w == 200) CHECK(with_stats.disagreeing > 0);
                        }
    }
}

// The same for the general tracer's rows, of one sample a pixel and of
// several (every example scene, and hostile ones whose deltas, shadow tests
// and intensities overflow, in grey and in colour; one sphere and one light
// of every kind, their own rows, hostile too): without --stats only the
// non-finite pixels are counted, and the image is the same.
TEST_CASE("render without branch counting: the general tracer's rows and samples", "[render-stats][isa]") {
    struct ImageSink final : RenderSink {
        std::vector<std::uint8_t> bytes;
        std::size_t row_bytes;
        explicit ImageSink(std::size_t n) : row_bytes(n) {}
        void image_rows(const std::uint8_t* rows, int count) override {
            bytes.insert(bytes.end(), rows, rows + static_cast<std::ptrdiff_t>(row_bytes) * count);
        }
    };
    std::vector<general_scenes_support::NamedScene> scenes = general_scenes_support::example_scenes();
    for (general_scenes_support::NamedScene& named : general_scenes_support::hostile_scenes(12))
        scenes.push_back(std::move(named));
    const std::size_t one_sphere_from = scenes.size();
    for (general_scenes_support::NamedScene& named : general_scenes_support::one_sphere_scenes(12))
        scenes.push_back(std::move(named));
    long long non_finite = 0, one_sphere_non_finite = 0;
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const general_scenes_support::NamedScene& named : scenes)
            for (const int spp : {1, 4, 9}) {
                const int w = named.panes.front();
                INFO(isa_name(isa) << ", " << named.name << ", spp " << spp << ", w = " << w);
                const RenderSettings counted{w, 1, RealType::double_, Formula::article, spp, true};
                RenderSettings uncounted = counted;
                uncounted.count_branches = false;
                const std::size_t row_bytes = static_cast<std::size_t>(w) * image_channels(named.scene);
                ImageSink with(row_bytes), without(row_bytes);
                RenderStats with_stats, without_stats;
                render(named.scene, counted, PixelSelection{}, with, &with_stats);
                render(named.scene, uncounted, PixelSelection{}, without, &without_stats);
                REQUIRE(with.bytes.size() == row_bytes * w);
                CHECK(with.bytes == without.bytes);
                CHECK(without_stats.count(Branch::non_finite) == with_stats.count(Branch::non_finite));
                CHECK(without_stats.first_non_finite_i == with_stats.first_non_finite_i);
                CHECK(without_stats.first_non_finite_j == with_stats.first_non_finite_j);
                CHECK(without_stats.count(Branch::lit) == 0);
                CHECK(without_stats.count(Branch::dark) == 0);
                CHECK(without_stats.count(Branch::shadowed) == 0);
                CHECK(without_stats.disagreeing == 0);
                non_finite += with_stats.count(Branch::non_finite);
                if (&named - scenes.data() >= static_cast<std::ptrdiff_t>(one_sphere_from))
                    one_sphere_non_finite += with_stats.count(Branch::non_finite);
            }
    }
    CHECK(non_finite > 0);             // the hostile scenes have some
    CHECK(one_sphere_non_finite > 0);  // and the hostile ones of one sphere
}

// The general tracer's sampled rows without --stats store one row-wide
// conversion for a vector of pixels whose samples all drew the background
// (render/sample_lanes.hpp's BackgroundSum), found by comparing sums. Any
// background: the same image and the same non-finite pixels as the counted
// rows (which convert each pixel), its zeros, sums that round, one that
// overflows, and infinite and NaN ones (a hand-made scene's), in grey and
// in colour, one object or several, panes of a power of two (whole grids)
// and not, on every instruction-set path this processor has. A corner
// pixel, all of whose samples miss, is the mean sample_pixel gives it.
TEST_CASE("render without branch counting: the general tracer's samples that all miss, any background",
          "[render-stats][isa][sample_lanes]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Colour> backgrounds;
    for (const double b : {0.5, 0.0, -0.0, 1.0, 0.1, 1.0 / 3, 4.9e-324, 0.999999, -0.25, 7.0, 1e308, inf, nan})
        backgrounds.push_back({b, b, b});
    backgrounds.push_back({0.5, 0.0, 1.0});
    backgrounds.push_back({-0.0, 0.1, 1e308});
    Scene one = article_scene();
    Scene busy = busy_scene(true);
    long long non_finite = 0, corners = 0;
    for (const Isa isa : supported_isas()) {
        PathForced forced(isa);
        for (const Colour& background : backgrounds)
            for (Scene* scene : {&one, &busy})
                for (const int spp : {4, 9, 16})
                    for (const int w : {32, 19}) {
                        scene->background = background;
                        const std::unique_ptr<Kernel> kernel =
                            make_general_kernel(*scene, RealType::double_, Formula::article, spp);
                        const int channels = image_channels(*scene);
                        INFO(isa_name(isa)
                             << ", " << (scene == &one ? "one sphere" : "busy") << ", background " << background.x
                             << " " << background.y << " " << background.z << ", spp " << spp << ", w = " << w);
                        const RenderSettings settings{w, 1, RealType::double_, Formula::article, spp, true};
                        BytesSink with(w * channels), without(w * channels);  // a row's bytes
                        RenderStats with_stats, without_stats;
                        kernel->set_branch_counting(true);
                        render(*kernel, *scene, settings, PixelSelection{}, with, &with_stats);
                        kernel->set_branch_counting(false);
                        render(*kernel, *scene, settings, PixelSelection{}, without, &without_stats);
                        REQUIRE(with.bytes.size() == static_cast<std::size_t>(w) * w * channels);
                        CHECK(with.bytes == without.bytes);
                        CHECK(without_stats.count(Branch::non_finite) == with_stats.count(Branch::non_finite));
                        CHECK(without_stats.first_non_finite_i == with_stats.first_non_finite_i);
                        CHECK(without_stats.first_non_finite_j == with_stats.first_non_finite_j);
                        non_finite += with_stats.count(Branch::non_finite);
                        if (scene != &one) continue;
                        // The top left pixel: every sample misses the sphere.
                        const double channel[3] = {background.x, background.y, background.z};
                        for (int c = 0; c < channels; ++c) {
                            double sum = -0.0;
                            for (int s = 0; s < spp; ++s) sum += channel[c];
                            CHECK(without.bytes[static_cast<std::size_t>(c)] == to_byte(sum / spp));
                        }
                        ++corners;
                    }
    }
    CHECK(non_finite > 0);  // the infinite, NaN and overflowing backgrounds
    CHECK(corners > 0);
}
