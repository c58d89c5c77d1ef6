// render --map: the branch atlas and the error map. The expected colours are
// the README's legend written out here, and the expected categories come
// from the article's literal program (tests/article_literal.hpp), exact
// constructions, or the plain kernels, never from the map code itself.
#include <catch2/catch.hpp>

#include <png.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "article_literal.hpp"
#include "collect_rows.hpp"
#include "render/kernel.hpp"
#include "render/maps.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "temp_dir.hpp"
#include "trace/number_text.hpp"

using namespace promyk;

namespace {

// The README's legend.
const Rgb8 legend_miss{0x56, 0xB4, 0xE9};      // sky blue
const Rgb8 legend_dark{0x00, 0x00, 0x00};      // black
const Rgb8 legend_lit{0xE6, 0x9F, 0x00};       // orange
const Rgb8 legend_tangent{0xF0, 0xE4, 0x42};   // yellow
const Rgb8 legend_behind{0x00, 0x9E, 0x73};    // bluish green
const Rgb8 legend_exact{0xFF, 0xFF, 0xFF};     // white
const Rgb8 legend_differs{0xD5, 0x5E, 0x00};   // vermillion

struct Image {
    int w = 0;
    std::vector<std::uint8_t> rgb;
    Rgb8 at(int i, int j) const {
        const std::size_t k = 3 * (static_cast<std::size_t>(i) * w + j);
        return {rgb[k], rgb[k + 1], rgb[k + 2]};
    }
};

using promyk::testing::Collect;

// The map rendered as `promyk render --map` renders it (two threads); a
// deferred map (the error map's own range) settled and its rows replayed.
Image map_of(MapKind kind, const Scene& scene, int w, RealType real = RealType::double_,
             Formula formula = Formula::article, int spp = 1, MapTally* tally = nullptr,
             std::optional<std::pair<double, double>> range = std::nullopt, ColourScale* scale_used = nullptr) {
    const std::unique_ptr<MapKernel> map = make_map_kernel(kind, scene, real, formula, spp, w, range);
    REQUIRE(map->channels() == 3);
    Collect sink;
    sink.row_bytes = static_cast<std::size_t>(w) * 3;
    render(*map, scene, {w, 2}, PixelSelection{}, sink);
    if (map->deferred()) {
        map->settle();
        sink.bytes.assign(sink.bytes.size(), 0);
        for (int i = 0; i < w; ++i) map->replay_row(w, i, sink.bytes.data() + static_cast<std::size_t>(i) * sink.row_bytes);
    }
    if (tally) *tally = map->tally();
    if (scale_used && map->colour_scale()) *scale_used = *map->colour_scale();
    return {w, sink.bytes};
}

std::string hex(Rgb8 c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02X%02X%02X", c.r, c.g, c.b);
    return text;
}

Scene sphere_scene(Vec3d S, double r) {
    Scene scene = article_scene();
    scene.spheres.front().S = S;
    scene.spheres.front().r = r;
    return scene;
}

const MapTally::Category& category(const MapTally& tally, const std::string& name) {
    for (const MapTally::Category& c : tally.categories)
        if (c.name == name) return c;
    FAIL("no category " << name);
    throw;
}

}  // namespace

TEST_CASE("the branch map of the article's scene is the literal program's branches in the legend's colours",
          "[maps]") {
    for (const int w : {8, 64}) {
        MapTally tally;
        const Image image = map_of(MapKind::branch, article_scene(), w, RealType::double_, Formula::article, 1, &tally);
        std::vector<promyk_literal::LiteralLocals> locals;
        promyk_literal::literal_program(w, {}, &locals);
        long long counts[3] = {};
        int first_dark_i = -1, first_dark_j = -1;
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                const auto returned = locals[static_cast<std::size_t>(i * w + j)].returned;
                const Rgb8 expected = returned == promyk_literal::LiteralReturn::half   ? legend_miss
                                      : returned == promyk_literal::LiteralReturn::zero ? legend_dark
                                                                                        : legend_lit;
                ++counts[static_cast<int>(returned)];
                if (returned == promyk_literal::LiteralReturn::zero && first_dark_i < 0) first_dark_i = i, first_dark_j = j;
                INFO("w = " << w << ", pixel (" << i << ", " << j << ")");
                CHECK(hex(image.at(i, j)) == hex(expected));
            }
        }
        if (w == 8) {
            CHECK(counts[0] == 32);
            CHECK(counts[1] == 10);
            CHECK(counts[2] == 22);
        }
        CHECK(category(tally, "miss").count == counts[0]);
        CHECK(category(tally, "miss").first_i == 0);
        CHECK(category(tally, "miss").first_j == 0);
        CHECK(category(tally, "dark").count == counts[1]);
        CHECK(category(tally, "dark").first_i == first_dark_i);
        CHECK(category(tally, "dark").first_j == first_dark_j);
        CHECK(category(tally, "lit").count == counts[2]);
        CHECK(category(tally, "tangent").count == 0);
        CHECK(category(tally, "behind the eye").count == 0);
    }
}

