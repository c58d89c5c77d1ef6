// Image output: PNG, PGM and PPM files read back byte for byte, grey and RGB,
// and the promise that a file is written completely or not at all.
#include <png.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "image/canvas.hpp"
#include "image/grid_contrast.hpp"
#include "image/image_writer.hpp"
#include "util/atomic_file.hpp"
#include "util/errors.hpp"
#include "temp_dir.hpp"
#include "util/output_file.hpp"

namespace fs = std::filesystem;
using namespace promyk;

namespace {

using testing::TempDir;

// A gradient that differs in both directions and wraps through all 256 levels.
std::vector<std::uint8_t> gradient(int width, int height) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            pixels[static_cast<std::size_t>(y * width + x)] = static_cast<std::uint8_t>(x * 7 + y * 31 + x * y);
        }
    }
    return pixels;
}

// Writes the image in bands of 1, 2, 3, ... rows, as a render would.
void write_image(ImageWriter& writer, const std::vector<std::uint8_t>& pixels) {
    const int width = writer.width();
    int band = 1;
    for (int y = 0; y < writer.height(); y += band, ++band) {
        const int count = std::min(band, writer.height() - y);
        writer.write_rows(pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width), count);
    }
}

using testing::read_bytes;
using testing::write_bytes;

struct Grey {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

// Reads a PNG back with libpng's simplified API, which a different code path
// from the writer's.
Grey read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()) != 0);
    CHECK((image.format & (PNG_FORMAT_FLAG_COLOR | PNG_FORMAT_FLAG_ALPHA | PNG_FORMAT_FLAG_LINEAR)) == 0);
    image.format = PNG_FORMAT_GRAY;
    Grey grey{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    grey.pixels.resize(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, grey.pixels.data(), 0, nullptr) != 0);
    return grey;
}

// Parses a binary PGM: "P5", width, height, maxval, one whitespace, pixels.
Grey read_pgm(const std::string& path) {
    std::istringstream in(read_bytes(path));
    std::string magic;
    int maxval = 0;
    Grey grey;
    in >> magic >> grey.width >> grey.height >> maxval;
    REQUIRE(magic == "P5");
    REQUIRE(maxval == 255);
    REQUIRE(in.get() == '\n');
    const std::string rest(std::istreambuf_iterator<char>(in), {});
    grey.pixels.assign(rest.begin(), rest.end());
    return grey;
}

Grey read_image(const std::string& path) {
    return image_format_for_path(path) == ImageFormat::png ? read_png(path) : read_pgm(path);
}

mode_t current_umask() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mask;
}

}  // namespace

TEST_CASE("image format follows the extension, in any case", "[image]") {
    CHECK(image_format_for_path("a.png") == ImageFormat::png);
    CHECK(image_format_for_path("out/A.PNG") == ImageFormat::png);
    CHECK(image_format_for_path("x.Pgm") == ImageFormat::pgm);
    CHECK(image_format_for_path("dir.png/x.pgm") == ImageFormat::pgm);
    CHECK(image_format_for_path("x.ppm") == ImageFormat::ppm);
    CHECK(image_format_for_path("out/X.PPM") == ImageFormat::ppm);
    CHECK(image_format_for_path("x.pPm") == ImageFormat::ppm);
    CHECK(image_format_for_path("a.ppm/b.png") == ImageFormat::png);
    CHECK_THROWS_AS(image_format_for_path("x.pnm"), UsageError);
    CHECK_THROWS_AS(image_format_for_path("x.pbm"), UsageError);
    CHECK_THROWS_AS(image_format_for_path("x.ppm.bak"), UsageError);
    CHECK_THROWS_AS(image_format_for_path("dir.png/x"), UsageError);
    CHECK_THROWS_AS(image_format_for_path("x.png.bak"), UsageError);
    CHECK_THROWS_AS(image_format_for_path("png"), UsageError);
    CHECK_THROWS_AS(image_format_for_path(""), UsageError);
    CHECK_THROWS_WITH(image_format_for_path("x.jpg"), "unsupported image extension 'x.jpg': use .png, .pgm or .ppm");
}

TEST_CASE("an unsupported extension creates no file", "[image]") {
    TempDir dir;
    CHECK_THROWS_AS(open_image_writer(dir.file("x.jpg"), 4, 4), UsageError);
    CHECK(dir.entries().empty());
}

