// The page's overlays (render/map_overlay.hpp, issue 17): the stored values a
// map kernel gives pixel by pixel (MapKernel::pixel_value, what export
// embeds and the page's workers compute), coloured by map_overlay, are
// `render --map`'s pixels byte for byte, with the run's own range and with
// a range given; the legend's data are map_legend's.
#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collect_rows.hpp"
#include "image/map_legend.hpp"
#include "render/map_overlay.hpp"
#include "render/maps.hpp"
#include "render/renderer.hpp"
#include "scene/scene_json.hpp"

using namespace promyk;

namespace {

using promyk::testing::Collect;

// As `promyk render --map KIND [--range]` draws it.
std::vector<std::uint8_t> rendered(MapKind kind, const Scene& scene, int w, RealType real, Formula formula,
                                   std::optional<std::pair<double, double>> range) {
    const std::unique_ptr<MapKernel> map = make_map_kernel(kind, scene, real, formula, 1, w, range);
    Collect sink;
    sink.row_bytes = static_cast<std::size_t>(w) * 3;
    render(*map, scene, {w, 2}, PixelSelection{}, sink);
    if (map->deferred()) {
        map->settle();
        for (int i = 0; i < w; ++i)
            map->replay_row(w, i, sink.bytes.data() + static_cast<std::size_t>(i) * sink.row_bytes);
    }
    return sink.bytes;
}

// Each pixel's stored value, computed one by one (a kernel made with some
// range: the values do not depend on it).
std::vector<double> stored(MapKind kind, const Scene& scene, int w, RealType real, Formula formula) {
    const std::unique_ptr<MapKernel> map =
        make_map_kernel(kind, scene, real, formula, 1, w, std::pair<double, double>{1e-3, 1e-2});
    std::vector<double> values;
    for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) values.push_back(map->pixel_value(w, i, j));
    return values;
}

Scene far_sphere() {
    return load_scene_text(R"({"name": "far", "z_E": 10000, "background": 0.5,
        "spheres": [{"S": [0, 0, 10000], "r": 1}], "lights": [{"L": [1.5, 1, 9998], "I": 1}]})",
                           "far.json");
}

}  // namespace

TEST_CASE("the page's overlay colours are render --map's pixels, byte for byte", "[maps][overlay]") {
    const int w = 24;
    for (const Scene& scene : {article_scene(), far_sphere()})
        for (const RealType real : {RealType::float_, RealType::double_})
            for (const Formula formula : {Formula::article, Formula::geometric})
                for (const MapKind kind : {MapKind::error, MapKind::digits_lost}) {
                    INFO(scene.name << " " << real_type_name(real) << " " << formula_name(formula) << " "
                                    << map_name(kind));
                    const std::vector<double> values = stored(kind, scene, w, real, formula);
                    std::vector<std::uint8_t> rgb;
                    const auto info = map_overlay(kind, real, values.data(), values.size(), std::nullopt,
                                                  Language::en, rgb);
                    CHECK(rgb == rendered(kind, scene, w, real, formula, std::nullopt));
                    CHECK(info["range_given"] == false);
                    if (kind == MapKind::error) {
                        // A range given (the page's "fix the range"): as --range LO,HI.
                        const std::pair<double, double> range{1e-9, 1e-4};
                        const auto fixed = map_overlay(kind, real, values.data(), values.size(), range,
                                                       Language::en, rgb);
                        CHECK(rgb == rendered(kind, scene, w, real, formula, range));
                        CHECK(fixed["range"][0] == 1e-9);
                        CHECK(fixed["range"][1] == 1e-4);
                        CHECK(fixed["range_given"] == true);
                    }
                }
}

TEST_CASE("the overlay's legend is map_legend's, in both languages", "[maps][overlay]") {
    const std::vector<double> values = stored(MapKind::error, article_scene(), 16, RealType::float_, Formula::article);
    std::vector<std::uint8_t> rgb;
    for (const Language language : {Language::en, Language::pl}) {
        const auto info =
            map_overlay(MapKind::error, RealType::float_, values.data(), values.size(), std::nullopt, language, rgb);
        const ColourScale scale = scalar_map_scale(MapKind::error, RealType::float_, values.data(), values.size());
        const Legend legend = map_legend(MapKind::error, &scale, language);
        CHECK(info["title"] == legend.bar->title);
        REQUIRE(info["ticks"].size() == legend.bar->ticks.size());
        for (std::size_t k = 0; k < legend.bar->ticks.size(); ++k) CHECK(info["ticks"][k]["text"] == legend.bar->ticks[k].text);
        REQUIRE(info["swatches"].size() == legend.swatches.size());
        for (std::size_t k = 0; k < legend.swatches.size(); ++k) CHECK(info["swatches"][k]["name"] == legend.swatches[k].name);
        CHECK(info["swatches"][0]["hex"] == "#FFFFFF");     // exact: white
        CHECK(info["swatches"][1]["hex"] == "#D55E00");     // branch differs: vermillion
        CHECK(info["ramp"].size() == 256);
        CHECK(info["ramp"][0] == "#440154");                // viridis from dark purple
        CHECK(info["ramp"][255] == "#FDE725");              // to yellow
        CHECK(info["range_text"][0] == legend_number(scale.low(), language));
    }
    CHECK(map_value_text(MapKind::error, 0, Language::en) == "exact");
    CHECK(map_value_text(MapKind::error, map_stored_value::branch_differs, Language::pl) == "inna gałąź");
    CHECK(map_value_text(MapKind::error, 2.5e-7, Language::en) == shown_number(2.5e-7, Language::en, 3));
}
