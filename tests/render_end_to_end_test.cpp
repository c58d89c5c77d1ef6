// promyk render, run as a user runs it, writes an image whose decoded 8-bit
// values are the article's program's intensities, rounded as README says:
// round(clamp(v, 0, 1) * 255). The rounding here is std::lround, independent
// of the engine's own conversion.
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <png.h>

#include "article_literal.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<unsigned char> expected_grey(int w, const promyk_literal::LiteralScene& scene = {}) {
    std::vector<unsigned char> grey;
    for (const double v : promyk_literal::literal_program(w, scene))
        grey.push_back(static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255)));
    return grey;
}

std::vector<unsigned char> decode_grey_png(const fs::path& path, int w) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()) != 0);
    CHECK(image.width == static_cast<png_uint_32>(w));
    CHECK(image.height == static_cast<png_uint_32>(w));
    image.format = PNG_FORMAT_GRAY;
    std::vector<unsigned char> grey(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, grey.data(), 0, nullptr) != 0);
    return grey;
}

std::vector<unsigned char> decode_pgm(const fs::path& path, int w) {
    std::ifstream file(path, std::ios::binary);
    std::string magic;
    int width = 0, height = 0, maxval = 0;
    file >> magic >> width >> height >> maxval;
    file.get();  // the single white space after maxval
    CHECK(magic == "P5");
    CHECK(width == w);
    CHECK(height == w);
    CHECK(maxval == 255);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// A fresh directory of a unique name (mkdtemp): two test runs at once never
// share one. The caller removes it at the end of the test.
fs::path fresh_dir(const std::string& name) {
    std::string path = (fs::temp_directory_path() / ("promyk-e2e-" + name + "-XXXXXX")).string();
    REQUIRE(::mkdtemp(path.data()) != nullptr);
    return path;
}

int run(const std::string& arguments) {
    return std::system((std::string(PROMYK_BINARY) + " " + arguments + " > /dev/null").c_str());
}

}  // namespace

TEST_CASE("promyk render writes the article's image: PNG at the default size", "[end-to-end]") {
    const fs::path dir = fresh_dir("png");
    REQUIRE(run("render -o " + (dir / "article.png").string()) == 0);
    CHECK(decode_grey_png(dir / "article.png", 512) == expected_grey(512));
    fs::remove_all(dir);
}

TEST_CASE("promyk render writes the article's image: odd sizes, PGM, any thread count", "[end-to-end]") {
    const fs::path dir = fresh_dir("pgm");
    for (const int w : {1, 37}) {
        for (const int threads : {1, 3}) {
            const fs::path out = dir / ("w" + std::to_string(w) + "t" + std::to_string(threads) + ".pgm");
            REQUIRE(run("render --w " + std::to_string(w) + " --threads " + std::to_string(threads) + " -o " +
                        out.string()) == 0);
            INFO("w = " << w << ", threads = " << threads);
            CHECK(decode_pgm(out, w) == expected_grey(w));
        }
    }
    const fs::path png = dir / "w37.png";
    REQUIRE(run("render --w 37 -o " + png.string()) == 0);
    CHECK(decode_grey_png(png, 37) == expected_grey(37));
    fs::remove_all(dir);
}

TEST_CASE("promyk render --scene writes a scene that is not the article's as the literal program computes it",
          "[end-to-end]") {
    // tests/reference/scenes/off_axis_far.json and tangent_axis.json, their
    // numbers written out here by hand: off-axis S, I = 3 (clamped to 255),
    // background 0.2; a tangent ray through the centre of w = 3 (background 0.625).
    promyk_literal::LiteralScene far;
    far.z_E = 3;
    far.x_S = 0.45, far.y_S = -0.35, far.z_S = 4.2;
    far.r = 1.3;
    far.x_L = -2.5, far.y_L = 2, far.z_L = 4.5;
    far.I = 3;
    far.background = 0.2;
    promyk_literal::LiteralScene tangent;
    tangent.z_E = 2;
    tangent.x_S = 1, tangent.y_S = 0, tangent.z_S = 4;
    tangent.r = 1;
    tangent.x_L = -1, tangent.y_L = 0.5, tangent.z_L = 1;
    tangent.I = 0.75;
    tangent.background = 0.625;

    const fs::path dir = fresh_dir("scenes");
    const std::string scenes = std::string(PROMYK_SOURCE_DIR) + "/tests/reference/scenes/";
    for (const int threads : {1, 2}) {
        INFO("threads = " << threads);
        const fs::path out = dir / ("far" + std::to_string(threads) + ".pgm");
        REQUIRE(run("render --scene " + scenes + "off_axis_far.json --w 45 --threads " + std::to_string(threads) +
                    " -o " + out.string()) == 0);
        CHECK(decode_pgm(out, 45) == expected_grey(45, far));
    }
    const fs::path out = dir / "tangent.png";
    REQUIRE(run("render --scene " + scenes + "tangent_axis.json --w 3 -o " + out.string()) == 0);
    const std::vector<unsigned char> grey = decode_grey_png(out, 3);
    CHECK(grey == expected_grey(3, tangent));
    CHECK(static_cast<int>(grey.at(4)) == 159);  // the tangent centre: round(0.625 * 255) = round(159.375)
    fs::remove_all(dir);
}