TEST_CASE("PNG and PGM read back byte for byte", "[image]") {
    const auto extension = GENERATE(std::string(".png"), std::string(".pgm"), std::string(".PNG"));
    const auto size = GENERATE(std::make_pair(1, 1), std::make_pair(1, 7), std::make_pair(9, 1), std::make_pair(3, 5),
                               std::make_pair(17, 13), std::make_pair(256, 3));
    const int width = size.first;
    const int height = size.second;
    CAPTURE(extension, width, height);
    TempDir dir;
    const std::string path = dir.file("image" + extension);
    const auto pixels = gradient(width, height);

    auto writer = open_image_writer(path, width, height);
    write_image(*writer, pixels);
    CHECK(writer->rows_written() == height);
    writer->commit();
    writer.reset();

    CHECK(dir.entries() == std::set<std::string>{"image" + extension});
    const Grey grey = read_image(path);
    CHECK(grey.width == width);
    CHECK(grey.height == height);
    CHECK(grey.pixels == pixels);
}

TEST_CASE("the PNG is 8-bit greyscale and .pgm is binary PGM (P5)", "[image]") {
    TempDir dir;
    const auto pixels = gradient(5, 2);
    for (const std::string name : {"g.png", "g.pgm"}) {
        auto writer = open_image_writer(dir.file(name), 5, 2);
        writer->write_rows(pixels.data(), 2);
        writer->commit();
    }
    const std::string png = read_bytes(dir.file("g.png"));
    REQUIRE(png.size() > 26);
    CHECK(png.compare(12, 4, "IHDR") == 0);
    CHECK(int(png[24]) == 8);  // bit depth
    CHECK(int(png[25]) == 0);  // colour type: greyscale
    CHECK(int(png[28]) == 0);  // not interlaced
    CHECK(read_bytes(dir.file("g.pgm")) == "P5\n5 2\n255\n" + std::string(pixels.begin(), pixels.end()));
}

TEST_CASE("the finished file gets the usual mode, not mkstemp's 0600", "[image]") {
    TempDir dir;
    const std::string path = dir.file("m.pgm");
    auto writer = open_image_writer(path, 1, 1);
    const std::uint8_t pixel = 0;
    writer->write_rows(&pixel, 1);
    writer->commit();
    CHECK((fs::status(path).permissions() & fs::perms::all) == static_cast<fs::perms>(0666 & ~current_umask()));
}

TEST_CASE("a writer destroyed without commit leaves nothing", "[image]") {
    const std::string name = GENERATE(std::string("a.png"), std::string("a.pgm"));
    TempDir dir;
    const auto pixels = gradient(8, 8);
    {
        auto writer = open_image_writer(dir.file(name), 8, 8);
        writer->write_rows(pixels.data(), 4);
        // The temporary sits beside the final file, hidden, while writing.
        const auto entries = dir.entries();
        REQUIRE(entries.size() == 1);
        CHECK(entries.begin()->rfind("." + name + ".promyk-", 0) == 0);
    }
    CHECK(dir.entries().empty());
}

TEST_CASE("commit before the last row throws and leaves nothing", "[image]") {
    const std::string name = GENERATE(std::string("a.png"), std::string("a.pgm"));
    TempDir dir;
    const auto pixels = gradient(4, 3);
    {
        auto writer = open_image_writer(dir.file(name), 4, 3);
        writer->write_rows(pixels.data(), 2);
        CHECK_THROWS_AS(writer->commit(), std::logic_error);
        CHECK_THROWS_AS(writer->write_rows(pixels.data(), 2), std::logic_error);  // 4 rows > 3
    }
    CHECK(dir.entries().empty());
}

TEST_CASE("an existing file is replaced only on commit", "[image]") {
    const std::string name = GENERATE(std::string("old.png"), std::string("old.pgm"));
    TempDir dir;
    const std::string path = dir.file(name);
    write_bytes(path, "old content");
    const auto pixels = gradient(6, 4);

    {  // abandoned: the old file stays
        auto writer = open_image_writer(path, 6, 4);
        writer->write_rows(pixels.data(), 4);
    }
    CHECK(read_bytes(path) == "old content");

    auto writer = open_image_writer(path, 6, 4);
    writer->write_rows(pixels.data(), 4);
    CHECK(read_bytes(path) == "old content");
    writer->commit();
    CHECK(read_image(path).pixels == pixels);
    CHECK(dir.entries() == std::set<std::string>{name});
}

