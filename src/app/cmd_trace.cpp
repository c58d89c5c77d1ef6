// promyk trace: one pixel's whole derivation, as a table or as JSON.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "render/trace_pixel.hpp"
#include "trace/trace_text.hpp"

namespace promyk::app {

namespace {

struct TraceOptions {
    std::string pixel = "3,4";
    int w = 8;
    std::string scene_file;
    std::string format = "text";
    bool wide = false;
    bool explain = false;
    std::string lang;  // empty: from LANG
    RealType real = RealType::double_;
    Formula formula = Formula::article;
};

int run_trace(const TraceOptions& options) {
    const cli::Pixel pixel = cli::parse_pixel(options.pixel, "--pixel", options.w);
    const Scene scene = cli::load_scene_option(options.scene_file);
    const PixelTrace trace = trace_pixel(scene, options.w, pixel.i, pixel.j, options.real, options.formula);
    std::string out;
    if (options.format == "json") {
        append_trace_json(out, trace);
        out += '\n';
    } else {
        TraceTextOptions text;
        text.layout = options.wide ? TraceLayout::wide : TraceLayout::narrow;
        text.language = options.lang.empty() ? language_from_environment() : *parse_language(options.lang);
        text.explain = options.explain;
        out = format_trace_text(trace, builtin_vocabulary(), text);
    }
    std::fputs(out.c_str(), stdout);
    return 0;
}

}  // namespace

std::function<int()> setup_trace(CLI::App& app) {
    auto options = std::make_shared<TraceOptions>();
    CLI::App* cmd = app.add_subcommand("trace", "Trace one pixel and print every quantity of the article's derivation");
    cmd->add_option("--pixel", options->pixel, "Pixel I,J: row i from the top, column j from the left")
        ->type_name("I,J")
        ->capture_default_str();
    add_w_option(*cmd, options->w);
    add_real_option(*cmd, options->real);
    add_formula_option(*cmd, options->formula);
    add_scene_option(*cmd, options->scene_file);
    cmd->add_option("--format", options->format, "text: an aligned table; json: the trace as one JSON line")
        ->check(CLI::IsMember({"text", "json"}))
        ->option_text("text|json (default: text)");
    cmd->add_flag("--wide", options->wide,
                  "text: one row a step (symbol, formula, value side by side; about 140 columns)\n"
                  "instead of the default layout that fits 80 columns");
    cmd->add_option("--lang", options->lang, "text: pl or en (default: Polish when LANG starts with pl)")
        ->check(CLI::IsMember({"pl", "en"}))
        ->option_text("pl|en");
    cmd->add_flag("--explain", options->explain, "text: under each formula, what the quantity means");
    cmd->footer(
        "Example: promyk trace --pixel 3,4 --w 8   (at w = 8, (0,0) misses, (5,1) is on the dark side, (3,4) is lit)");
    return [options] { return run_trace(*options); };
}

}  // namespace promyk::app