TEST_CASE("a sphere behind the eye is mapped where the literal program would draw it", "[maps]") {
    // The article's scene with S = (0, 0, -3.2): the program never checks
    // t > 0, so it draws the sphere where the line meets it behind the eye.
    const int w = 16;
    promyk_literal::LiteralScene literal;
    literal.z_S = -3.2;
    std::vector<promyk_literal::LiteralLocals> locals;
    promyk_literal::literal_program(w, literal, &locals);
    const Scene scene = sphere_scene({0, 0, -3.2}, 1.1);
    for (const Formula formula : {Formula::article, Formula::stable, Formula::fma, Formula::geometric}) {
        const Image image = map_of(MapKind::branch, scene, w, RealType::double_, formula);
        int behind_pixels = 0;
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                const bool drawn = locals[static_cast<std::size_t>(i * w + j)].returned !=
                                   promyk_literal::LiteralReturn::half;
                behind_pixels += drawn;
                INFO("formula " << formula_name(formula) << ", pixel (" << i << ", " << j << ")");
                CHECK(hex(image.at(i, j)) == hex(drawn ? legend_behind : legend_miss));
            }
        }
        CHECK(behind_pixels > 20);
    }
}

TEST_CASE("a tangent ray gets the tangent colour in every type and formula", "[maps]") {
    // w = 1: the one pixel's ray is the axis, E = (0, 0, 2). S = (r, 0, z)
    // lies at distance exactly r from it. With r = 1, z = 10 every quantity
    // is exact (delta = 0, delta_g = 0); with r = 0.1, z = 3.3
    // (tests/data/hard_cases.json, tangent_axis_tenth) the ray is tangent to
    // the sphere of the rounded inputs only within rounding: the computed
    // discriminant is a residue of the roundings of r^2 and |S|^2.
    struct Case {
        Vec3d S;
        double r;
    };
    for (const Case c : {Case{{1, 0, 10}, 1}, Case{{0.1, 0, 3.3}, 0.1}}) {
        const Scene scene = sphere_scene(c.S, c.r);
        for (const RealType real : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_}) {
            for (const Formula formula : {Formula::article, Formula::stable, Formula::fma, Formula::geometric}) {
                INFO("r = " << c.r << ", " << real_type_name(real) << ", " << formula_name(formula));
                CHECK(hex(map_of(MapKind::branch, scene, 1, real, formula).at(0, 0)) == hex(legend_tangent));
            }
        }
    }
    // Moved off by a thousandth of r, the same ray is no longer tangent.
    const Scene off = sphere_scene({1.001, 0, 10}, 1);
    CHECK(hex(map_of(MapKind::branch, off, 1).at(0, 0)) == hex(legend_miss));
    const Scene in = sphere_scene({0.999, 0, 10}, 1);
    CHECK(hex(map_of(MapKind::branch, in, 1).at(0, 0)) != hex(legend_tangent));
}

TEST_CASE("the error map of the reference against itself is exact everywhere", "[maps]") {
    for (const Scene& scene : {article_scene(), sphere_scene({0, 0, 1e4}, 1)}) {
        const int w = 16;
        MapTally tally;
        const Image image = map_of(MapKind::error, scene, w, RealType::quad_, Formula::geometric, 1, &tally);
        for (int i = 0; i < w; ++i)
            for (int j = 0; j < w; ++j) CHECK(hex(image.at(i, j)) == hex(legend_exact));
        CHECK(category(tally, "exact").count == w * w);
        CHECK(!tally.has_largest);
    }
}