TEST_CASE("a file that cannot be created throws OutputError and leaves nothing", "[image]") {
    const std::string name = GENERATE(std::string("x.png"), std::string("x.pgm"));
    TempDir dir;
    write_bytes(dir.file("regular"), "");

    SECTION("the directory does not exist") {
        const std::string path = dir.file("missing/" + name);
        CHECK_THROWS_MATCHES(open_image_writer(path, 2, 2), OutputError,
                             Catch::Message("cannot write " + path + ": No such file or directory"));
    }
    SECTION("the directory is a regular file") {
        const std::string path = dir.file("regular/" + name);
        CHECK_THROWS_MATCHES(open_image_writer(path, 2, 2), OutputError,
                             Catch::Message("cannot write " + path + ": Not a directory"));
    }
    SECTION("a directory where files cannot be created, even by root") {
        CHECK_THROWS_AS(open_image_writer("/proc/promyk-test-" + name, 2, 2), OutputError);
        CHECK_FALSE(fs::exists("/proc/promyk-test-" + name));
    }
    CHECK(dir.entries() == std::set<std::string>{"regular"});
}

TEST_CASE("a directory as the output is refused before any file is created", "[image]") {
    const std::string name = GENERATE(std::string("d.png"), std::string("d.pgm"));
    TempDir dir;
    const std::string path = dir.file(name);
    fs::create_directory(path);  // the final path is a directory
    CHECK_THROWS_MATCHES(open_image_writer(path, 3, 3), OutputError,
                         Catch::Message("cannot write " + path + ": Is a directory"));
    CHECK(dir.entries() == std::set<std::string>{name});
    CHECK(fs::is_empty(path));
}

TEST_CASE("a rename that fails throws OutputError and removes the temporary", "[image]") {
    TempDir dir;
    const std::string path = dir.file("d.txt");
    {
        AtomicFile file(path);
        file.write("text");
        fs::create_directory(path);  // the final path became a directory meanwhile
        CHECK_THROWS_MATCHES(file.commit(), OutputError, Catch::Message("cannot write " + path + ": Is a directory"));
    }
    CHECK(dir.entries() == std::set<std::string>{"d.txt"});
    CHECK(fs::is_empty(path));
}

TEST_CASE("a write that fails midway throws OutputError and leaves nothing", "[image]") {
    // A file-size limit makes every write past it fail with EFBIG, as a full
    // disk would; SIGXFSZ is ignored so the failure is an error, not a kill.
    const std::string name = GENERATE(std::string("big.png"), std::string("big.pgm"));
    TempDir dir;
    const std::string path = dir.file(name);
    const int side = 1024;
    std::vector<std::uint8_t> noise(static_cast<std::size_t>(side) * side);
    std::uint32_t state = 12345;  // incompressible, so the PNG is large too
    for (auto& byte : noise) {
        state = state * 1664525u + 1013904223u;
        byte = static_cast<std::uint8_t>(state >> 24);
    }

    rlimit old_limit{};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &old_limit) == 0);
    const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = old_limit;
    limit.rlim_cur = 64 * 1024;
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &limit) == 0);
    // Nothing is reported while the limit holds: Catch's own output could hit it.
    std::string message;
    bool output_error = false;
    try {
        auto writer = open_image_writer(path, side, side);
        for (int y = 0; y < side; y += 64) writer->write_rows(noise.data() + static_cast<std::size_t>(y) * side, 64);
        writer->commit();
    } catch (const OutputError& error) {
        output_error = true;
        message = error.what();
    } catch (const std::exception& error) {
        message = error.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &old_limit);
    ::signal(SIGXFSZ, old_handler);

    CHECK(output_error);
    CHECK(message == "cannot write " + path + ": File too large");
    CHECK(dir.entries().empty());
}

TEST_CASE("AtomicFile writes, moves and commits", "[image]") {
    TempDir dir;
    const std::string path = dir.file("text.txt");
    AtomicFile first(path);
    first.write("hello, ");
    std::fputs("world", first.stream());
    const std::string temporary = first.temporary_path();
    CHECK(fs::path(temporary).parent_path() == dir.path);

    AtomicFile second(std::move(first));
    CHECK(first.temporary_path().empty());  // NOLINT(bugprone-use-after-move)
    CHECK(second.temporary_path() == temporary);
    second.commit();
    CHECK(read_bytes(path) == "hello, world");
    CHECK_FALSE(fs::exists(temporary));
    CHECK_THROWS_AS(second.commit(), std::logic_error);
    CHECK_THROWS_AS(second.write("x"), std::logic_error);
}

