// Samples per pixel (--spp): the pattern (render/samples.hpp) and the pixel
// as the mean of its samples, against the article's program run literally
// at each sample's point (tests/article_literal.hpp), never against itself.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <vector>

#include "article_literal.hpp"
#include "render/kernel.hpp"
#include "image/quantize.hpp"
#include "render/renderer.hpp"
#include "render/samples.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "lesson/lesson_check.hpp"
#include "trace/vocabulary.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

// The hash written out independently (Python: tests/reference/README.md,
// "samples"), pinned so that every build, and a JavaScript port, agree.
struct Pinned {
    int i, j, s;
    std::uint32_t hash;
};

std::vector<Scene> sample_example_scenes() {
    std::vector<Scene> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes"))
        if (entry.path().extension() == ".json" && entry.path().string().find(".schema.") == std::string::npos)
            scenes.push_back(load_scene_file(entry.path().string()));
    return scenes;
}

struct SampleRowsSink final : RenderSink {
    std::vector<std::uint8_t> pixels;
    void image_rows(const std::uint8_t* rows, int count) override {
        (void)count;
        pixels.insert(pixels.end(), rows, rows + static_cast<std::ptrdiff_t>(count) * row_bytes);
    }
    int row_bytes = 0;
};

}  // namespace

TEST_CASE("a number of samples is a square from 1 to 1024", "[samples]") {
    for (int n = 1; n <= 32; ++n) CHECK(valid_spp(n * n));
    for (const int spp : {0, -1, -4, 2, 3, 5, 8, 15, 17, 63, 65, 1023, 1025, 33 * 33}) CHECK_FALSE(valid_spp(spp));
    CHECK(spp_side(1) == 1);
    CHECK(spp_side(64) == 8);
    CHECK(spp_side(1024) == 32);
    CHECK_THROWS_AS(make_kernel(article_scene(), RealType::double_, Formula::article, 2), UsageError);
    CHECK_THROWS_AS(make_kernel(article_scene(), RealType::double_, Formula::article, 0), UsageError);
}

TEST_CASE("the sample hash is pinned: every build gives the same samples", "[samples]") {
    // lowbias32(i·0x9e3779b1 ^ lowbias32(j·0x85ebca6b ^ lowbias32(s + 0x632be5ab))),
    // computed in Python with arbitrary-precision integers masked to 32 bits.
    for (const Pinned p : {Pinned{0, 0, 0, 0x8a06eb4aU}, Pinned{3, 4, 1, 0x3e56cfb5U}, Pinned{511, 7, 63, 0xb3b17501U},
                           Pinned{100000, 99999, 1023, 0x56bb9573U}}) {
        INFO("(" << p.i << ", " << p.j << ", " << p.s << ")");
        CHECK(sample_hash(p.i, p.j, p.s) == p.hash);
    }
    // Pixel (3, 4) with 4 samples, as exact fractions of 2^17 (the same script).
    const double u[4] = {-54813.0 / 131072, 53173.0 / 131072, -40261.0 / 131072, 14397.0 / 65536};
    const double v[4] = {-46593.0 / 131072, -24789.0 / 65536, 21967.0 / 131072, 643.0 / 131072};
    for (int s = 0; s < 4; ++s) {
        CHECK(sample_offset(3, 4, s, 4).u == u[s]);
        CHECK(sample_offset(3, 4, s, 4).v == v[s]);
    }
    CHECK(centre_sample(3, 4, 4) == 3);  // (0.2197, 0.0049) is the nearest the centre
}

TEST_CASE("one sample is the pixel's centre, more put one sample in each cell of an n × n grid", "[samples]") {
    for (const int i : {0, 3, 7, 1000}) {
        for (const int j : {0, 5, 999}) {
            CHECK(sample_offset(i, j, 0, 1).u == 0.0);
            CHECK(sample_offset(i, j, 0, 1).v == 0.0);
            CHECK(centre_sample(i, j, 1) == 0);
            for (const int spp : {4, 9, 16, 64, 1024}) {
                const int n = spp_side(spp);
                std::vector<int> cells(static_cast<std::size_t>(spp), 0);
                int nearest = 0;
                for (int s = 0; s < spp; ++s) {
                    const SampleOffset o = sample_offset(i, j, s, spp);
                    INFO("pixel (" << i << ", " << j << "), spp " << spp << ", sample " << s);
                    REQUIRE(o.u >= -0.5);
                    REQUIRE(o.u < 0.5);
                    REQUIRE(o.v >= -0.5);
                    REQUIRE(o.v < 0.5);
                    // Its cell: column s mod n, row s div n.
                    CHECK(static_cast<int>(std::floor((o.u + 0.5) * n)) == s % n);
                    CHECK(static_cast<int>(std::floor((o.v + 0.5) * n)) == s / n);
                    ++cells[static_cast<std::size_t>(s)];
                    const SampleOffset best = sample_offset(i, j, nearest, spp);
                    if (o.u * o.u + o.v * o.v < best.u * best.u + best.v * best.v) nearest = s;
                }
                CHECK(centre_sample(i, j, spp) == nearest);
            }
        }
    }
    // Jitter varies from pixel to pixel (not one pattern repeated).
    CHECK(sample_offset(0, 0, 0, 4).u != sample_offset(0, 1, 0, 4).u);
    CHECK(sample_offset(0, 0, 0, 4).u != sample_offset(1, 0, 0, 4).u);
}