TEST_CASE("the error map marks the pixels whose branch differs from the reference's", "[maps]") {
    // tests/data/hard_cases.json, far_1e4: a unit sphere at distance 10^4 on
    // the axis. The axis ray hits it; float with the article's formula
    // loses delta to cancellation and misses; double keeps it.
    const Scene far = sphere_scene({0, 0, 1e4}, 1);
    MapTally tally;
    CHECK(hex(map_of(MapKind::error, far, 1, RealType::float_, Formula::article, 1, &tally).at(0, 0)) == hex(legend_differs));
    CHECK(category(tally, "branch differs").count == 1);
    CHECK(category(tally, "branch differs").first_i == 0);
    const Rgb8 in_double = map_of(MapKind::error, far, 1, RealType::double_, Formula::article).at(0, 0);
    CHECK(hex(in_double) != hex(legend_differs));

    // The same sphere seen through a pane at z_E = 10^4, where it fills the
    // inscribed disc: delta = |E|^2 (1 - x^2 - y^2) is at most 10^8 against
    // C^2 = 10^16, whose float ulp is 2^30. The marked pixels are exactly
    // those where the plain kernels' branches differ, and there are many.
    const int w = 64;
    Scene wide = far;
    wide.z_E = 1e4;
    const Image image = map_of(MapKind::error, wide, w, RealType::float_, Formula::article);
    const auto computed = make_kernel(wide, RealType::float_, Formula::article);
    const auto reference = make_kernel(wide, RealType::quad_, Formula::geometric);
    int marked = 0;
    for (int i = 0; i < w; ++i) {
        for (int j = 0; j < w; ++j) {
            Branch a, b;
            computed->intensity(w, i, j, &a);
            reference->intensity(w, i, j, &b);
            marked += a != b;
            INFO("pixel (" << i << ", " << j << ")");
            CHECK((hex(image.at(i, j)) == hex(legend_differs)) == (a != b));
        }
    }
    CHECK(marked > w * w / 10);
}

TEST_CASE("the error map's scale runs from its low end to its high end on viridis, log10", "[maps]") {
    const ColourScale scale = fallback_error_scale();
    CHECK(scale.low() == 1e-20);
    CHECK(scale.high() == 1);
    CHECK(hex(scale(1e-20)) == "#440154");
    CHECK(hex(scale(1e-30)) == "#440154");
    CHECK(hex(scale(1)) == "#FDE725");
    CHECK(hex(scale(5)) == "#FDE725");
    CHECK(hex(scale(1e-10)) == "#21918C");  // the middle stop
    // double against quad on the article's scene: errors of a few ulps, in
    // the scale's lower third, and no branch differs.
    MapTally tally;
    map_of(MapKind::error, article_scene(), 32, RealType::double_, Formula::article, 1, &tally);
    REQUIRE(tally.has_largest);
    CHECK(tally.largest > 0);
    CHECK(tally.largest < 1e-14);
    CHECK(category(tally, "branch differs").count == 0);
}

TEST_CASE("a run's error range is widened to whole decades around its errors", "[maps]") {
    struct Case {
        double smallest, largest, low, high;
    };
    for (const Case& c : {Case{3e-17, 4e-16, 1e-17, 1e-15}, Case{1e-17, 1e-16, 1e-17, 1e-16},
                          Case{2e-9, 2e-9, 1e-9, 1e-8}, Case{1e-16, 1e-16, 1e-16, 1e-15},
                          Case{9.99e-8, 1.01e-5, 1e-8, 1e-4}, Case{5e-324, 0.5, 5e-324, 1}}) {
        CAPTURE(c.smallest, c.largest);
        const ColourScale scale = error_scale_of_run(c.smallest, c.largest);
        CHECK(scale.low() == c.low);
        CHECK(scale.high() == c.high);
        CHECK(scale.low() <= c.smallest);
        CHECK(scale.high() >= c.largest);
        CHECK(scale.logarithmic());
    }
}