TEST_CASE("AtomicFile move assignment discards the file it replaces", "[image]") {
    TempDir dir;
    AtomicFile a(dir.file("a"));
    AtomicFile b(dir.file("b"));
    CHECK(dir.entries().size() == 2);
    a = std::move(b);
    CHECK(dir.entries().size() == 1);
    a.commit();
    CHECK(dir.entries() == std::set<std::string>{"b"});
}

namespace {

// Parses a plain PGM (P2): whitespace-separated numbers after the magic.
Grey read_plain_pgm(const std::string& text) {
    std::istringstream in(text);
    std::string magic;
    int maxval = 0;
    Grey grey;
    in >> magic >> grey.width >> grey.height >> maxval;
    REQUIRE(magic == "P2");
    REQUIRE(maxval == 255);
    int value = 0;
    while (in >> value) {
        REQUIRE(value >= 0);
        REQUIRE(value <= 255);
        grey.pixels.push_back(static_cast<std::uint8_t>(value));
    }
    return grey;
}

}  // namespace

TEST_CASE("plain PGM is P2 text with lines of at most 70 characters", "[image]") {
    const auto size = GENERATE(std::make_pair(1, 1), std::make_pair(3, 2), std::make_pair(17, 13),
                               std::make_pair(100, 3));
    CAPTURE(size.first, size.second);
    TempDir dir;
    const std::string path = dir.file("plain.pgm");
    auto pixels = gradient(size.first, size.second);
    pixels[0] = 255;  // the widest number
    {
        OutputFile file(path);
        auto writer = open_image_writer(file, ImageFormat::pgm_plain, size.first, size.second);
        write_image(*writer, pixels);
        writer->finish();
        file.commit();
    }
    const std::string text = read_bytes(path);
    CHECK(text.rfind(fmt::format("P2\n{} {}\n255\n", size.first, size.second), 0) == 0);
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) CHECK(line.size() <= 70);
    const Grey grey = read_plain_pgm(text);
    CHECK(grey.width == size.first);
    CHECK(grey.height == size.second);
    CHECK(grey.pixels == pixels);
}

TEST_CASE("plain PGM: each image row starts a line", "[image]") {
    TempDir dir;
    const std::string path = dir.file("p.pgm");
    const std::vector<std::uint8_t> pixels = {0, 128, 255, 7, 8, 9};
    OutputFile file(path);
    auto writer = open_image_writer(file, ImageFormat::pgm_plain, 3, 2);
    writer->write_rows(pixels.data(), 2);
    writer->finish();
    file.commit();
    CHECK(read_bytes(path) == "P2\n3 2\n255\n0 128 255\n7 8 9\n");
}

TEST_CASE("a scaled writer draws each pixel as a block, with grid lines between", "[image]") {
    const bool grid = GENERATE(false, true);
    const int scale = GENERATE(1, 2, 3);
    CAPTURE(grid, scale);
    TempDir dir;
    const std::string path = dir.file("s.pgm");
    const int w = 3;
    const auto pixels = gradient(w, w);
    const int side = static_cast<int>(scaled_side(w, scale, grid));
    CHECK(side == w * scale + (grid ? w - 1 : 0));
    {
        OutputFile file(path);
        auto writer = scale_image_writer(open_image_writer(file, ImageFormat::pgm, side, side), w, scale, grid);
        CHECK(writer->width() == w);
        write_image(*writer, pixels);
        writer->finish();
        file.commit();
    }
    const Grey grey = read_pgm(path);
    REQUIRE(grey.width == side);
    REQUIRE(grey.height == side);
    const int step = scale + (grid ? 1 : 0);
    auto block = [&](int i, int j) { return int(pixels[static_cast<std::size_t>(i * w + j)]); };
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const bool line_y = grid && y % step == scale, line_x = grid && x % step == scale;
            const int i = y / step, j = x / step;
            // A line pixel is the grey that stands out most from its neighbours.
            const int expected = line_y && line_x ? contrasting_grey({block(i, j), block(i, j + 1), block(i + 1, j),
                                                                      block(i + 1, j + 1)})
                                 : line_y         ? contrasting_grey({block(i, j), block(i + 1, j)})
                                 : line_x         ? contrasting_grey({block(i, j), block(i, j + 1)})
                                                  : block(i, j);
            CAPTURE(x, y);
            REQUIRE(int(grey.pixels[static_cast<std::size_t>(y * side + x)]) == expected);
        }
    }
}