TEST_CASE("with samples, a pixel is the mean of the article's program at each sample's point", "[samples]") {
    const promyk_literal::LiteralScene literal;
    for (const int w : {8, 64}) {
        for (const int spp : {4, 9, 16}) {
            const auto kernel = make_kernel(article_scene(), RealType::double_, Formula::article, spp);
            for (int i = 0; i < w; i += w / 8) {
                for (int j = 0; j < w; ++j) {
                    double sum = 0;
                    promyk_literal::LiteralReturn centre_return{};
                    const int centre = centre_sample(i, j, spp);
                    for (int s = 0; s < spp; ++s) {
                        const SampleOffset o = sample_offset(i, j, s, spp);
                        // The article's x_E = (2j + 1)/w - 1 with j + 1/2 + u for j + 1/2.
                        const double x_E = (2.0 * j + 1.0 + 2.0 * o.u) / w - 1.0;
                        const double y_E = -(2.0 * i + 1.0 + 2.0 * o.v) / w + 1.0;
                        promyk_literal::LiteralLocals locals;
                        sum += promyk_literal::literal_intensity(x_E, y_E, literal.z_E, literal, &locals);
                        if (s == centre) centre_return = locals.returned;
                    }
                    Branch branch;
                    const double got = kernel->intensity(w, i, j, &branch).x;
                    INFO("w " << w << ", spp " << spp << ", pixel (" << i << ", " << j << ")");
                    CHECK(got == sum / spp);
                    const Branch expected = centre_return == promyk_literal::LiteralReturn::half   ? Branch::miss
                                            : centre_return == promyk_literal::LiteralReturn::zero ? Branch::dark
                                                                                                    : Branch::lit;
                    CHECK(branch == expected);
                }
            }
        }
    }
}

TEST_CASE("spp 1 is the article's image, bit for bit", "[samples]") {
    const auto one = make_kernel(article_scene(), RealType::double_, Formula::article, 1);
    const auto plain = make_kernel(article_scene());
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j) CHECK(one->intensity(32, i, j).x == plain->intensity(32, i, j).x);
}

TEST_CASE("a traced pixel with samples equals the rendered one, on every example scene", "[samples]") {
    for (const Scene& scene : sample_example_scenes()) {
        for (const RealType real : {RealType::double_, RealType::float_}) {
            const int w = 8, spp = 4;
            const auto kernel = make_kernel(scene, real, Formula::article, spp);
            // The image as the renderer writes it (both threads).
            SampleRowsSink sink;
            sink.row_bytes = w * kernel->channels();
            RenderSettings settings{w, 2, real, Formula::article, spp};
            RenderStats stats;
            render(scene, settings, PixelSelection{}, sink, &stats);
            REQUIRE(sink.pixels.size() == static_cast<std::size_t>(w * w * kernel->channels()));
            long long disagreeing = 0;
            for (int i = 0; i < w; ++i) {
                for (int j = 0; j < w; ++j) {
                    const PixelTrace trace = trace_pixel(scene, w, i, j, real, Formula::article, spp);
                    Branch branch;
                    const Vec3d untraced = kernel->intensity(w, i, j, &branch);
                    INFO("scene " << scene.name << ", real " << real_type_name(real) << ", pixel (" << i << ", " << j
                                  << ")");
                    CHECK(trace.header.spp == spp);
                    CHECK(trace.branch == branch);
                    CHECK(trace.result == untraced.x);
                    if (trace.result_rgb) CHECK(*trace.result_rgb == untraced);
                    const std::size_t at = static_cast<std::size_t>((i * w + j) * kernel->channels());
                    CHECK(sink.pixels[at] == to_byte(untraced.x));
                    // One group per sample, in order, each closed by its I_s.
                    REQUIRE(trace.samples);
                    int groups = 0, intensities = 0;
                    for (const TraceGroup& group : trace.groups) {
                        if (group.kind != "sample") continue;
                        CHECK(group.index == groups);
                        CHECK(group.parent == -1);
                        ++groups;
                    }
                    CHECK(groups == spp);
                    for (const Step& step : trace.steps) intensities += step.key == Key::I_s;
                    CHECK(intensities == spp);
                    REQUIRE(!trace.steps.empty());
                    CHECK(trace.steps.back().key == Key::I_mean);
                    CHECK(trace.steps.back().group == -1);
                    CHECK(trace.samples->centre == centre_sample(i, j, spp));
                    int total = 0;
                    for (const int n : trace.samples->branches) total += n;
                    CHECK(total == spp);
                    disagreeing += !trace.samples->agree();
                }
            }
            CHECK(stats.primary_rays == static_cast<long long>(w) * w * spp);
            CHECK(stats.disagreeing == disagreeing);
            long long pixels = 0;
            for (const long long n : stats.branches) pixels += n;
            CHECK(pixels == static_cast<long long>(w) * w);
        }
    }
}

