// promyk export: one self-contained HTML page of a scene (issue 16). The page
// embeds the scene's text, the rendered image, the branch map and, if asked,
// a trace file; it computes every other pixel's trace itself, with the same
// C++ compiled to WebAssembly, so the file stays small at any w.
//
// The output rules are render's: everything is checked before anything is
// computed, a regular file is written completely or not at all, `-o -` is
// refused on a terminal.
#include <algorithm>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/accuracy_file.hpp"
#include "app/cli_values.hpp"
#include "app/trace_limit.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/web_page.hpp"
#include "render/maps.hpp"
#include "render/renderer.hpp"
#include "scene/scene_json.hpp"
#include "trace/byte_size_text.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/base64.hpp"
#include "util/errors.hpp"
#include "util/output_file.hpp"
#include "util/printable.hpp"
#include "util/wrap.hpp"

namespace promyk::app {

namespace {

// The largest pane a page embeds: the image and the branch map go in pixel by
// pixel (base64), so w = 2048 is already a page of about 11 MB.
constexpr int max_export_w = 2048;
// The largest trace file a page embeds: the browser holds it twice (the text
// and the tracer's copy), and the page must stay small enough to e-mail.
constexpr std::uintmax_t max_embedded_traces = std::uintmax_t{16} << 20;
// The largest bench file (promyk bench accuracy --json is a few kB a scene).
constexpr std::size_t max_bench_bytes = std::size_t{16} << 20;
// The largest pane whose error and digits-lost maps the page gets: each is a
// double a pixel (512 kB at 256), and the page recomputes them in its
// workers when the scene or the settings change.
constexpr int max_overlay_w = 256;

struct ExportOptions {
    std::string scene_file;
    int w = 128;
    std::string traces_file;
    std::string output = "promyk.html";
    std::string max_trace_size;  // --max-trace-size; empty: the default limit
    std::string bench_file;      // --bench: promyk bench accuracy --json's file
};

// Collects a render's rows: the image, or the branch map's colours.
class RowsSink final : public RenderSink {
public:
    explicit RowsSink(std::size_t row_bytes) : row_bytes_(row_bytes) {}
    void image_rows(const std::uint8_t* rows, int count) override {
        bytes_.append(reinterpret_cast<const char*>(rows), row_bytes_ * static_cast<std::size_t>(count));
    }
    std::string& bytes() { return bytes_; }

private:
    std::size_t row_bytes_;
    std::string bytes_;
};

// The branch atlas, one byte a pixel: the BranchCategory index, read back
// from the colours `render --map branch` draws (one definition for both).
std::string branch_map_bytes(const Scene& scene, int w) {
    const std::unique_ptr<MapKernel> map = make_map_kernel(MapKind::branch, scene, RealType::double_,
                                                           Formula::article, 1, w);
    RowsSink sink(static_cast<std::size_t>(w) * 3);
    render(*map, scene, RenderSettings{w, 0, RealType::double_, Formula::article, 1}, PixelSelection{}, sink);
    const std::string& rgb = sink.bytes();
    std::string categories(rgb.size() / 3, '\0');
    for (std::size_t p = 0; p < categories.size(); ++p) {
        const Rgb8 colour{static_cast<std::uint8_t>(rgb[3 * p]), static_cast<std::uint8_t>(rgb[3 * p + 1]),
                          static_cast<std::uint8_t>(rgb[3 * p + 2])};
        for (int c = 0; c < branch_category_count; ++c)
            if (branch_colour(static_cast<BranchCategory>(c)).rgb == colour) categories[p] = static_cast<char>(c);
    }
    return categories;
}

// A scalar map's stored value of every pixel (render/maps.hpp,
// map_stored_value), in row order, as little-endian doubles: the page
// colours them with the same C++ (map_overlay, in its wasm) and hovers them.
std::string map_values_bytes(MapKind kind, const Scene& scene, int w) {
    const std::unique_ptr<MapKernel> map = make_map_kernel(kind, scene, RealType::double_, Formula::article, 1, w,
                                                           std::pair<double, double>{1e-20, 1});
    std::string bytes;
    bytes.reserve(static_cast<std::size_t>(w) * static_cast<std::size_t>(w) * 8);
    for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) {
            const double value = map->pixel_value(w, i, j);
            std::uint64_t bits;
            std::memcpy(&bits, &value, sizeof bits);
            for (int b = 0; b < 8; ++b) bytes += static_cast<char>((bits >> (8 * b)) & 0xFF);
        }
    return bytes;
}

// The trace file's text, refused when too large to embed (with its size and
// the flags that make a smaller one).
std::string read_traces(const std::string& path) {
    std::error_code error;
    if (path != "-" && std::filesystem::is_regular_file(path, error)) {
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        if (!error && size > max_embedded_traces)
            throw InputError(path, "", ui_message("export_traces_too_large",
                                                  {{"size", byte_size_text(static_cast<double>(size))},
                                                   {"limit", byte_size_text(static_cast<double>(max_embedded_traces))}}));
    }
    return cli::read_input_file(path, "--traces reads", max_embedded_traces, "--traces");
}

// Every line must be a trace of this scene at this w: a page shows one scene.
void check_traces(const std::string& text, const std::string& path, const Scene& scene, int w) {
    const std::string hash = scene_hash(scene);
    std::size_t start = 0;
    for (long line = 1; start < text.size(); ++line) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string_view row(text.data() + start, end - start);
        start = end + 1;
        if (row.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        const std::string where = fmt::format("line {}", line);
        const nlohmann::json trace = nlohmann::json::parse(row, nullptr, false);
        if (trace.is_discarded() || !trace.is_object() || !trace.contains("scene_hash") ||
            !trace["scene_hash"].is_string() || !trace.contains("w") || !trace["w"].is_number_integer())
            throw InputError(path, where,
                             ui_message("export_traces_not_trace",
                                        {{"what", trace.is_discarded() ? "invalid JSON" : "fields missing"}}));
        const std::string file_hash = trace["scene_hash"].get<std::string>();
        const auto name = trace.find("scene");
        const std::string file_scene = name != trace.end() && name->is_string() ? name->get<std::string>() : "?";
        if (file_hash != hash)
            throw InputError(path, where, ui_message("export_traces_other_scene",
                                                     {{"file_scene", printable(file_scene)},
                                                      {"file_hash", printable(file_hash)},
                                                      {"scene", scene.name},
                                                      {"hash", hash}}));
        const long long file_w = trace["w"].get<long long>();
        if (file_w != w)
            throw InputError(path, where, ui_message("export_traces_other_w", {{"file_w", std::to_string(file_w)},
                                                                                {"w", std::to_string(w)}}));
    }
}

// The page's data as JSON inside <script type="application/json">: '<', '>'
// and '&' escaped, so no text of a scene or a file can end the element.
std::string page_data(const nlohmann::json& data) {
    // A path's bytes need not be UTF-8: such a byte becomes U+FFFD, not a crash.
    const std::string text = data.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
    std::string safe;
    safe.reserve(text.size());
    for (const char c : text) {
        if (c == '<')
            safe += "\\u003c";
        else if (c == '>')
            safe += "\\u003e";
        else if (c == '&')
            safe += "\\u0026";
        else
            safe += c;
    }
    return safe;
}

int run_export(const ExportOptions& options) {
    const std::string_view page = web_page_template();
    if (page.empty()) throw OutputError(ui_message("export_no_web", {{"missing", std::string(web_page_missing())}}));
    if (options.w > max_export_w)
        throw UsageError(ui_message("export_w_too_large",
                                    {{"w", std::to_string(options.w)}, {"max", std::to_string(max_export_w)}}));

    // Every output is looked at before anything is read or computed.
    const OutputTarget target = inspect_output(options.output);
    if (target.kind == OutputKind::standard_output && ::isatty(STDOUT_FILENO))
        throw UsageError(ui_message("export_stdout_terminal"));
    require_outputs_not_inputs({{"-o", target}}, {{"--scene", options.scene_file},
                                                  {"--traces", options.traces_file},
                                                  {"--bench", options.bench_file}});

    // The scene's own text goes into the page, so the page's tracer reads
    // exactly what --scene read here.
    std::string scene_text;
    const Scene scene = options.scene_file.empty()
                            ? article_scene()
                            : load_scene_text(scene_text = cli::read_input_file(options.scene_file, "--scene reads",
                                                                                max_scene_file_bytes, "--scene"),
                                              options.scene_file);
    // The page traces any pixel on a click: a scene whose pixel's trace is
    // above the limit is refused here, not left to the browser.
    TraceCost cost;
    cost.scene = &scene;
    require_trace_size(cost, options.max_trace_size);
    std::string traces;
    if (!options.traces_file.empty()) {
        traces = read_traces(options.traces_file);
        check_traces(traces, options.traces_file, scene, options.w);
    }
    // The bench results, checked before anything is computed (exit 3, nothing written).
    nlohmann::json bench;
    if (!options.bench_file.empty())
        bench = read_accuracy_file(
            cli::read_input_file(options.bench_file, "--bench reads", max_bench_bytes, "--bench"), options.bench_file);

    const int channels = image_channels(scene);
    RowsSink image(static_cast<std::size_t>(options.w) * static_cast<std::size_t>(channels));
    render(scene, RenderSettings{options.w, 0, RealType::double_, Formula::article, 1}, PixelSelection{}, image);

    nlohmann::json data = {
        {"format", 1},
        {"promyk", PROMYK_VERSION},
        {"lang", ui_language() == Language::pl ? "pl" : "en"},
        {"scene", scene.name},
        {"scene_hash", scene_hash(scene)},
        // What `promyk trace --scene` was given; empty: the built-in scene.
        {"scene_file", options.scene_file},
        {"scene_text", base64(scene_text)},
        {"w", options.w},
        {"channels", channels},
        {"image", base64(image.bytes())},
        {"branch_map", base64(branch_map_bytes(scene, options.w))},
        {"traces_file", options.traces_file},
        {"traces", base64(traces)},
        // The precision lab: the error and digits-lost maps of the image's
        // settings (null above max_overlay_w), and the bench results (null: none).
        {"maps", nullptr},
        {"bench_file", options.bench_file},
        {"bench", bench},
    };
    if (options.w <= max_overlay_w)
        data["maps"] = {{"real", "double"},
                        {"formula", "article"},
                        {"spp", 1},
                        {"max_w", max_overlay_w},
                        {"error", base64(map_values_bytes(MapKind::error, scene, options.w))},
                        {"digits_lost", base64(map_values_bytes(MapKind::digits_lost, scene, options.w))}};
    else
        data["maps"] = {{"max_w", max_overlay_w}};
    const std::size_t at = page.find(web_page_data_marker);
    OutputFile out(target);
    out.write(page.substr(0, at));
    out.write(page_data(data));
    out.write(page.substr(at + web_page_data_marker.size()));
    out.commit();

    const std::string file =
        target.kind == OutputKind::standard_output ? ui_message("export_stdout") : printable(options.output);
    fmt::print(stderr, "{}\n",
               wrap_text(ui_message("export_wrote", {{"file", file},
                                                     {"scene", printable(scene.name)},
                                                     {"w", std::to_string(options.w)},
                                                     {"size", byte_size_text(static_cast<double>(out.bytes_written()))}}),
                         4));
    return 0;
}

}  // namespace