TEST_CASE("a scaled writer refuses an inner image of the wrong size", "[image]") {
    TempDir dir;
    OutputFile file(dir.file("s.pgm"));
    CHECK_THROWS_AS(scale_image_writer(open_image_writer(file, ImageFormat::pgm, 8, 8), 3, 3, false),
                    std::invalid_argument);
}

// ---- RGB images ----

namespace {

// An RGB gradient, r, g, b a pixel, whose channels differ from one another.
std::vector<std::uint8_t> rgb_gradient(int width, int height) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const auto p = static_cast<std::size_t>(y * width + x) * 3;
            pixels[p] = static_cast<std::uint8_t>(x * 7 + y * 31 + x * y);
            pixels[p + 1] = static_cast<std::uint8_t>(255 - x * 11 - y * 3);
            pixels[p + 2] = static_cast<std::uint8_t>(x * y * 5 + 100);
        }
    }
    return pixels;
}

// Writes an RGB image in bands of 1, 2, 3, ... rows.
void write_rgb_image(ImageWriter& writer, const std::vector<std::uint8_t>& pixels) {
    int band = 1;
    for (int y = 0; y < writer.height(); y += band, ++band) {
        const int count = std::min(band, writer.height() - y);
        writer.write_rows(pixels.data() + static_cast<std::size_t>(y) * writer.row_bytes(), count);
    }
}

// Reads an RGB PNG back with libpng's simplified API; the file must be RGB
// (colour, no alpha, 8 bits).
Grey read_rgb_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()) != 0);
    CHECK(image.format == PNG_FORMAT_RGB);
    image.format = PNG_FORMAT_RGB;
    Grey rgb{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    rgb.pixels.resize(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, rgb.pixels.data(), 0, nullptr) != 0);
    return rgb;
}

// Parses a binary PPM: "P6", width, height, maxval, one whitespace, samples.
Grey read_ppm(const std::string& path) {
    std::istringstream in(read_bytes(path));
    std::string magic;
    int maxval = 0;
    Grey rgb;
    in >> magic >> rgb.width >> rgb.height >> maxval;
    REQUIRE(magic == "P6");
    REQUIRE(maxval == 255);
    REQUIRE(in.get() == '\n');
    const std::string rest(std::istreambuf_iterator<char>(in), {});
    rgb.pixels.assign(rest.begin(), rest.end());
    return rgb;
}

// Parses a plain PPM (P3): whitespace-separated numbers after the magic.
Grey read_plain_ppm(const std::string& text) {
    std::istringstream in(text);
    std::string magic;
    int maxval = 0;
    Grey rgb;
    in >> magic >> rgb.width >> rgb.height >> maxval;
    REQUIRE(magic == "P3");
    REQUIRE(maxval == 255);
    int value = 0;
    while (in >> value) {
        REQUIRE(value >= 0);
        REQUIRE(value <= 255);
        rgb.pixels.push_back(static_cast<std::uint8_t>(value));
    }
    REQUIRE(in.eof());  // nothing but numbers
    return rgb;
}

std::string as_string(const std::vector<std::uint8_t>& bytes) { return std::string(bytes.begin(), bytes.end()); }

}  // namespace

TEST_CASE("a writer has the channels it was opened with", "[image][rgb]") {
    TempDir dir;
    OutputFile file(dir.file("c.ppm"));
    CHECK(open_image_writer(file, ImageFormat::ppm, 4, 2)->channels() == 1);
    CHECK(open_image_writer(file, ImageFormat::png, 4, 2, 1)->channels() == 1);
    auto rgb = open_image_writer(file, ImageFormat::png, 4, 2, 3);
    CHECK(rgb->channels() == 3);
    CHECK(rgb->row_bytes() == 12);
    CHECK(open_image_writer(file, ImageFormat::ppm, 4, 2, 3)->row_bytes() == 12);
    CHECK_THROWS_AS(open_png_writer(file, 4, 2, 2), std::invalid_argument);
    CHECK_THROWS_AS(open_ppm_writer(file, 4, 2, false, 4), std::invalid_argument);
    CHECK_THROWS_AS(check_image_format(ImageFormat::png, 0, "x.png"), std::invalid_argument);
}

