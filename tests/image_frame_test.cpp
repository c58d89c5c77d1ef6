// The pictures drawn around a pane: the bitmap font, the grid's contrast,
// the row and column numbers (--labels) and a map's legend (--legend).
// Positions are checked on PNGs decoded by libpng, not on promyk's canvases.
#include <catch2/catch.hpp>

#include <png.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "collect_rows.hpp"
#include "image/bitmap_font.hpp"
#include "image/canvas.hpp"
#include "image/framed_writer.hpp"
#include "image/image_writer.hpp"
#include "image/legend.hpp"
#include "image/map_legend.hpp"
#include "image/pane_labels.hpp"
#include "render/maps.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "temp_dir.hpp"
#include "util/output_file.hpp"

using namespace promyk;
using promyk::testing::TempDir;

namespace {

struct Decoded {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
    int luma(int x, int y) const {
        const std::size_t k = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x);
        return luminance(rgb[k], rgb[k + 1], rgb[k + 2]);
    }
    bool grey_at(int x, int y) const {
        const std::size_t k = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x);
        return rgb[k] == rgb[k + 1] && rgb[k + 1] == rgb[k + 2];
    }
};

// Any PNG (grey or RGB) read back as RGB by libpng's simplified API.
Decoded decode_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()) != 0);
    image.format = PNG_FORMAT_RGB;
    Decoded decoded{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    decoded.rgb.resize(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, decoded.rgb.data(), 0, nullptr) != 0);
    return decoded;
}

struct Pane {
    int w = 0;
    int channels = 1;
    std::vector<std::uint8_t> pixels;  // w rows of w pixels
};

// Writes `pane` as `promyk render` does: scaled, gridded, framed with labels
// and/or a legend, into a PNG; returns its path.
std::string write_pane(const TempDir& dir, const Pane& pane, int scale, bool grid, bool labels,
                       const Legend* legend = nullptr) {
    const std::string path = dir.file("pane.png");
    const int side = static_cast<int>(scaled_side(pane.w, scale, grid));
    Frame frame;
    if (labels) draw_pane_labels(pane_labels(pane.w, scale, grid), pane.w, scale, grid, pane.channels, frame);
    if (legend) frame.bottom = draw_legend(*legend, framed_width(frame, side), pane.channels);
    OutputFile file(path);
    std::unique_ptr<ImageWriter> writer = open_image_writer(file, ImageFormat::png, framed_width(frame, side),
                                                            framed_height(frame, side), pane.channels);
    if (!frame.empty()) writer = frame_image_writer(std::move(writer), std::move(frame), side, side);
    if (side != pane.w) writer = scale_image_writer(std::move(writer), pane.w, scale, grid);
    writer->write_rows(pane.pixels.data(), pane.w);
    writer->finish();
    file.commit();
    return path;
}

using promyk::testing::Collect;

Pane article_pane(int w) {
    Collect sink;
    sink.row_bytes = static_cast<std::size_t>(w);
    render(article_scene(), {w, 2}, PixelSelection{}, sink);
    return {w, 1, sink.bytes};
}

Pane branch_map_pane(int w) {
    const auto map = make_map_kernel(MapKind::branch, article_scene(), RealType::double_, Formula::article, 1, w);
    Collect sink;
    sink.row_bytes = static_cast<std::size_t>(w) * 3;
    render(*map, article_scene(), {w, 2}, PixelSelection{}, sink);
    return {w, 3, sink.bytes};
}

Pane random_colour_pane(int w, unsigned seed) {
    std::mt19937 random(seed);
    Pane pane{w, 3, {}};
    for (int k = 0; k < 3 * w * w; ++k) pane.pixels.push_back(static_cast<std::uint8_t>(random() % 256));
    return pane;
}

// Runs of consecutive indices where `inked(k)` holds: [first, last] pairs.
template <typename Inked>
std::vector<std::pair<int, int>> runs(int count, Inked inked) {
    std::vector<std::pair<int, int>> found;
    for (int k = 0; k < count; ++k) {
        if (!inked(k)) continue;
        if (!found.empty() && found.back().second == k - 1)
            found.back().second = k;
        else
            found.push_back({k, k});
    }
    return found;
}

}  // namespace

