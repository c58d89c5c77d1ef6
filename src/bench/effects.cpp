#include "bench/effects.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/cpu_pinning.hpp"
#include "bench/timing.hpp"
#include "render/renderer.hpp"
#include "render/stages.hpp"
#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "util/embedded_files.hpp"
#include "util/interrupt.hpp"
#include "util/standard_output.hpp"

namespace promyk::bench {

namespace {

class NullSink final : public RenderSink {
public:
    void image_rows(const std::uint8_t*, int) override {}
};

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
    std::vector<RenderStats> stats(scenes.size());

    std::vector<int> cpus = allowed_cpus();
    std::optional<PinnedToCpu> pin;
    if (!cpus.empty()) pin.emplace(cpus.front());  // one core for every run: like with like
    print_standard_output("promyk bench effects: every example scene at w = {} ({} pixels), one thread,\n"
               "  {} alternating round{}, medians; each timed run repeats the pane until it lasts\n"
               "  at least {:.0f} ms\n\n",
               w, w * static_cast<long>(w), options.repetitions, options.repetitions == 1 ? "" : "s",
               TimingPolicy{}.min_run_seconds * 1e3);
    flush_standard_output();
    std::vector<TimedWork> jobs;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        NullSink sink;
        render(scenes[k], {w, 1}, PixelSelection{}, sink, &stats[k]);  // the work columns (untimed)
        jobs.push_back(repeated([&, k] {
            NullSink timed_sink;
            render(scenes[k], {w, 1}, PixelSelection{}, timed_sink);
        }));
    }
    TimingPolicy policy;
    policy.rounds = options.repetitions;
    const std::vector<Timing> timings = time_side_by_side(jobs, policy);

    const Timing& article = timings.front();
    print_standard_output("  {:<12} {:>9} {:>9}  {:>13} {:>13} {:>12}  {}\n", "scene", "ns/pixel", "× article",
               "shadow rays/px", "sphere tests/px", "plane tests/px", "stages");
    std::vector<std::string> problems;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Timing& t = timings[k];
        const RenderStats& s = stats[k];
        if (!t.timed) problems.push_back(ui_message("bench_effects_untimed", {{"scene", scenes[k].name}, {"why", t.problem}}));
        const std::string ns = t.timed ? fmt::format("{:.2f}", t.median_seconds_per_unit / pixels * 1e9) : "-";
        const std::string ratio =
            t.timed && article.timed ? fmt::format("{:.2f}", t.median_seconds_per_unit / article.median_seconds_per_unit)
                                     : "-";
        print_standard_output("  {:<12} {:>9} {:>9}  {:>13.3f} {:>13.3f} {:>12.3f}  {}\n", scenes[k].name, ns, ratio,
                   static_cast<double>(s.shadow_rays) / pixels, static_cast<double>(s.sphere_tests) / pixels,
                   static_cast<double>(s.plane_tests) / pixels, stage_list(scenes[k]));
    }
    if (!problems.empty()) print_standard_output("\n");
    for (const std::string& problem : problems) print_standard_output("  {}\n", problem);
    print_standard_output("\n  × article: the scene's time per pixel over the article's (1.00). Every pixel casts one primary "
               "ray;\n  the work columns count what the scene's stages add per pixel.\n");
    return 0;
}

}  // namespace promyk::bench