TEST_CASE("RGB PNG and PPM read back byte for byte", "[image][rgb]") {
    const auto extension = GENERATE(std::string(".png"), std::string(".ppm"), std::string(".PPM"));
    const auto size = GENERATE(std::make_pair(1, 1), std::make_pair(1, 7), std::make_pair(9, 1), std::make_pair(17, 13),
                               std::make_pair(256, 3));
    const int width = size.first;
    const int height = size.second;
    CAPTURE(extension, width, height);
    TempDir dir;
    const std::string path = dir.file("image" + extension);
    const auto pixels = rgb_gradient(width, height);

    auto writer = open_image_writer(path, width, height, 3);
    write_rgb_image(*writer, pixels);
    writer->commit();
    writer.reset();

    CHECK(dir.entries() == std::set<std::string>{"image" + extension});
    const Grey rgb = image_format_for_path(path) == ImageFormat::png ? read_rgb_png(path) : read_ppm(path);
    CHECK(rgb.width == width);
    CHECK(rgb.height == height);
    CHECK(rgb.pixels == pixels);
}

TEST_CASE("an RGB PNG is 8-bit RGB and holds the exact bytes", "[image][rgb]") {
    TempDir dir;
    const std::string path = dir.file("c.png");
    // Red, green, blue; white, black, a grey that is not r = g = b everywhere.
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 1, 2, 3};
    auto writer = open_image_writer(path, 3, 2, 3);
    writer->write_rows(pixels.data(), 1);
    writer->write_rows(pixels.data() + 9, 1);
    writer->commit();
    const std::string png = read_bytes(path);
    REQUIRE(png.size() > 26);
    CHECK(png.compare(12, 4, "IHDR") == 0);
    CHECK(int(png[19]) == 3);  // width (big-endian, low byte)
    CHECK(int(png[23]) == 2);  // height
    CHECK(int(png[24]) == 8);  // bit depth
    CHECK(int(png[25]) == 2);  // colour type: RGB
    CHECK(int(png[28]) == 0);  // not interlaced
    const Grey rgb = read_rgb_png(path);
    CHECK(rgb.width == 3);
    CHECK(rgb.height == 2);
    CHECK(rgb.pixels == pixels);
}

TEST_CASE("binary PPM is P6: the header, then r, g, b a pixel", "[image][rgb]") {
    TempDir dir;
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 32, 13};  // 2 x 2, with ' ' and '\r'
    auto writer = open_image_writer(dir.file("c.ppm"), 2, 2, 3);
    writer->write_rows(pixels.data(), 2);
    writer->commit();
    CHECK(read_bytes(dir.file("c.ppm")) == "P6\n2 2\n255\n" + as_string(pixels));
}

TEST_CASE("a grey image written as PPM has r = g = b", "[image][rgb]") {
    TempDir dir;
    const std::vector<std::uint8_t> grey = {0, 64, 128, 255, 7, 200};
    SECTION("binary, P6") {
        auto writer = open_image_writer(dir.file("g.ppm"), 3, 2);  // channels = 1 by default
        CHECK(writer->channels() == 1);
        writer->write_rows(grey.data(), 1);
        writer->write_rows(grey.data() + 3, 1);
        writer->commit();
        const std::vector<std::uint8_t> rgb = {0,   0,   0,   64, 64, 64, 128, 128, 128,
                                               255, 255, 255, 7,  7,  7,  200, 200, 200};
        CHECK(read_bytes(dir.file("g.ppm")) == "P6\n3 2\n255\n" + as_string(rgb));
    }
    SECTION("plain, P3") {
        OutputFile file(dir.file("g.ppm"));
        auto writer = open_image_writer(file, ImageFormat::ppm_plain, 3, 2, 1);
        writer->write_rows(grey.data(), 2);
        writer->finish();
        file.commit();
        CHECK(read_bytes(dir.file("g.ppm")) ==
              "P3\n3 2\n255\n0 0 0 64 64 64 128 128 128\n255 255 255 7 7 7 200 200 200\n");
    }
}

TEST_CASE("plain PPM is P3: each image row starts a line, r g b in order", "[image][rgb]") {
    TempDir dir;
    const std::string path = dir.file("p.ppm");
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 0, 128, 255, 7, 8, 9, 1, 2, 3};
    OutputFile file(path);
    auto writer = open_image_writer(file, ImageFormat::ppm_plain, 2, 2, 3);
    writer->write_rows(pixels.data(), 2);
    writer->finish();
    file.commit();
    CHECK(read_bytes(path) == "P3\n2 2\n255\n255 0 0 0 128 255\n7 8 9 1 2 3\n");
}

