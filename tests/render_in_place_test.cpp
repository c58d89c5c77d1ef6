// A sink that keeps the whole image in memory (RenderSink::image_memory)
// has its rows drawn there in place; every byte, count and trace line must
// be what a sink fed band by band (image_rows) receives.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "scene/scene_json.hpp"
#include "sweep_size.hpp"

using namespace promyk;

namespace {

struct StreamedSink final : RenderSink {
    std::vector<std::uint8_t> pixels;
    std::string traces;
    int row_bytes = 0;
    void image_rows(const std::uint8_t* rows, int count) override {
        pixels.insert(pixels.end(), rows, rows + static_cast<std::ptrdiff_t>(count) * row_bytes);
    }
    void trace_lines(std::string_view lines) override { traces.append(lines); }
};

struct InPlaceSink final : RenderSink {
    std::vector<std::uint8_t> pixels;
    std::string traces;
    int image_rows_calls = 0;
    std::uint8_t* image_memory() override { return pixels.data(); }
    void image_rows(const std::uint8_t*, int) override { ++image_rows_calls; }
    void trace_lines(std::string_view lines) override { traces.append(lines); }
};

void check_same_stats(const RenderStats& a, const RenderStats& b) {
    CHECK(a.rows_computed == b.rows_computed);
    CHECK(a.primary_rays == b.primary_rays);
    CHECK(a.shadow_rays == b.shadow_rays);
    CHECK(a.sphere_tests == b.sphere_tests);
    CHECK(a.plane_tests == b.plane_tests);
    CHECK(a.skipped == b.skipped);
    for (int k = 0; k < branch_count; ++k) CHECK(a.branches[k] == b.branches[k]);
    CHECK(a.disagreeing == b.disagreeing);
    CHECK(a.first_non_finite_i == b.first_non_finite_i);
    CHECK(a.first_non_finite_j == b.first_non_finite_j);
}

// Renders the scene both ways and compares everything the sinks and stats got.
void check_in_place(const Scene& scene, const RenderSettings& settings, const PixelSelection& traced) {
    const int channels = image_channels(scene);
    const std::size_t bytes = static_cast<std::size_t>(settings.w) * settings.w * channels;
    StreamedSink streamed;
    streamed.row_bytes = settings.w * channels;
    RenderStats streamed_stats;
    render(scene, settings, traced, streamed, &streamed_stats);

    InPlaceSink in_place;
    in_place.pixels.assign(bytes, 0xA5);  // not a grey level the pane would leave by chance everywhere
    RenderStats in_place_stats;
    render(scene, settings, traced, in_place, &in_place_stats);

    REQUIRE(streamed.pixels.size() == bytes);
    CHECK(in_place.pixels == streamed.pixels);
    CHECK(in_place.traces == streamed.traces);
    CHECK(in_place.image_rows_calls == 0);
    check_same_stats(in_place_stats, streamed_stats);
}

}  // namespace

TEST_CASE("rows drawn in place equal rows delivered band by band", "[render-in-place]") {
    // w = 1030 takes three bands (render/renderer.cpp's band_rows: about
    // 2^19 pixels a band), the last one short; w = 1 and 7 take one.
    for (const int w : {1, 7, 1030}) {
        for (const int threads : {1, 2, 3}) {
            INFO("w = " << w << ", threads = " << threads);
            check_in_place(article_scene(), {w, threads}, PixelSelection{});
        }
    }
}

TEST_CASE("every example scene, coloured ones too, with samples and traces, drawn in place", "[render-in-place]") {
    long long index = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PROMYK_SOURCE_DIR "/lessons/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find(".schema.") != std::string::npos) continue;
        const Scene scene = load_scene_file(path);
        ++index;
        for (const int spp : {1, 4}) {
            if (!in_sweep(index + spp, 2)) continue;  // under the sanitizers, one or the other
            INFO(path << ", spp = " << spp);
            RenderSettings settings{61, 2};
            settings.spp = spp;
            check_in_place(scene, settings, PixelSelection::all());
        }
    }
}