TEST_CASE("the font has a glyph for every digit, Latin letter and Polish letter, each unlike the others", "[image]") {
    const std::string letters =
        "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyząćęłńóśźżĄĆĘŁŃÓŚŹŻ.,:;-−+=<>≤≥×·…()[]/|_%'\"„”!?";
    std::set<std::vector<std::uint8_t>> shapes;
    int count = 0;
    for (const char32_t code : utf8_code_points(letters)) {
        CAPTURE(static_cast<unsigned>(code));
        CHECK(has_glyph(code));
        Canvas canvas(font::glyph_width, font::glyph_height, 1);
        // Drawn alone, re-encoded to UTF-8 by the decoder's inverse.
        std::string one;
        if (code < 0x80) {
            one += static_cast<char>(code);
        } else if (code < 0x800) {
            one += static_cast<char>(0xC0 | code >> 6), one += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            one += static_cast<char>(0xE0 | code >> 12), one += static_cast<char>(0x80 | (code >> 6 & 0x3F));
            one += static_cast<char>(0x80 | (code & 0x3F));
        }
        CHECK(draw_text(canvas, 0, 0, one, 1, Paint::grey(0)) == 0);
        std::vector<std::uint8_t> shape;
        for (int y = 0; y < canvas.height(); ++y) shape.insert(shape.end(), canvas.row(y), canvas.row(y) + canvas.row_bytes());
        shapes.insert(shape);
        ++count;
    }
    CHECK(static_cast<int>(shapes.size()) == count);  // no two glyphs alike
}

TEST_CASE("a code point without a glyph, or a byte that is not UTF-8, draws a box and is counted", "[image]") {
    Canvas canvas(60, 12, 1);
    CHECK(draw_text(canvas, 0, 0, "a\u4E00b", 1, Paint::grey(0)) == 1);
    CHECK(draw_text(canvas, 0, 0, "a\xFF" "b", 1, Paint::grey(0)) == 1);
    CHECK(draw_text(canvas, 0, 0, "zażółć gęślą jaźń", 1, Paint::grey(0)) == 0);
    // The box: a capital's height, hollow.
    Canvas box(5, 10, 1);
    draw_text(box, 0, 0, "\u4E00", 1, Paint::grey(0));
    CHECK(int(box.at(0, 1).r) == 0);
    CHECK(int(box.at(2, 4).r) == 255);
    CHECK(text_width("abc", 2) == (3 * font::advance - 1) * 2);
    CHECK(utf8_code_points("ż\xC5") == std::u32string{U'ż', U'\uFFFD'});
}