TEST_CASE("plain PPM: lines of at most 70 characters, a pixel never split", "[image][rgb]") {
    const auto size =
        GENERATE(std::make_pair(1, 1), std::make_pair(3, 2), std::make_pair(17, 13), std::make_pair(100, 3));
    CAPTURE(size.first, size.second);
    TempDir dir;
    const std::string path = dir.file("plain.ppm");
    auto pixels = rgb_gradient(size.first, size.second);
    std::fill(pixels.begin(), pixels.begin() + 3, std::uint8_t{255});  // the widest pixel
    {
        OutputFile file(path);
        auto writer = open_image_writer(file, ImageFormat::ppm_plain, size.first, size.second, 3);
        write_rgb_image(*writer, pixels);
        writer->finish();
        file.commit();
    }
    const std::string text = read_bytes(path);
    const std::string header = fmt::format("P3\n{} {}\n255\n", size.first, size.second);
    REQUIRE(text.rfind(header, 0) == 0);
    std::istringstream lines(text.substr(header.size()));
    std::string line;
    int line_count = 0;
    while (std::getline(lines, line)) {
        ++line_count;
        CAPTURE(line);
        CHECK(line.size() <= 70);
        CHECK(std::count(line.begin(), line.end(), ' ') % 3 == 2);  // whole pixels: 3k numbers, 3k - 1 spaces
    }
    // 11 characters and a space for the widest pixel: at least 5 pixels a line
    // fit, and 100 pixels of up to 12 characters need more than one line.
    if (size.first == 100) CHECK(line_count > size.second);
    if (size.first <= 5) CHECK(line_count == size.second);
    const Grey rgb = read_plain_ppm(text);
    CHECK(rgb.width == size.first);
    CHECK(rgb.height == size.second);
    CHECK(rgb.pixels == pixels);
}

TEST_CASE("plain PPM wraps before the 71st character, between pixels", "[image][rgb]") {
    // Six pixels of "255 255 255" are 6 * 11 + 5 = 71 characters: the sixth
    // starts a new line; five are 59.
    TempDir dir;
    const std::string path = dir.file("w.ppm");
    const std::vector<std::uint8_t> pixels(6 * 3, 255);
    OutputFile file(path);
    auto writer = open_image_writer(file, ImageFormat::ppm_plain, 6, 1, 3);
    writer->write_rows(pixels.data(), 1);
    writer->finish();
    file.commit();
    const std::string five = "255 255 255 255 255 255 255 255 255 255 255 255 255 255 255";
    CHECK(read_bytes(path) == "P3\n6 1\n255\n" + five + "\n255 255 255\n");
}

TEST_CASE("a coloured image as PGM is refused before any file is created", "[image][rgb]") {
    TempDir dir;
    SECTION("check_image_format") {
        CHECK_THROWS_MATCHES(check_image_format(ImageFormat::pgm, 3, "x.pgm"), UsageError,
                             Catch::Message("x.pgm: PGM holds grey levels only and this scene is coloured; "
                                            "write .png or .ppm"));
        CHECK_THROWS_AS(check_image_format(ImageFormat::pgm_plain, 3, "x.pgm"), UsageError);
        for (const ImageFormat format :
             {ImageFormat::png, ImageFormat::pgm, ImageFormat::pgm_plain, ImageFormat::ppm, ImageFormat::ppm_plain}) {
            CHECK_NOTHROW(check_image_format(format, 1, "x"));
        }
        for (const ImageFormat format : {ImageFormat::png, ImageFormat::ppm, ImageFormat::ppm_plain}) {
            CHECK_NOTHROW(check_image_format(format, 3, "x"));
        }
    }
    SECTION("open_image_writer(path, ...)") {
        const std::string name = GENERATE(std::string("x.pgm"), std::string("X.PGM"));
        const std::string path = dir.file(name);
        CHECK_THROWS_MATCHES(open_image_writer(path, 4, 4, 3), UsageError,
                             Catch::Message(path + ": PGM holds grey levels only and this scene is coloured; "
                                                   "write .png or .ppm"));
        CHECK_FALSE(fs::exists(path));
    }
    SECTION("refused before opening: a file that could not be created is not the error") {
        // Were the file opened first, these would be OutputError.
        CHECK_THROWS_AS(open_image_writer(dir.file("missing/x.pgm"), 4, 4, 3), UsageError);
        CHECK_THROWS_AS(open_image_writer("/proc/promyk-test-x.pgm", 4, 4, 3), UsageError);
    }
    SECTION("open_image_writer(file, ...) writes nothing into the file") {
        const std::string path = dir.file("x.pgm");
        {
            OutputFile file(path);
            CHECK_THROWS_AS(open_image_writer(file, ImageFormat::pgm, 4, 4, 3), UsageError);
            CHECK_THROWS_AS(open_image_writer(file, ImageFormat::pgm_plain, 4, 4, 3), UsageError);
            CHECK_THROWS_AS(open_pgm_writer(file, 4, 4, false, 3), UsageError);
            CHECK(file.bytes_written() == 0);
        }
    }
    CHECK(dir.entries().empty());
}

