// promyk render, run as a user runs it, writes an image whose decoded 8-bit
// values are the article's program's intensities, rounded as README says:
// round(clamp(v, 0, 1) * 255). The rounding here is std::lround, independent
// of the engine's own conversion.
#include <catch2/catch.hpp>

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

std::vector<unsigned char> expected_grey(int w) {
    std::vector<unsigned char> grey;
    for (const double v : promyk_literal::literal_program(w))
        grey.push_back(static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255)));
    return grey;
}

std::vector<unsigned char> decode_png(const fs::path& path, int w) {
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

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("promyk-e2e-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

int run(const std::string& arguments) {
    return std::system((std::string(PROMYK_BINARY) + " " + arguments + " > /dev/null").c_str());
}

}  // namespace

TEST_CASE("promyk render writes the article's image: PNG at the default size", "[end-to-end]") {
    const fs::path dir = fresh_dir("png");
    REQUIRE(run("render -o " + (dir / "article.png").string()) == 0);
    CHECK(decode_png(dir / "article.png", 512) == expected_grey(512));
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
    CHECK(decode_png(png, 37) == expected_grey(37));
    fs::remove_all(dir);
}
