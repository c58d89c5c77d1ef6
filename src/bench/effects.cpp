#include "bench/effects.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_text.hpp"
#include "bench/cpu_pinning.hpp"
#include "bench/timing.hpp"
#include "render/general_kernel.hpp"
#include "render/renderer.hpp"
#include "render/skipping.hpp"
#include "render/stages.hpp"
#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "util/embedded_files.hpp"
#include "util/interrupt.hpp"
#include "util/standard_output.hpp"
#include "util/text_table.hpp"
#include "util/wrap.hpp"

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
    const int spp = options.spp;
    const double pixels = static_cast<double>(w) * w;
    // One thread, spp samples a pixel (or n). Timed as `promyk render` runs
    // without --stats, counting only the non-finite pixels (as bench speed
    // does); the untimed runs that fill the work columns count every branch.
    const auto settings = [&](int n, bool counted = false) {
        RenderSettings s;
        s.w = w, s.threads = 1, s.spp = n;
        s.count_branches = counted;
        return s;
    };
    std::vector<RenderStats> stats(scenes.size());

    std::vector<int> cpus = allowed_cpus();
    std::optional<PinnedToCpu> pin;
    if (!cpus.empty()) pin.emplace(cpus.front());  // one core for every run: like with like
    print_standard_output("{}\n\n", wrap_text(ui_message(spp > 1 ? "bench_effects_title_spp" : "bench_effects_title",
                                                      {{"w", std::to_string(w)},
                                                       {"spp", std::to_string(spp)},
                                                       {"pixels", counted(w * static_cast<long long>(w), "bench_pixels")},
                                                       {"rounds", counted(options.repetitions, "bench_rounds")},
                                                       {"ms", fixed(TimingPolicy{}.min_run_seconds * 1e3, 0)}}),
                                           2));
    flush_standard_output();
    std::vector<TimedWork> jobs;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        NullSink sink;
        render(scenes[k], settings(spp, true), PixelSelection{}, sink, &stats[k]);  // the work columns (untimed)
        jobs.push_back(repeated([&, k] {
            NullSink timed_sink;
            render(scenes[k], settings(spp), PixelSelection{}, timed_sink);
        }));
    }
    // The article's scene twice more, both computing every pixel (no
    // background skipping): through the article's kernel, and forced through
    // the general tracer, which should cost it only the stages it uses.
    const Scene& article_scene = scenes.front();
    const std::unique_ptr<Kernel> general =
        make_general_kernel(article_scene, RealType::double_, Formula::article, spp);
    const std::size_t no_skipping = jobs.size(), forced_general = jobs.size() + 1;
    std::vector<std::string> names;
    for (const Scene& scene : scenes) names.push_back(scene.name);
    names.push_back(ui_message("bench_effects_article_no_skipping"));
    names.push_back(ui_message("bench_effects_article_general"));
    stats.resize(scenes.size() + 2);
    const bool skipping = background_skipping();
    set_background_skipping(false);
    {
        NullSink sink;
        render(article_scene, settings(spp, true), PixelSelection{}, sink, &stats[no_skipping]);
        render(*general, article_scene, settings(spp, true), PixelSelection{}, sink, &stats[forced_general]);
    }
    set_background_skipping(skipping);
    general->set_branch_counting(false);  // timed as the article's kernel is (settings)
    jobs.push_back(repeated([&] {
        NullSink timed_sink;
        set_background_skipping(false);
        render(article_scene, settings(spp), PixelSelection{}, timed_sink);
        set_background_skipping(skipping);
    }));
    jobs.push_back(repeated([&] {
        NullSink timed_sink;
        render(*general, article_scene, settings(spp), PixelSelection{}, timed_sink);
    }));
    // With samples, each row's scene once more at spp 1 (the two kernels'
    // too), in the same rounds: a sample's cost against its own pixel's.
    const std::size_t rows = jobs.size();
    const std::unique_ptr<Kernel> general_1 = make_general_kernel(article_scene);
    general_1->set_branch_counting(false);
    if (spp > 1) {
        for (std::size_t k = 0; k < scenes.size(); ++k)
            jobs.push_back(repeated([&, k] {
                NullSink timed_sink;
                render(scenes[k], settings(1), PixelSelection{}, timed_sink);
            }));
        jobs.push_back(repeated([&] {
            NullSink timed_sink;
            set_background_skipping(false);
            render(article_scene, settings(1), PixelSelection{}, timed_sink);
            set_background_skipping(skipping);
        }));
        jobs.push_back(repeated([&] {
            NullSink timed_sink;
            render(*general_1, article_scene, settings(1), PixelSelection{}, timed_sink);
        }));
    }
    TimingPolicy policy;
    policy.rounds = options.repetitions;
    const std::vector<Timing> timings = time_side_by_side(jobs, policy);

    const Timing& article = timings.front();
    std::vector<TextColumn> columns = {{ui_message("bench_col_scene"), true},
                                              {ui_message("bench_col_ns_pixel")},
                                              {ui_message("bench_col_x_article")},
                                              {ui_message("bench_col_shadow_rays")},
                                              {ui_message("bench_col_sphere_tests")},
                                              {ui_message("bench_col_plane_tests")},
                                              {ui_message("bench_col_skipped")}};
    if (spp > 1) columns.push_back({ui_message("bench_col_sample_x_spp1")});
    TextTable table(columns);
    std::vector<std::string> problems;
    for (std::size_t k = 0; k < rows; ++k) {
        const Timing& t = timings[k];
        const RenderStats& s = stats[k];
        if (!t.timed) problems.push_back(ui_message("bench_effects_untimed", {{"scene", names[k]}, {"why", t.problem}}));
        std::vector<std::string> cells = {
            names[k], t.timed ? fixed(t.median_seconds_per_unit / pixels * 1e9, 2) : "-",
            t.timed && article.timed ? fixed(t.median_seconds_per_unit / article.median_seconds_per_unit, 2) : "-",
            fixed(static_cast<double>(s.shadow_rays) / pixels, 3),
            fixed(static_cast<double>(s.sphere_tests) / pixels, 3),
            fixed(static_cast<double>(s.plane_tests) / pixels, 3),
            fixed(static_cast<double>(s.skipped) / pixels, 3)};
        if (spp > 1) {
            // Its time a sample over its own time a pixel at spp 1.
            const Timing& one = timings[rows + k];
            if (!one.timed) problems.push_back(ui_message("bench_effects_untimed", {{"scene", names[k]}, {"why", one.problem}}));
            cells.push_back(t.timed && one.timed
                                ? fixed(t.median_seconds_per_unit / (spp * one.median_seconds_per_unit), 2)
                                : "-");
        }
        table.add_row(cells);
    }
    print_standard_output("{}", table.text());
    const Timing& article_kernel = timings[no_skipping];
    const Timing& general_kernel = timings[forced_general];
    if (article_kernel.timed && general_kernel.timed)
        print_standard_output(
            "\n{}\n", indented(ui_message("bench_effects_general_ratio",
                                          {{"ratio", fixed(general_kernel.median_seconds_per_unit /
                                                               article_kernel.median_seconds_per_unit,
                                                           2)}})));
    if (!problems.empty()) print_standard_output("\n");
    for (const std::string& problem : problems) print_standard_output("{}\n", wrap_text("  " + problem, 4));
    print_standard_output("\n{}\n", wrap_text("  " + ui_message("bench_effects_stages"), 2));
    // The longest list of stages goes on below its scene's name.
    std::size_t name_width = 0;
    for (const Scene& scene : scenes) name_width = std::max(name_width, display_width(scene.name));
    for (const Scene& scene : scenes) {
        const std::string line = "    " + scene.name + std::string(name_width - display_width(scene.name) + 2, ' ') + stage_list(scene);
        print_standard_output("{}\n", wrap_text(line, 6 + name_width));
    }
    print_standard_output("\n{}\n",
                          wrap_text("  " +
                                        ui_message(spp > 1 ? "bench_effects_explained_spp" : "bench_effects_explained",
                                                   {{"spp", std::to_string(spp)}}) +
                                        " " + ui_message("bench_timed_as_render"),
                                    2));
    return 0;
}

}  // namespace promyk::bench