TEST_CASE("a scaled RGB writer draws RGB blocks, with grey grid lines in every channel", "[image][rgb]") {
    const bool grid = GENERATE(false, true);
    const int scale = GENERATE(1, 2, 3);
    CAPTURE(grid, scale);
    TempDir dir;
    const std::string path = dir.file("s.ppm");
    const int w = 3;
    const auto pixels = rgb_gradient(w, w);
    const int side = static_cast<int>(scaled_side(w, scale, grid));
    {
        OutputFile file(path);
        auto writer = scale_image_writer(open_image_writer(file, ImageFormat::ppm, side, side, 3), w, scale, grid);
        CHECK(writer->width() == w);
        CHECK(writer->channels() == 3);
        write_rgb_image(*writer, pixels);
        writer->finish();
        file.commit();
    }
    const Grey rgb = read_ppm(path);
    REQUIRE(rgb.width == side);
    REQUIRE(rgb.height == side);
    REQUIRE(rgb.pixels.size() == static_cast<std::size_t>(side * side * 3));
    const int step = scale + (grid ? 1 : 0);
    auto luma = [&](int i, int j) {
        const std::size_t k = static_cast<std::size_t>((i * w + j) * 3);
        return luminance(pixels[k], pixels[k + 1], pixels[k + 2]);
    };
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const bool line_y = grid && y % step == scale, line_x = grid && x % step == scale;
            const int i = y / step, j = x / step;
            // A line pixel is grey (r = g = b), the grey that stands out most from its neighbours.
            const int line = line_y && line_x ? contrasting_grey({luma(i, j), luma(i, j + 1), luma(i + 1, j),
                                                                  luma(i + 1, j + 1)})
                             : line_y         ? contrasting_grey({luma(i, j), luma(i + 1, j)})
                             : line_x         ? contrasting_grey({luma(i, j), luma(i, j + 1)})
                                              : -1;
            for (int c = 0; c < 3; ++c) {
                const int expected = line >= 0 ? line : pixels[static_cast<std::size_t>((i * w + j) * 3 + c)];
                CAPTURE(x, y, c);
                REQUIRE(int(rgb.pixels[static_cast<std::size_t>((y * side + x) * 3 + c)]) == expected);
            }
        }
    }
}

TEST_CASE("a scaled RGB writer, 2 x 2 at scale 2 with a grid, byte for byte", "[image][rgb]") {
    TempDir dir;
    const std::string path = dir.file("s.ppm");
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 1, 2, 3};
    {
        OutputFile file(path);
        auto writer = scale_image_writer(open_image_writer(file, ImageFormat::ppm_plain, 5, 5, 3), 2, 2, true);
        writer->write_rows(pixels.data(), 2);
        writer->finish();
        file.commit();
    }
    CHECK(read_bytes(path) ==
          "P3\n5 5\n255\n"
          // Luminances: red 54, green 182, blue 19, (1, 2, 3) 2. Red | green:
          // white (73 from green, 64 for mid-grey); blue | (1, 2, 3): white;
          // under red over blue: white; under green over (1, 2, 3): grey 92
          // (90 from each); the crossing of all four: white (73).
          "255 0 0 255 0 0 255 255 255 0 255 0 0 255 0\n"
          "255 0 0 255 0 0 255 255 255 0 255 0 0 255 0\n"
          "255 255 255 255 255 255 255 255 255 92 92 92 92 92 92\n"
          "0 0 255 0 0 255 255 255 255 1 2 3 1 2 3\n"
          "0 0 255 0 0 255 255 255 255 1 2 3 1 2 3\n");
}
