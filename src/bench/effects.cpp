#include "bench/effects.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/cpu_pinning.hpp"
#include "render/renderer.hpp"
#include "render/stages.hpp"
#include "scene/scene_json.hpp"
#include "util/embedded_files.hpp"
#include "util/interrupt.hpp"

namespace promyk::bench {

namespace {

using Clock = std::chrono::steady_clock;

class NullSink final : public RenderSink {
public:
    void image_rows(const std::uint8_t*, int) override {}
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// The article's scene first, then the example scenes in the order of the
// features they add (the others after them, by name).
std::vector<Scene> example_scenes() {
    const std::vector<std::string> order = {"article", "two_spheres", "two_lights", "floor",
                                            "shadows", "phong",       "colour",     "everything"};
    std::vector<std::pair<std::size_t, Scene>> found;
    for (const embedded::EmbeddedFile& file : embedded::lesson_files()) {
        const std::string path(file.path);
        if (path.rfind("scenes/", 0) != 0 || path.size() < 5 || path.substr(path.size() - 5) != ".json" ||
            path.find(".schema.") != std::string::npos)
            continue;
        const std::string stem = path.substr(7, path.size() - 12);
        const auto at = std::find(order.begin(), order.end(), stem);
        found.emplace_back(static_cast<std::size_t>(at - order.begin()), parse_scene(file.text, "scenes/" + stem + ".json"));
        found.back().second.name = stem;
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second.name < b.second.name;
    });
    std::vector<Scene> scenes;
    for (auto& [rank, scene] : found) scenes.push_back(std::move(scene));
    return scenes;
}

std::string stage_list(const Scene& scene) {
    std::string out;
    for (const std::string& id : effect_ids(scene, plan_stages(scene))) out += (out.empty() ? "" : ", ") + id;
    return out;
}

}  // namespace

int run_effects_bench(const EffectsOptions& options) {
    const std::vector<Scene> scenes = example_scenes();
    const int w = options.w;
    const double pixels = static_cast<double>(w) * w;
    std::vector<std::vector<double>> times(scenes.size());
    std::vector<RenderStats> stats(scenes.size());

    std::vector<int> cpus = allowed_cpus();
    std::optional<PinnedToCpu> pin;
    if (!cpus.empty()) pin.emplace(cpus.front());  // one core for every run: like with like
    fmt::print("promyk bench effects: every example scene at w = {} ({} pixels), one thread, {} alternating "
               "round{}, medians\n\n",
               w, w * static_cast<long>(w), options.repetitions, options.repetitions == 1 ? "" : "s");
    std::fflush(stdout);
    for (int round = 0; round < options.repetitions; ++round) {
        for (std::size_t k = 0; k < scenes.size(); ++k) {
            throw_if_interrupted();
            NullSink sink;
            const auto start = Clock::now();
            render(scenes[k], {w, 1}, PixelSelection{}, sink, &stats[k]);
            times[k].push_back(std::chrono::duration<double>(Clock::now() - start).count());
        }
    }

    const double article = median(times.front());
    // A ratio is worth printing only when the runs are long enough for the
    // clock and the scheduler to be noise (as in bench speed).
    const bool ratios = article >= 0.020;
    fmt::print("  {:<12} {:>9} {:>9}  {:>13} {:>13} {:>12}  {}\n", "scene", "ns/pixel", "× article",
               "shadow rays/px", "sphere tests/px", "plane tests/px", "stages");
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const double t = median(times[k]);
        const RenderStats& s = stats[k];
        const std::string ratio = ratios ? fmt::format("{:.2f}", t / article) : "—";
        fmt::print("  {:<12} {:>9.2f} {:>9}  {:>13.3f} {:>13.3f} {:>12.3f}  {}\n", scenes[k].name, t / pixels * 1e9,
                   ratio, static_cast<double>(s.shadow_rays) / pixels,
                   static_cast<double>(s.sphere_tests) / pixels, static_cast<double>(s.plane_tests) / pixels,
                   stage_list(scenes[k]));
    }
    if (!ratios)
        fmt::print("\n  no ratios: the article's scene ran in {:.1f} ms, under 20 ms, too short to compare; use "
                   "--w {} or more\n",
                   article * 1e3, 2048);
    fmt::print("\n  × article: the scene's time per pixel over the article's (1.00). Every pixel casts one primary "
               "ray;\n  the work columns count what the scene's stages add per pixel.\n");
    return 0;
}

}  // namespace promyk::bench