TEST_CASE("an edge pixel's samples disagree and its branch is the centre sample's", "[samples]") {
    // Pixel (1, 4) of the article at w = 8 straddles the sphere's top edge.
    const PixelTrace trace = trace_pixel(article_scene(), 8, 1, 4, RealType::double_, Formula::article, 16);
    REQUIRE(trace.samples);
    CHECK_FALSE(trace.samples->agree());
    const int hits = trace.samples->branches[static_cast<int>(Branch::lit)] +
                     trace.samples->branches[static_cast<int>(Branch::dark)];
    const int misses = trace.samples->branches[static_cast<int>(Branch::miss)];
    CHECK(hits > 0);
    CHECK(misses > 0);
    // The centre sample's own trace, run alone as the article's ray through its point.
    const SampleOffset o = sample_offset(1, 4, trace.samples->centre, 16);
    promyk_literal::LiteralLocals locals;
    const promyk_literal::LiteralScene literal;
    promyk_literal::literal_intensity((2.0 * 4 + 1.0 + 2.0 * o.u) / 8 - 1.0, -(2.0 * 1 + 1.0 + 2.0 * o.v) / 8 + 1.0,
                                      literal.z_E, literal, &locals);
    CHECK(trace.branch == (locals.returned == promyk_literal::LiteralReturn::half ? Branch::miss
                           : locals.returned == promyk_literal::LiteralReturn::zero ? Branch::dark
                                                                                    : Branch::lit));
}

TEST_CASE("a sample's steps are named by their path for diff and answer files", "[samples]") {
    const Vocabulary& vocabulary = builtin_vocabulary();
    CHECK(check_path("sample[3].delta", vocabulary).fault == PathFault::none);
    CHECK(check_path("sample[0].I_s", vocabulary).fault == PathFault::none);
    CHECK(check_path("sample[2].sphere[1].t", vocabulary).fault == PathFault::none);
    CHECK(check_path("sample[2].light[0].sphere[1].delta_s", vocabulary).fault == PathFault::none);
    // A sample holds no sample, and stands only first.
    CHECK(check_path("sample[0].sample[1].t", vocabulary).fault != PathFault::none);
    CHECK(check_path("sphere[0].sample[1].t", vocabulary).fault != PathFault::none);
}

TEST_CASE("a pixel's digits lost with samples is the most any step of any sample loses", "[samples]") {
    for (const Scene& scene : sample_example_scenes()) {
        for (const Formula formula : {Formula::article, Formula::geometric}) {
            const auto kernel = make_kernel(scene, RealType::float_, formula, 4);
            for (int i = 0; i < 6; ++i) {
                for (int j = 0; j < 6; ++j) {
                    const PixelTrace trace = trace_pixel(scene, 6, i, j, RealType::float_, formula, 4);
                    double most = 0;
                    for (const Step& step : trace.steps)
                        if (step.digits_lost > most) most = step.digits_lost;  // NaN: no estimate
                    INFO("scene " << scene.name << ", pixel (" << i << ", " << j << ")");
                    CHECK(kernel->digits_lost(6, i, j) == most);
                }
            }
        }
    }
}