TEST_CASE("a float map and a double map of the article's scene each use many colours of the ramp", "[maps]") {
    // With the fixed 1e-20 ... 1 scale each was nearly one flat colour: a
    // float's errors all near 1e-8, a double's near 1e-16. Viridis grows
    // lighter from end to end, so the spread of luminance tells how much of
    // the ramp a map uses.
    auto spread = [](const Image& image) {
        int darkest = 255, lightest = 0;
        for (int k = 0; k < image.w * image.w; ++k) {
            const Rgb8 c = image.at(k / image.w, k % image.w);
            if (c == legend_exact) continue;
            const int l = (54 * c.r + 183 * c.g + 19 * c.b + 128) >> 8;
            darkest = std::min(darkest, l), lightest = std::max(lightest, l);
        }
        return lightest - darkest;
    };
    const int w = 64;
    for (const RealType real : {RealType::float_, RealType::double_}) {
        const std::string type(real_type_name(real));
        CAPTURE(type);
        ColourScale scale(0, 1, false);
        MapTally tally;
        const Image image = map_of(MapKind::error, article_scene(), w, real, Formula::article, 1, &tally,
                                   std::nullopt, &scale);
        std::set<std::string> colours;
        for (int i = 0; i < w; ++i)
            for (int j = 0; j < w; ++j)
                if (image.at(i, j) != legend_exact) colours.insert(hex(image.at(i, j)));
        CHECK(colours.size() >= 40);
        CHECK(spread(image) >= 120);
        // The run's range holds its errors; its largest reaches the top decade.
        REQUIRE(tally.has_largest);
        CHECK(scale.high() >= tally.largest);
        CHECK(scale.high() / 10 < tally.largest);
        // (the range's words as the run's language writes them: U+2212 in the exponent)
        CHECK(category(tally, "below " + local_number_text(fmt::format("{:g}", scale.low()), Language::en)).count == 0);
        // The fixed scale, for contrast: a narrow band of the ramp.
        const Image fixed = map_of(MapKind::error, article_scene(), w, real, Formula::article, 1, nullptr,
                                   std::make_pair(1e-20, 1.0));
        CHECK(spread(fixed) < 80);
    }
}

TEST_CASE("with --range two runs' error maps give the same colour to the same error", "[maps]") {
    // The errors computed here from the plain kernels, not from the map.
    const std::pair<double, double> range{1e-18, 1e-6};
    const ColourScale scale = error_scale(range.first, range.second);
    const int w = 24;
    std::set<std::string> seen;
    for (const RealType real : {RealType::float_, RealType::double_, RealType::long_double}) {
        const std::string type(real_type_name(real));
        CAPTURE(type);
        ColourScale used(0, 1, false);
        const Image image =
            map_of(MapKind::error, article_scene(), w, real, Formula::article, 1, nullptr, range, &used);
        CHECK(used.low() == range.first);
        CHECK(used.high() == range.second);
        const auto computed = make_kernel(article_scene(), real, Formula::article);
        const auto reference = make_kernel(article_scene(), RealType::quad_, Formula::geometric);
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                Branch a, b;
                const Vec3<quad> I = computed->exact_intensity(w, i, j, &a);
                const Vec3<quad> I_ref = reference->exact_intensity(w, i, j, &b);
                REQUIRE(a == b);
                const double error = static_cast<double>(fabsq(I.x - I_ref.x));
                INFO("pixel (" << i << ", " << j << ") error " << error);
                // Outside the range an error is drawn at the nearest end.
                const Rgb8 expected = error == 0 ? legend_exact : scale(std::clamp(error, range.first, range.second));
                CHECK(hex(image.at(i, j)) == hex(expected));
                if (error != 0) seen.insert(hex(expected));
            }
        }
    }
    CHECK(seen.size() >= 20);
}

namespace {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
};

RgbImage read_map_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()) != 0);
    CHECK((image.format & PNG_FORMAT_FLAG_COLOR) != 0);
    image.format = PNG_FORMAT_RGB;
    RgbImage rgb{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    rgb.pixels.resize(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, rgb.pixels.data(), 0, nullptr) != 0);
    return rgb;
}

}  // namespace