TEST_CASE("every legend name, title and number in both languages has its glyphs", "[image][legend]") {
    std::vector<ColourScale> scales = {error_scale_of_run(3e-17, 4e-16), error_scale(1e-12, 2.5e-7),
                                       fallback_error_scale(), error_scale_of_run(5e-324, 0.5)};
    for (const RealType real : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
        scales.push_back(digits_lost_scale(real));
    for (const Language language : {Language::pl, Language::en}) {
        CAPTURE(std::string(language_code(language)));
        std::vector<Legend> legends = {map_legend(MapKind::branch, nullptr, language),
                                       map_legend(MapKind::error, nullptr, language)};
        for (std::size_t k = 0; k < 4; ++k) legends.push_back(map_legend(MapKind::error, &scales[k], language));
        for (std::size_t k = 4; k < scales.size(); ++k)
            legends.push_back(map_legend(MapKind::digits_lost, &scales[k], language));
        for (const Legend& legend : legends) {
            int unknown = -1;
            const Canvas strip = draw_legend(legend, 900, 3, &unknown);
            CHECK(unknown == 0);
            CHECK(strip.height() > 0);
            for (const LegendSwatch& swatch : legend.swatches) {
                CAPTURE(swatch.name);
                for (const char32_t code : utf8_code_points(swatch.name)) CHECK(has_glyph(code));
            }
        }
    }
    // The branch map's names are the words of messages_words.json.
    const Legend polish = map_legend(MapKind::branch, nullptr, Language::pl);
    REQUIRE(polish.swatches.size() == 7);
    CHECK(polish.swatches[0].name == "chybienie");
    CHECK(polish.swatches[2].name == "strona oświetlona");
    CHECK(polish.swatches[4].name == "wartość nieskończona");
    CHECK(polish.swatches[6].name == "za okiem");
}

TEST_CASE("legend numbers are short, and Polish ones take a comma and a minus sign", "[image][legend]") {
    CHECK(legend_number(1e-16, Language::en) == "1e−16");  // U+2212, as every number shown
    CHECK(legend_number(1e-16, Language::pl) == "1e−16");
    CHECK(legend_number(2.5e-7, Language::en) == "2.5e−7");
    CHECK(legend_number(2.5e-7, Language::pl) == "2,5e−7");
    CHECK(legend_number(1e20, Language::en) == "1e20");
    CHECK(legend_number(1, Language::pl) == "1");
    CHECK(legend_number(0.001, Language::pl) == "0,001");
    const ColourScale scale = error_scale_of_run(3e-17, 4e-16);
    const Legend legend = map_legend(MapKind::error, &scale, Language::en);
    REQUIRE(legend.bar);
    REQUIRE(legend.bar->ticks.size() == 3);  // 1e-17, 1e-16, 1e-15
    CHECK(legend.bar->ticks[1].text == "1e−16");
    CHECK(legend.bar->ticks[1].t == Approx(0.5));
}

TEST_CASE("a legend wraps its names into rows to fit the width, and says what it needs when it cannot", "[image][legend]") {
    const Legend legend = map_legend(MapKind::branch, nullptr, Language::pl);
    const LegendNeed need = legend_need(legend);
    CHECK(need.widest == "wartość nieskończona");
    CHECK(need.width == 2 * 2 + 7 + 3 + text_width("wartość nieskończona", 1));
    CHECK(legend_size(legend, need.width) == 1);
    CHECK(legend_size(legend, need.width - 1) == 0);
    CHECK_THROWS_AS(draw_legend(legend, need.width - 1, 3), std::invalid_argument);
    // Narrow: one name a row or nearly; wide: fewer rows.
    const int narrow = draw_legend(legend, need.width, 3).height();
    const int wide = draw_legend(legend, 300, 3).height();  // both at font size 1
    CHECK(narrow >= 5 * font::line_height);
    CHECK(wide < narrow);
    // Every name drawn lies inside the strip: the right edge column has no ink at any width.
    for (const int width : {need.width, need.width + 37, 300, 640}) {
        const Canvas strip = draw_legend(legend, width, 3);
        for (int y = 0; y < strip.height(); ++y) CHECK(luminance(strip.at(width - 1, y)) == 255);
    }
}

TEST_CASE("every grid line pixel stands out from the squares it borders", "[image][grid]") {
    TempDir dir;
    struct Scene_ {
        const char* name;
        Pane pane;
    };
    const std::vector<Scene_> scenes = {{"the article's scene, grey", article_pane(16)},
                                        {"the branch map, colour", branch_map_pane(16)},
                                        {"random colours", random_colour_pane(16, 7)},
                                        {"random colours 2", random_colour_pane(9, 11)}};
    for (const Scene_& scene : scenes) {
        for (const int scale : {1, 3, 8}) {
            CAPTURE(scene.name, scale);
            const Pane& pane = scene.pane;
            const Decoded image = decode_png(write_pane(dir, pane, scale, true, false));
            const int pitch = scale + 1;
            REQUIRE(image.width == pane.w * pitch - 1);
            // A square's luminance, as the image shows it (decoded).
            auto square = [&](int i, int j) { return image.luma(j * pitch, i * pitch); };
            int lines = 0;
            for (int y = 0; y < image.width; ++y) {
                for (int x = 0; x < image.width; ++x) {
                    const bool line_y = y % pitch == scale, line_x = x % pitch == scale;
                    if (!line_y && !line_x) continue;
                    const int i = y / pitch, j = x / pitch, here = image.luma(x, y);
                    CAPTURE(x, y);
                    REQUIRE(image.grey_at(x, y));
                    // Built whole, not assigned: GCC 12 warns (-Wnonnull) about
                    // assigning a list to an empty vector.
                    const std::vector<int> borders =
                        line_y && line_x
                            ? std::vector<int>{square(i, j), square(i, j + 1), square(i + 1, j), square(i + 1, j + 1)}
                        : line_y ? std::vector<int>{square(i, j), square(i + 1, j)}
                                 : std::vector<int>{square(i, j), square(i, j + 1)};
                    const int margin = line_y && line_x ? 32 : 64;
                    for (const int b : borders) REQUIRE(std::abs(here - b) >= margin);
                    ++lines;
                }
            }
            CHECK(lines == 2 * (pane.w - 1) * image.width - (pane.w - 1) * (pane.w - 1));
        }
    }
}

TEST_CASE("row and column numbers sit centred on their rows' and columns' bands", "[image][labels]") {
    TempDir dir;
    struct Case {
        int w, scale;
        bool grid;
    };
    for (const Case c : {Case{8, 40, true}, Case{8, 40, false}, Case{64, 4, true}, Case{16, 20, true},
                         Case{64, 1, false}}) {
        CAPTURE(c.w, c.scale, c.grid);
        const Pane pane = c.w <= 16 ? article_pane(c.w) : branch_map_pane(c.w);
        const Decoded image = decode_png(write_pane(dir, pane, c.scale, c.grid, true));
        const PaneLabels labels = pane_labels(c.w, c.scale, c.grid);
        const int side = static_cast<int>(scaled_side(c.w, c.scale, c.grid));
        const int pitch = c.scale + (c.grid ? 1 : 0);
        REQUIRE(image.width == labels.left_width + side);
        REQUIRE(image.height == labels.top_height + side);
        const int labelled = (c.w - 1) / labels.every + 1;

        // Rows: runs of image rows with ink in the left margin.
        const auto row_runs = runs(image.height, [&](int y) {
            for (int x = 0; x < labels.left_width; ++x)
                if (image.luma(x, y) < 128) return true;
            return false;
        });
        REQUIRE(static_cast<int>(row_runs.size()) == labelled);
        for (int k = 0; k < labelled; ++k) {
            const int i = k * labels.every;
            const double band_centre = labels.top_height + i * pitch + (c.scale - 1) / 2.0;
            const double ink_centre = (row_runs[static_cast<std::size_t>(k)].first + row_runs[static_cast<std::size_t>(k)].second) / 2.0;
            CAPTURE(i);
            // Clamped inside the image only where the band is shorter than the digits (scale 1's last row).
            if (i * pitch + (c.scale + 7 * labels.size) / 2 < side) CHECK(std::abs(ink_centre - band_centre) <= 1);
            CHECK(row_runs[static_cast<std::size_t>(k)].second - row_runs[static_cast<std::size_t>(k)].first + 1 ==
                  7 * labels.size);
        }
        // Columns of single digits (w = 8): runs of image columns with ink in the top margin.
        if (c.w <= 10) {
            const auto column_runs = runs(image.width - labels.left_width, [&](int x) {
                for (int y = 0; y < labels.top_height; ++y)
                    if (image.luma(labels.left_width + x, y) < 128) return true;
                return false;
            });
            REQUIRE(static_cast<int>(column_runs.size()) == labelled);
            for (int j = 0; j < labelled; ++j) {
                const double band_centre = j * pitch + (c.scale - 1) / 2.0;
                const auto& run = column_runs[static_cast<std::size_t>(j)];
                CHECK(std::abs((run.first + run.second) / 2.0 - band_centre) <= 1);
            }
        }
        // The pane itself is where it was, shifted by the margins.
        CHECK(image.luma(labels.left_width, labels.top_height) == (pane.channels == 1 ? pane.pixels[0] : image.luma(labels.left_width, labels.top_height)));
    }
    // Only every k-th number when they would touch: k from 1, 2, 5, 10, ...
    CHECK(pane_labels(8, 40, true).every == 1);
    CHECK(pane_labels(64, 4, true).every == 5);
    CHECK(pane_labels(512, 1, false).every == 20);
    CHECK(pane_labels(32768, 1, false).every == 50);
}

TEST_CASE("a legend below a framed pane is the image's width and keeps the pane's pixels in place", "[image][legend]") {
    TempDir dir;
    const Pane pane = branch_map_pane(8);
    const Legend legend = map_legend(MapKind::branch, nullptr, Language::pl);
    const Decoded image = decode_png(write_pane(dir, pane, 40, true, true, &legend));
    const PaneLabels labels = pane_labels(8, 40, true);
    const int side = static_cast<int>(scaled_side(8, 40, true));
    REQUIRE(image.width == labels.left_width + side);
    REQUIRE(image.height > labels.top_height + side);
    // Pixel (i, j)'s block, and below the pane the legend: ink (text) and a swatch of the lit colour.
    const std::size_t first = 3 * (static_cast<std::size_t>(labels.top_height) * image.width + labels.left_width);
    CHECK(int(image.rgb[first]) == pane.pixels[0]);
    bool lit_swatch = false, text = false;
    for (int y = labels.top_height + side; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t k = 3 * (static_cast<std::size_t>(y) * image.width + x);
            lit_swatch |= image.rgb[k] == 0xE6 && image.rgb[k + 1] == 0x9F && image.rgb[k + 2] == 0x00;
            text |= image.luma(x, y) == 0;
        }
    }
    CHECK(lit_swatch);
    CHECK(text);
}
