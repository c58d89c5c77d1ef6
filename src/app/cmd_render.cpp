// promyk render: the whole image, and optionally JSON Lines traces beside it.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/progress.hpp"
#include "render/image_writer.hpp"
#include "render/renderer.hpp"
#include "util/atomic_file.hpp"
#include "util/errors.hpp"

namespace promyk::app {

namespace {

struct RenderOptions {
    std::string scene_file;
    std::string output = "promyk.png";
    int w = 512;
    int threads = 0;
    std::string traces_file;
    std::vector<std::string> trace_pixels;
    std::vector<std::string> trace_regions;
};

// Streams rows into the image and trace lines into the traces file; both
// are temporary files until commit, so a failed render leaves nothing.
class FileSink final : public RenderSink {
public:
    FileSink(ImageWriter& image, AtomicFile* traces, Progress& progress)
        : image_(image), traces_(traces), progress_(progress) {}
    void image_rows(const std::uint8_t* rows, int count) override { image_.write_rows(rows, count); }
    void trace_lines(std::string_view lines) override { traces_->write(lines); }
    void progress(int rows_done, int rows_total) override { progress_.update(rows_done, rows_total); }

private:
    ImageWriter& image_;
    AtomicFile* traces_;
    Progress& progress_;
};

PixelSelection traced_pixels(const RenderOptions& options) {
    PixelSelection selection;
    for (const std::string& text : options.trace_pixels) {
        const cli::Pixel pixel = cli::parse_pixel(text, "--trace-pixel", options.w);
        selection.add_pixel(pixel.i, pixel.j);
    }
    for (const std::string& text : options.trace_regions)
        selection.add_region(cli::parse_region(text, "--trace-region", options.w));
    if (options.traces_file.empty()) {
        if (!selection.empty()) throw UsageError("--trace-pixel and --trace-region choose pixels for --traces FILE");
        return selection;
    }
    return selection.empty() ? PixelSelection::all() : selection;
}

int run_render(const RenderOptions& options) {
    if (!options.traces_file.empty() && options.traces_file == options.output)
        throw UsageError("--traces and -o name the same file");
    const PixelSelection traced = traced_pixels(options);
    const Scene scene = cli::load_scene_option(options.scene_file);
    article_world(scene);  // reject a scene the engine cannot trace before creating any file

    std::unique_ptr<ImageWriter> image = open_image_writer(options.output, options.w, options.w);
    std::optional<AtomicFile> traces;
    if (!options.traces_file.empty()) traces.emplace(options.traces_file);
    {
        Progress progress("promyk render", "rows");
        FileSink sink(*image, traces ? &*traces : nullptr, progress);
        render(scene, {options.w, options.threads}, traced, sink);
    }
    image->commit();
    if (traces) traces->commit();
    fmt::print("wrote {} ({} x {} pixels, scene \"{}\")\n", options.output, options.w, options.w, scene.name);
    if (traces) fmt::print("wrote {} (JSON Lines, one trace per pixel)\n", options.traces_file);
    return 0;
}

}  // namespace

std::function<int()> setup_render(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render the scene to an image (PNG or PGM), optionally with traces");
    add_scene_option(*cmd, options->scene_file);
    cmd->add_option("-o,--output", options->output, "Image file: .png, or .pgm for the plain format")
        ->type_name("FILE")
        ->check(non_empty())
        ->capture_default_str();
    add_w_option(*cmd, options->w);
    add_threads_option(*cmd, options->threads);
    cmd->add_option("--traces", options->traces_file,
                    "Also write one JSON trace per pixel to FILE (JSON Lines, rows in order);\n"
                    "all pixels unless --trace-pixel or --trace-region choose some")
        ->type_name("FILE")
        ->check(non_empty());
    cmd->add_option("--trace-pixel", options->trace_pixels, "Trace pixel I,J (repeatable)")
        ->type_name("I,J")
        ->allow_extra_args(false);
    cmd->add_option("--trace-region", options->trace_regions,
                    "Trace the pixels of rectangle I0,J0,I1,J1, corners included (repeatable)")
        ->type_name("I0,J0,I1,J1")
        ->allow_extra_args(false);
    cmd->footer("Intensity maps to 8-bit grey as round(clamp(v, 0, 1) * 255).");
    return [options] { return run_render(*options); };
}

}  // namespace promyk::app