TEST_CASE("promyk render --map branch writes the atlas as an RGB PNG", "[maps][cli]") {
    promyk::testing::TempDir dir("promyk-maps");
    const std::string out = dir.file("m.png");
    REQUIRE(std::system((std::string(PROMYK_BINARY) + " render --map branch --w 8 --scale 3 -o " + out +
                         " 2> /dev/null")
                            .c_str()) == 0);
    const RgbImage image = read_map_png(out);
    REQUIRE(image.width == 24);
    REQUIRE(image.height == 24);
    std::vector<promyk_literal::LiteralLocals> locals;
    promyk_literal::literal_program(8, {}, &locals);
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 24; ++x) {
            const auto returned = locals[static_cast<std::size_t>((y / 3) * 8 + x / 3)].returned;
            const Rgb8 expected = returned == promyk_literal::LiteralReturn::half   ? legend_miss
                                  : returned == promyk_literal::LiteralReturn::zero ? legend_dark
                                                                                    : legend_lit;
            const std::size_t k = 3 * (static_cast<std::size_t>(y) * 24 + x);
            INFO("image pixel (" << y << ", " << x << ")");
            CHECK(hex({image.pixels[k], image.pixels[k + 1], image.pixels[k + 2]}) == hex(expected));
        }
    }
}

TEST_CASE("the digits-lost map colours each pixel by the most digits its trace loses", "[maps]") {
    // The lesson's far sphere in float with the article's formula: C² and
    // |E|²(|S|² − r²) round to the same float, so delta cancels completely
    // in every pixel: all of float's 24·log10(2) = 7.22 digits.
    const Scene far = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/far_sphere.json");
    MapTally tally;
    const Image lost = map_of(MapKind::digits_lost, far, 8, RealType::float_, Formula::article, 1, &tally);
    const double float_digits = 24 * std::log10(2.0);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) CHECK(hex(lost.at(i, j)) == hex(ColourScale::ramp(float_digits / 8)));
    CHECK(category(tally, "7 to 8").count == 64);
    CHECK(tally.largest == Approx(float_digits).epsilon(1e-12));
    // The article's scene in double: each pixel as its trace says (the
    // largest digits_lost of its steps), white where no step cancels.
    const int w = 16;
    const Image image = map_of(MapKind::digits_lost, article_scene(), w, RealType::double_, Formula::article, 1, &tally);
    const ColourScale scale = digits_lost_scale(RealType::double_);
    CHECK(scale.high() == 16);
    long long total = 0;
    for (const MapTally::Category& c : tally.categories) total += c.count;
    CHECK(total == w * w);
    for (int i = 0; i < w; ++i) {
        for (int j = 0; j < w; ++j) {
            double most = 0;
            for (const Step& step : trace_pixel(article_scene(), w, i, j).steps)
                if (step.digits_lost > most) most = step.digits_lost;
            INFO("pixel (" << i << ", " << j << "): " << most);
            CHECK(hex(image.at(i, j)) == hex(most > 0 ? scale(most) : none_lost_colour().rgb));
        }
    }
}

namespace {
// This process's resident memory in bytes, from /proc/self/statm.
long long resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    long long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * static_cast<long long>(sysconf(_SC_PAGESIZE));
}
}  // namespace

TEST_CASE("A deferred error map touches no memory before its rows are computed", "[maps][interrupt]") {
    // w 4096 keeps 128 MB of values; zero-filling them up front took most of
    // a second in which SIGINT went unseen (hostile run). Each pixel is
    // written by its row, so making the map must not make those pages resident.
    const int w = 4096;
    const long long before = resident_bytes();
    REQUIRE(before > 0);
    const std::unique_ptr<MapKernel> map =
        make_map_kernel(MapKind::error, article_scene(), RealType::double_, Formula::article, 1, w);
    REQUIRE(map->deferred());
    const long long grown = resident_bytes() - before;
    INFO("resident memory grew by " << grown << " bytes");
    CHECK(grown < 32LL * 1024 * 1024);
}
