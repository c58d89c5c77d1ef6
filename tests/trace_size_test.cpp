// The trace size estimate: pixels counted once however the selection
// overlaps, samples spread through the selection, bytes measured.
#include <catch2/catch.hpp>

#include "render/trace_pixel.hpp"

#include <algorithm>
#include <set>

#include "render/trace_size.hpp"
#include "scene/scene.hpp"

using namespace promyk;

TEST_CASE("traced pixels are counted once", "[trace-size]") {
    TracedPixels all;
    all.all = true;
    CHECK(count_traced_pixels(all, 512) == 512 * 512);
    CHECK(count_traced_pixels(all, 32768) == 32768LL * 32768);

    TracedPixels chosen;
    chosen.pixels = {{3, 4}, {3, 4}, {0, 0}, {7, 7}};
    chosen.regions = {{0, 0, 1, 1}, {1, 1, 2, 2}};
    // regions: 4 + 4 - 1 shared = 7; pixels: (0,0) inside, (3,4), (7,7) outside
    CHECK(count_traced_pixels(chosen, 8) == 9);

    TracedPixels huge;
    huge.regions = {{0, 0, 32767, 32767}, {5, 5, 10, 10}};
    CHECK(count_traced_pixels(huge, 32768) == 32768LL * 32768);
}

TEST_CASE("samples are distinct chosen pixels, the same every run", "[trace-size]") {
    TracedPixels chosen;
    chosen.pixels = {{3, 4}, {7, 7}};
    chosen.regions = {{0, 0, 1, 1}, {1, 1, 2, 2}};
    const auto sample = sample_traced_pixels(chosen, 8, 32);
    CHECK(sample.size() == 9);  // fewer chosen than samples: all of them
    CHECK(std::set<std::pair<int, int>>(sample.begin(), sample.end()).size() == 9);

    TracedPixels all;
    all.all = true;
    const auto spread = sample_traced_pixels(all, 512, 64);
    REQUIRE(spread.size() == 64);
    CHECK(spread.front().first < 16);
    CHECK(spread.back().first > 496);
    CHECK(std::is_sorted(spread.begin(), spread.end()));
    std::set<int> columns;
    for (const auto& pixel : spread) columns.insert(pixel.second);
    CHECK(columns.size() > 32);  // not all in one column (where a whole pane's samples would all miss)
    CHECK(spread == sample_traced_pixels(all, 512, 64));
}

TEST_CASE("the estimate multiplies the pixels by a measured trace size", "[trace-size]") {
    TracedPixels all;
    all.all = true;
    CHECK(estimate_trace_size(article_scene(), 512, all).pixels == 512 * 512);
    // Against the real size: every trace of a 128 × 128 pane, written out.
    const TraceSizeEstimate estimate = estimate_trace_size(article_scene(), 128, all);
    const Scene scene = article_scene();
    const ArticleWorld<double> world = article_world(scene);
    const TraceHeader header = trace_header(scene, 128);
    double real = 0;
    for (int i = 0; i < 128; ++i) {
        for (int j = 0; j < 128; ++j) {
            std::string line;
            append_trace_json(line, trace_pixel(world, header, i, j));
            real += static_cast<double>(line.size() + 1);  // and its newline
        }
    }
    CHECK(estimate.bytes_per_trace > 200);
    CHECK(estimate.bytes() > real * 0.95);
    CHECK(estimate.bytes() < real * 1.05);

    TracedPixels none;
    CHECK(estimate_trace_size(article_scene(), 8, none).bytes() == 0);
}