std::function<int()> setup_export(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* cmd = app.add_subcommand(
        "export", "Write one self-contained web page of the scene: the image, every pixel's trace on a click");
    add_scene_option(*cmd, options->scene_file);
    add_w_option(*cmd, options->w);
    cmd->add_option("--traces", options->traces_file,
                    "Embed a trace file made by promyk render --traces (same scene and w, at most 16 MiB):\n"
                    "its pixels are marked and show the file's own values")
        ->type_name("FILE")
        ->check(non_empty());
    cmd->add_option("-o,--output", options->output, "The HTML file, or - for standard output (not a terminal)")
        ->type_name("FILE")
        ->check(non_empty())
        ->capture_default_str();
    cmd->add_option("--bench", options->bench_file,
                    "Embed the results of promyk bench accuracy --json FILE and plot them in the page: time\n"
                    "(ratio to double/article) against error, one mark per real type x formula x spp, per scene.\n"
                    "A file that is not such JSON is refused (exit 3) and nothing is written")
        ->type_name("FILE")
        ->check(non_empty());
    add_max_trace_size_option(*cmd, options->max_trace_size);
    cmd->footer(
        "The page opens from disk with no server and no network: it runs promyk's own tracer compiled to\n"
        "WebAssembly, so any pixel is traced in the browser, value for value as promyk trace. It needs\n"
        "a promyk built with emscripten and npm (.ci/install-deps); without them export exits with 4.");
    return [options] { return run_export(*options); };
}

}  // namespace promyk::app
