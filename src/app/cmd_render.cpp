// promyk render: the whole image, and optionally JSON Lines traces beside it.
//
// Every output is checked and opened before anything is computed (a
// directory, a missing folder, two outputs that are one file: nothing is
// rendered and nothing is created), and the outputs are committed together
// at the end, so a failed run leaves none of its new files.
#include <algorithm>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/progress.hpp"
#include "app/trace_limit.hpp"
#include "image/framed_writer.hpp"
#include "image/legend.hpp"
#include "image/pane_labels.hpp"
#include "image/image_writer.hpp"
#include "image/map_legend.hpp"
#include "render/maps.hpp"
#include "render/renderer.hpp"
#include "render/scene_report.hpp"
#include "render/stages.hpp"
#include "render/trace_size.hpp"
#include "trace/byte_size_text.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/printable.hpp"
#include "util/wrap.hpp"
#include "util/output_file.hpp"

namespace promyk::app {

namespace {


struct RenderOptions {
    std::string scene_file;
    std::string output = "promyk.png";
    int w = 512;
    int threads = 0;
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    int spp = 1;
    bool plain = false;
    bool stats = false;
    int scale = 1;
    bool grid = false;
    std::string traces_file;
    std::vector<std::string> trace_pixels;
    std::vector<std::string> trace_regions;
    bool force = false;
    std::string max_trace_size;  // --max-trace-size; empty: the default limit
    std::string map;  // empty: the shading; else a map_name (render/maps.hpp)
    bool labels = false;  // row and column numbers on the margins
    bool legend = false;  // a map's legend below it
    std::string range;    // the error map's scale, "LO,HI"; empty: the run's own
};

// Room the margins and the legend may take beyond the pane.
constexpr int frame_allowance = 512;

// Streams rows into the image and trace lines into the traces file; regular
// files are temporaries until commit, so a failed render leaves nothing.
class FileSink final : public RenderSink {
public:
    // `image` null: the rows are dropped (a deferred map's placeholders).
    FileSink(ImageWriter* image, OutputFile* traces, Progress& progress)
        : image_(image), traces_(traces), progress_(progress) {}
    void image_rows(const std::uint8_t* rows, int count) override {
        if (image_) image_->write_rows(rows, count);
    }
    void trace_lines(std::string_view lines) override {
        traces_->write(lines);
        lines_ += std::count(lines.begin(), lines.end(), '\n');  // vectorised, unlike a loop of +=
    }
    void progress(int rows_done, int rows_total) override { progress_.update(rows_done, rows_total); }
    std::int64_t trace_count() const { return lines_; }

private:
    ImageWriter* image_;
    OutputFile* traces_;
    Progress& progress_;
    std::int64_t lines_ = 0;
};

// The pixels to trace, as the renderer wants them and as typed (for the size estimate).
struct Traced {
    PixelSelection selection;
    TracedPixels pixels;
};

Traced traced_pixels(const RenderOptions& options) {
    Traced traced;
    for (const std::string& text : options.trace_pixels) {
        const cli::Pixel pixel = cli::parse_pixel(text, "--trace-pixel", options.w);
        traced.selection.add_pixel(pixel.i, pixel.j);
        traced.pixels.pixels.emplace_back(pixel.i, pixel.j);
    }
    for (const std::string& text : options.trace_regions) {
        const PixelRegion region = cli::parse_region(text, "--trace-region", options.w);
        traced.selection.add_region(region);
        traced.pixels.regions.push_back(region);
    }
    if (options.traces_file.empty()) {
        if (!traced.selection.empty())
            throw UsageError("--trace-pixel and --trace-region choose pixels for --traces FILE");
        return traced;
    }
    if (traced.selection.empty()) {
        traced.selection = PixelSelection::all();
        traced.pixels.all = true;
    }
    return traced;
}

// 1.2 kB, 150 MB, 2.5 GB: SI units, as disk sizes are sold.
std::string byte_size(double bytes) {
    if (bytes < 1000) return fmt::format("{:.0f} bytes", bytes);
    const char* units[] = {"kB", "MB", "GB", "TB", "PB"};
    int unit = 0;
    bytes /= 1000;
    while (bytes >= 999.5 && unit < 4) {
        bytes /= 1000;
        ++unit;
    }
    return bytes < 9.95 ? fmt::format("{:.1f} {}", bytes, units[unit]) : fmt::format("{:.0f} {}", bytes, units[unit]);
}

// A device or a FIFO named without an extension (-o /dev/null) gets PNG,
// as does standard output; a file needs .png, .pgm or .ppm.
ImageFormat image_format(const RenderOptions& options, const OutputTarget& target) {
    ImageFormat format = ImageFormat::png;
    if (target.kind == OutputKind::file) {
        format = image_format_for_path(options.output);
    } else {
        try {
            format = image_format_for_path(options.output);
        } catch (const UsageError&) {
            format = ImageFormat::png;
        }
    }
    if (options.plain) {
        if (format != ImageFormat::pgm && format != ImageFormat::ppm)
            throw UsageError(fmt::format("--plain writes plain PGM (P2) or PPM (P3); it needs an -o FILE ending in "
                                         ".pgm or .ppm, not '{}'",
                                         options.output));
        format = format == ImageFormat::pgm ? ImageFormat::pgm_plain : ImageFormat::ppm_plain;
    }
    return format;
}

void check_scale(const RenderOptions& options) {
    // w blocks of `scale` pixels, and with --grid the w − 1 lines between them.
    // With --labels or --legend the frame takes up to frame_allowance more.
    const int lines = options.grid ? options.w - 1 : 0;
    const int room = max_image_side - (options.labels || options.legend ? frame_allowance : 0);
    const int largest = (room - lines) / options.w;
    if (largest < 1)
        throw UsageError(fmt::format("--grid at --w {} would make an image wider than {} pixels", options.w,
                                     max_image_side));
    if (options.scale < 1 || options.scale > largest)
        throw UsageError(fmt::format("--scale must be between 1 and {} at --w {}{} (the image may be at most {} "
                                     "pixels wide), not {}",
                                     largest, options.w, options.grid ? " with --grid" : "", max_image_side,
                                     options.scale));
}

// --range LO,HI: two finite numbers, 0 < LO < HI.
std::pair<double, double> parse_range(const std::string& text) {
    const auto comma = text.find(',');
    auto number = [](const std::string& part, double& value) {
        if (part.empty() || part.find_first_of(" \t\n") != std::string::npos) return false;
        char* end = nullptr;
        value = std::strtod(part.c_str(), &end);
        return end == part.c_str() + part.size() && std::isfinite(value);
    };
    double low = 0, high = 0;
    if (comma == std::string::npos || !number(text.substr(0, comma), low) || !number(text.substr(comma + 1), high) ||
        !(0 < low && low < high))
        throw UsageError(ui_message("map_range_invalid", {{"text", printable(text)}}));
    return {low, high};
}

// The image's width at `scale`: the pane and, with --labels, the left margin.
long framed_image_width(const RenderOptions& options, int scale) {
    const long side = scaled_side(options.w, scale, options.grid);
    return side + (options.labels ? pane_labels(options.w, scale, options.grid).left_width : 0);
}

// --legend must fit the image's width: exit 2 naming the smallest --scale that fits.
void check_legend_width(const RenderOptions& options, const Legend& legend) {
    const LegendNeed need = legend_need(legend);
    const long width = framed_image_width(options, options.scale);
    if (width >= need.width) return;
    const int lines = options.grid ? options.w - 1 : 0;
    const int largest = (max_image_side - frame_allowance - lines) / options.w;
    for (int scale = options.scale + 1; scale <= largest; ++scale) {
        if (framed_image_width(options, scale) >= need.width)
            throw UsageError(ui_message("legend_too_narrow", {{"width", std::to_string(width)},
                                                              {"needed", std::to_string(need.width)},
                                                              {"widest", need.widest},
                                                              {"scale", std::to_string(scale)}}));
    }
    throw UsageError(ui_message("legend_too_narrow_at_max", {{"width", std::to_string(width)},
                                                             {"needed", std::to_string(need.width)},
                                                             {"widest", need.widest}}));
}

std::string image_description(const RenderOptions& options, const Scene& scene, const MapKernel* map, int width,
                              int height) {
    const std::string what = map ? fmt::format("{}, ", map->description()) : std::string();
    if (options.scale == 1 && !options.grid && width == options.w && height == options.w)
        return ui_message("render_image", {{"what", what}, {"w", std::to_string(options.w)}, {"scene", scene.name}});
    return ui_message("render_image_scaled", {{"what", what},
                                              {"width", std::to_string(width)},
                                              {"height", std::to_string(height)},
                                              {"w", std::to_string(options.w)},
                                              {"scale", std::to_string(options.scale)},
                                              {"grid", options.grid ? ui_message("render_with_grid") : ""},
                                              {"scene", scene.name}});
}

// A map category's name in the run's language: the branches and notes by
// their names (messages_words.json), the error and digits-lost map's own
// words as their legends name them; a range of values is already worded.
std::string category_text(const std::string& name) {
    for (const char* branch : {"miss", "dark", "lit", "shadowed", "non-finite"})
        if (name == branch) return ui_message("branch_name_" + name);
    if (name == "tangent") return ui_message("note_name_tangent");
    if (name == "behind the eye") return ui_message("note_name_behind");
    if (name == "exact") return ui_message("map_legend_exact");
    if (name == "branch differs") return ui_message("map_legend_branch_differs");
    if (name == "none lost") return ui_message("map_legend_none_lost");
    return name;
}

// A map's categories on stderr, each with its count and its first pixel in
// row order, to trace: the legend a teacher reads beside the image.
void print_map_stats(const MapKernel& map, const RenderOptions& options) {
    const MapTally tally = map.tally();
    const std::string command = fmt::format(
        "promyk trace --pixel I,J --w {}{}{}{}{}", options.w,
        options.scene_file.empty() ? "" : " --scene " + printable(options.scene_file),
        options.real == RealType::double_ ? "" : fmt::format(" --real {}", real_type_name(options.real)),
        options.formula == Formula::article ? "" : fmt::format(" --formula {}", formula_name(options.formula)),
        options.spp == 1 ? "" : fmt::format(" --spp {}", options.spp));
    fmt::print(stderr, "{}\n",
               wrap_text(ui_message("map_stats_heading", {{"what", map.description()}, {"command", command}}), 4));
    for (const MapTally::Category& category : tally.categories) {
        if (category.count == 0 && !category.listed_if_empty) continue;
        const MessageArgs args = {{"name", category_text(category.name)},
                                  {"pixels", counted(category.count, "render_pixels")},
                                  {"i", std::to_string(category.first_i)},
                                  {"j", std::to_string(category.first_j)}};
        fmt::print(stderr, "{}\n", ui_message(category.count == 0 ? "map_stats_category" : "map_stats_category_first", args));
    }
    if (tally.has_largest)
        fmt::print(stderr, "{}\n",
                   ui_message("map_stats_largest",
                              {{"value", local_number_text(fmt::format("{:.3g}", tally.largest), ui_language())},
                               {"i", std::to_string(tally.largest_i)},
                               {"j", std::to_string(tally.largest_j)}}));
    if (map.kind() == MapKind::error && map.colour_scale()) {
        const Language language = ui_language();
        fmt::print(stderr, "{}\n",
                   ui_message("map_stats_range",
                              {{"low", legend_number(map.colour_scale()->low(), language)},
                               {"high", legend_number(map.colour_scale()->high(), language)},
                               {"how", ui_message(options.range.empty() ? "map_range_of_run" : "map_range_given")}}));
    }
}

// What the engine did, on stderr: the stages it ran, rays by kind,
// intersection tests by shape, pixels by branch.
void print_stats(const RenderStats& stats, const Scene& scene, int spp) {
    std::string stages;
    for (const std::string& id : effect_ids(scene, plan_stages(scene))) stages += (stages.empty() ? "" : ", ") + id;
    const auto line = [](const std::string& text) { fmt::print(stderr, "{}\n", wrap_text(text, 4)); };
    line(ui_message("render_stats_heading"));
    line(ui_message("render_stats_stages", {{"stages", stages}}));
    line(ui_message("render_stats_rays", {{"primary", std::to_string(stats.primary_rays)},
                                          {"per", spp == 1 ? ui_message("render_stats_one") : std::to_string(spp)},
                                          {"shadow", std::to_string(stats.shadow_rays)}}));
    line(ui_message("render_stats_tests",
                    {{"spheres", std::to_string(stats.sphere_tests)}, {"planes", std::to_string(stats.plane_tests)}}));
    if (stats.skipped > 0) line(ui_message("render_stats_skipped", {{"count", std::to_string(stats.skipped)}}));
    line(ui_message("render_stats_pixels", {{"miss", std::to_string(stats.count(Branch::miss))},
                                            {"dark", std::to_string(stats.count(Branch::dark))},
                                            {"lit", std::to_string(stats.count(Branch::lit))},
                                            {"shadowed", std::to_string(stats.count(Branch::shadowed))},
                                            {"non_finite", std::to_string(stats.count(Branch::non_finite))}}));
    if (spp > 1) line(ui_message("render_stats_disagree", {{"count", std::to_string(stats.disagreeing)}}));
}

int run_render(const RenderOptions& options) {
    check_scale(options);
    if (options.legend && options.map.empty()) throw UsageError(ui_message("legend_without_map"));
    std::optional<std::pair<double, double>> error_range;
    if (!options.range.empty()) {
        if (options.map != "error") throw UsageError(ui_message("map_range_without_error_map"));
        error_range = parse_range(options.range);
    }
    if (options.map == "error" && !error_range && options.w > max_w_for_run_range)
        throw UsageError(ui_message("map_range_needed", {{"w", std::to_string(options.w)},
                                                         {"max", std::to_string(max_w_for_run_range)}}));
    const Traced traced = traced_pixels(options);

    // Every output is looked at before anything is computed or created.
    const OutputTarget image_target = inspect_output(options.output);
    const ImageFormat format = image_format(options, image_target);
    if (image_target.kind == OutputKind::standard_output && ::isatty(STDOUT_FILENO))
        throw UsageError("-o - would write a PNG to the terminal: redirect standard output to a file or a pipe");
    std::optional<OutputTarget> traces_target;
    if (!options.traces_file.empty()) {
        traces_target = inspect_output(options.traces_file);
        require_distinct_outputs({{"-o", image_target}, {"--traces", *traces_target}});
    }
    // Nor may an output be the scene it is made from.
    std::vector<std::pair<std::string, OutputTarget>> outputs = {{"-o", image_target}};
    if (traces_target) outputs.emplace_back("--traces", *traces_target);
    require_outputs_not_inputs(outputs, {{"--scene", options.scene_file}});

    const Scene scene = cli::load_scene_option(options.scene_file);
    // What scene check would warn of (a light inside a sphere draws a black
    // disc): said on stderr, so a surprising image has its reason beside it.
    if (!options.scene_file.empty())
        for (const std::string& warning : report_scene(scene).warnings)
            fmt::print(stderr, "{}\n", wrap_text("promyk: " + printable(ui_message("scene_warning", {{"text", warning}})), 4));
    // A coloured scene and a map need an RGB format: refused before any file is created.
    std::optional<MapKind> map_kind;
    if (!options.map.empty()) {
        map_kind = parse_map_name(options.map);
        if (format == ImageFormat::pgm || format == ImageFormat::pgm_plain)
            throw UsageError(fmt::format("{}: PGM holds grey levels only and a --map image is in colour; write .png "
                                         "or .ppm",
                                         options.output));
    }
    const int channels = map_kind ? 3 : image_channels(scene);
    check_image_format(format, channels, options.output);
    std::unique_ptr<MapKernel> map;
    if (map_kind)
        map = make_map_kernel(*map_kind, scene, options.real, options.formula, options.spp, options.w, error_range);
    if (options.legend) check_legend_width(options, map_legend(*map_kind, map->colour_scale(), ui_language()));

    // The size guard protects disks: it applies where the traces land in a
    // regular file (a path, or standard output redirected to one), not to a
    // pipe, a terminal or /dev/null.
    if (traces_target) {
        // Each pixel's trace is built whole before it is written: bounded
        // like trace's (a full trace at w = 512 is already ~150 MB, at
        // w = 2048 ~2.5 GB).
        TraceCost cost;
        cost.scene = &scene;
        cost.real = options.real;
        cost.spp = options.spp;
        require_trace_size(cost, options.max_trace_size);
        const double limit = trace_size_limit(options.max_trace_size);
        const std::int64_t pixels = count_traced_pixels(traced.pixels, options.w);
        if (traces_target->lands_in_regular_file && !options.force &&
            static_cast<double>(pixels) * trace_cost_bytes(cost) > limit) {
            const TraceSizeEstimate estimate = estimate_trace_size(scene, options.w, traced.pixels, 256, options.real,
                                                                   options.formula, options.spp);
            if (estimate.bytes() > limit) {
                const double magnitude = std::pow(10.0, std::floor(std::log10(estimate.bytes())));
                throw UsageError(ui_message(
                    "limit_traces_file_too_large",
                    {{"file", traces_target->display_name()},
                     {"estimate", byte_size_text(estimate.bytes())},
                     {"pixels", std::to_string(estimate.pixels)},
                     {"each", byte_size_text(estimate.bytes_per_trace)},
                     {"limit", byte_size_text(limit)},
                     {"enough", fmt::format("{:.0f}", std::ceil(estimate.bytes() / magnitude) * magnitude)}}));
            }
        }
    }

    // Open every output (create the temporaries) before computing.
    OutputFile image_file(image_target);
    std::optional<OutputFile> traces;
    if (traces_target) traces.emplace(*traces_target);
    const int side = static_cast<int>(scaled_side(options.w, options.scale, options.grid));
    int image_width = side, image_height = side;
    // The image writer: the pane's blocks, in a frame of numbers and a legend
    // if asked. A deferred map opens it after the render: its legend's
    // numbers come from the run.
    auto open_image = [&]() {
        Frame frame;
        if (options.labels) {
            draw_pane_labels(pane_labels(options.w, options.scale, options.grid), options.w, options.scale,
                             options.grid, channels, frame);
        }
        if (options.legend) {
            frame.bottom = draw_legend(map_legend(*map_kind, map->colour_scale(), ui_language()),
                                       framed_width(frame, side), channels);
        }
        image_width = framed_width(frame, side);
        image_height = framed_height(frame, side);
        std::unique_ptr<ImageWriter> writer = open_image_writer(image_file, format, image_width, image_height, channels);
        if (!frame.empty()) writer = frame_image_writer(std::move(writer), std::move(frame), side, side);
        if (side != options.w) writer = scale_image_writer(std::move(writer), options.w, options.scale, options.grid);
        return writer;
    };
    const bool deferred = map && map->deferred();
    std::unique_ptr<ImageWriter> image;
    if (!deferred) image = open_image();

    std::int64_t trace_count = 0;
    RenderStats stats;
    {
        Progress progress("promyk render", "rows");
        FileSink sink(image.get(), traces ? &*traces : nullptr, progress);
        // Every branch counted only for --stats (the non-finite warning's count always).
        const RenderSettings settings{options.w,       options.threads, options.real,
                                      options.formula, options.spp,     options.stats};
        if (map)
            render(*map, scene, settings, traced.selection, sink, &stats);
        else
            render(scene, settings, traced.selection, sink, &stats);
        trace_count = sink.trace_count();
    }
    if (deferred) {
        // The scale from the run's own errors, then the rows in its colours.
        map->settle();
        image = open_image();
        std::vector<std::uint8_t> row(static_cast<std::size_t>(options.w) * 3);
        for (int i = 0; i < options.w; ++i) {
            throw_if_interrupted();  // colouring and compressing w rows takes seconds at w 4096
            map->replay_row(options.w, i, row.data());
            image->write_rows(row.data(), 1);
        }
    }
    image->finish();
    commit_together({&image_file, traces ? &*traces : nullptr});

    // Status on stderr: standard output carries only the product (-o -, --traces -).
    const std::string image_name =
        image_target.kind == OutputKind::standard_output ? ui_message("render_png_stdout") : printable(options.output);
    fmt::print(stderr, "{}\n",
               wrap_text(ui_message("render_wrote",
                                    {{"file", image_name},
                                     {"what", printable(image_description(options, scene, map.get(), image_width,
                                                                          image_height))}}),
                         4));
    if (traces) {
        const std::string file = traces->target().kind == OutputKind::standard_output
                                     ? ui_message("render_traces_stdout")
                                     : printable(options.traces_file);
        fmt::print(stderr, "{}\n",
                   wrap_text(ui_message("render_wrote_traces",
                                        {{"file", file},
                                         {"traces", counted(static_cast<long long>(trace_count), "render_traces")},
                                         {"size", byte_size(static_cast<double>(traces->bytes_written()))}}),
                             4));
    }
    if (const long long non_finite = stats.count(Branch::non_finite)) {
        // The render finished; these pixels' numbers overflowed (PRODUCT.md §9).
        fmt::print(stderr, "{}\n",
                   wrap_text("promyk: " + ui_message("render_non_finite",
                                                     {{"count", std::to_string(non_finite)},
                                                      {"pixels", std::to_string(static_cast<long long>(options.w) * options.w)},
                                                      {"i", std::to_string(stats.first_non_finite_i)},
                                                      {"j", std::to_string(stats.first_non_finite_j)},
                                                      {"w", std::to_string(options.w)},
                                                      {"scene", options.scene_file.empty() ? "" : " --scene " + printable(options.scene_file)}}),
                             4));
    }
    if (options.stats) {
        if (map)
            print_map_stats(*map, options);
        else
            print_stats(stats, scene, options.spp);
    }
    return 0;
}

}  // namespace

std::function<int()> setup_render(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render the scene to an image (PNG, PGM or PPM), optionally with traces");
    add_scene_option(*cmd, options->scene_file);
    cmd->add_option("-o,--output", options->output,
                    "Image file: .png for PNG, .pgm for binary PGM (P5, add --plain for plain PGM, P2;\n"
                    "grey scenes only), .ppm for binary PPM (P6, add --plain for plain PPM, P3),\n"
                    "or - for PNG on standard output; a coloured scene is written in RGB")
        ->type_name("FILE")
        ->check(non_empty())
        ->capture_default_str();
    cmd->add_flag("--stats", options->stats,
                  "Print what the engine did on stderr: the stages it ran, rays cast (primary, shadow),\n"
                  "intersection tests (sphere, plane), pixels by branch");
    cmd->add_flag("--plain", options->plain,
                  "With a .pgm or .ppm output: write plain PGM (P2) or plain PPM (P3), numbers as text,\n"
                  "instead of binary (P5, P6)");
    add_w_option(*cmd, options->w);
    cmd->add_option("--scale", options->scale,
                    "Draw each pixel as an N × N block, to show a small pane (w · N at most 32768)")
        ->type_name("N")
        ->check(whole_number(1, cli::max_w))
        ->capture_default_str();
    cmd->add_flag("--grid", options->grid,
                  "Draw 1-pixel lines between the pixels' blocks (see --scale), each line pixel black,\n"
                  "white or grey, whichever stands out most from the blocks it borders");
    cmd->add_flag("--labels", options->labels,
                  "Number the rows (i, left margin) and columns (j, top margin), each number centred\n"
                  "on its row or column; the image grows by the margins. When the numbers would touch\n"
                  "(a small --scale, a big --w) only every k-th row and column is numbered, k the\n"
                  "first of 1, 2, 5, 10, 20, 50, ... that fits; without --scale that is every 10th\n"
                  "row and column or fewer");
    add_threads_option(*cmd, options->threads);
    add_real_option(*cmd, options->real);
    add_formula_option(*cmd, options->formula);
    add_spp_option(*cmd, options->spp);
    cmd->add_option("--traces", options->traces_file,
                    "Also write one JSON trace per pixel to FILE, or to standard output with -\n"
                    "(JSON Lines, rows in order); all pixels unless --trace-pixel or --trace-region choose some")
        ->type_name("FILE")
        ->check(non_empty());
    cmd->add_option("--trace-pixel", options->trace_pixels, "Trace pixel I,J (repeatable)")
        ->type_name("I,J")
        ->allow_extra_args(false);
    cmd->add_option("--trace-region", options->trace_regions,
                    "Trace the pixels of rectangle I0,J0,I1,J1, corners included (repeatable)")
        ->type_name("I0,J0,I1,J1")
        ->allow_extra_args(false);
    cmd->add_flag("--force", options->force,
                  "Write a trace file even if it would be larger than the trace limit (250 MB)");
    add_max_trace_size_option(*cmd, options->max_trace_size);
    cmd->add_option("--map", options->map,
                    "Draw a per-pixel quantity instead of the shading, in colour (.png or .ppm; docs/maps.md):\n"
                    "branch: the branch taken (miss, dark, lit, shadowed, non-finite) and the notes tangent\n"
                    "and behind the eye, in Okabe-Ito colours; error: |I - I_ref| against quad with the\n"
                    "geometric formula on a log scale from the run's smallest to its largest non-zero\n"
                    "error in whole decades (or --range), white where exact, vermillion where the\n"
                    "branch differs; digits-lost: the most significant digits any step loses to\n"
                    "cancellation (as trace marks them), one colour step a digit, white where none.\n"
                    "--real, --formula and --spp choose what is mapped; --stats counts each category,\n"
                    "names its first pixel and prints the error map's scale")
        ->type_name("branch|error|digits-lost")
        ->check(one_of("--map", {"branch", "error", "digits-lost"}));
    cmd->add_flag("--legend", options->legend,
                  "With --map: add a legend strip below the map, as wide as the image: each colour\n"
                  "with its name in the run's language, the colour bar with its numbers. If the\n"
                  "image is too narrow for its longest name, exit 2 naming the --scale that fits");
    cmd->add_option("--range", options->range,
                    "With --map error: fix the colour scale to LO .. HI (0 < LO < HI; errors outside\n"
                    "are drawn at the nearest end), so that two runs' maps compare colour for colour.\n"
                    "Needed above --w 4096")
        ->type_name("LO,HI");
    cmd->footer("Intensity maps to 8-bit grey as round(clamp(v, 0, 1) * 255).");
    return [options] { return run_render(*options); };
}

}  // namespace promyk::app
