// promyk trace: one pixel's whole derivation, as a table or as JSON.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "util/edit_distance.hpp"
#include "trace/messages.hpp"
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/trace_limit.hpp"
#include "render/scene_report.hpp"
#include "render/trace_pixel.hpp"
#include "trace/messages.hpp"
#include "trace/trace_compare.hpp"
#include "trace/trace_text.hpp"
#include "util/errors.hpp"
#include "util/printable.hpp"
#include "util/text.hpp"
#include "util/wrap.hpp"
#include "util/standard_output.hpp"

namespace promyk::app {

namespace {

struct TraceOptions {
    std::string pixel = "3,4";
    int w = 8;
    std::string scene_file;
    std::string format = "text";
    bool wide = false;
    bool explain = false;
    RealType real = RealType::double_;
    std::string compare;  // "float,double,quad": trace in each, side by side
    Formula formula = Formula::article;
    int spp = 1;
    std::string max_trace_size;  // --max-trace-size; empty: the default limit
};

// The types of --compare, least precise first (the last is the reference).
std::vector<RealType> compared_types(const std::string& list) {
    const std::vector<std::pair<std::string, RealType>> known = {{"float", RealType::float_},
                                                                 {"double", RealType::double_},
                                                                 {"long-double", RealType::long_double},
                                                                 {"quad", RealType::quad_}};
    std::vector<bool> chosen(known.size(), false);
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name(trim(std::string_view(list).substr(start, comma - start)));
        const auto it = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.first == name; });
        if (it == known.end())
            throw UsageError(cli::choice_problem(name, "--compare", {"float", "double", "long-double", "quad"}));
        chosen[static_cast<std::size_t>(it - known.begin())] = true;
        start = comma + 1;
    }
    std::vector<RealType> types;
    for (std::size_t k = 0; k < known.size(); ++k)
        if (chosen[k]) types.push_back(known[k].second);
    if (types.size() < 2) throw UsageError(ui_message("cli_compare_types"));
    return types;
}

int run_trace(const TraceOptions& options) {
    const cli::Pixel pixel = cli::parse_pixel(options.pixel, "--pixel", options.w);
    const Scene scene = cli::load_scene_option(options.scene_file);
    const Language language = ui_language();
    // A scene too small for float's unit vectors: the reason beside a float
    // trace whose K̂ comes out short (double and wider compute it right).
    bool float_traced = options.real == RealType::float_;
    if (!options.compare.empty()) {
        const std::vector<RealType> types = compared_types(options.compare);
        float_traced = std::find(types.begin(), types.end(), RealType::float_) != types.end();
    }
    if (float_traced)
        if (const std::optional<std::string> warning = float_range_warning(scene))
            fmt::print(stderr, "{}\n",
                       wrap_text("promyk: " + printable(ui_message("scene_warning", {{"text", *warning}})), 4));
    // The trace's size, estimated from the scene before anything is traced.
    TraceCost cost;
    cost.scene = &scene;
    cost.real = options.real;
    cost.spp = options.spp;
    cost.text = options.format != "json";
    if (!options.compare.empty()) {
        const std::vector<RealType> types = compared_types(options.compare);
        cost.real = RealType::quad_;  // the larger size of a type other than double, for each
        cost.traces = static_cast<int>(types.size());
        require_trace_size(cost, options.max_trace_size);
        std::vector<PixelTrace> traces;
        for (const RealType type : types)
            traces.push_back(trace_pixel(scene, options.w, pixel.i, pixel.j, type, options.formula, options.spp));
        std::string out;
        if (options.format == "json") {
            for (const PixelTrace& trace : traces) {
                append_trace_json(out, trace);
                out += '\n';
            }
        } else {
            out = format_comparison(traces, builtin_vocabulary(), language);
        }
        write_standard_output(out);
        return 0;
    }
    require_trace_size(cost, options.max_trace_size);
    const PixelTrace trace = trace_pixel(scene, options.w, pixel.i, pixel.j, options.real, options.formula, options.spp);
    std::string out;
    if (options.format == "json") {
        append_trace_json(out, trace);
        out += '\n';
    } else {
        TraceTextOptions text;
        text.layout = options.wide ? TraceLayout::wide : TraceLayout::narrow;
        text.language = language;
        text.explain = options.explain;
        text.digits = shown_digits(0);  // the trace is the record: every digit unless --digits
        out = format_trace_text(trace, builtin_vocabulary(), text);
    }
    write_standard_output(out);
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
    cmd->add_option("--compare", options->compare,
                    "Trace the pixel in several types and print the steps side by side, each value marked\n"
                    "(|) where its digits stop agreeing with the most precise type's (e.g. float,double,quad);\n"
                    "with --format json, one trace a line")
        ->type_name("TYPES")
        ->check(non_empty())
        ->excludes("--real");
    add_formula_option(*cmd, options->formula);
    add_spp_option(*cmd, options->spp);
    add_max_trace_size_option(*cmd, options->max_trace_size);
    add_scene_option(*cmd, options->scene_file);
    add_format_option(*cmd, options->format, {"text", "json"}, "text: an aligned table; json: the trace as one JSON line");
    cmd->add_flag("--wide", options->wide,
                  "text: one row a step (symbol, formula, value side by side; about 140 columns)\n"
                  "instead of the default layout that fits 80 columns");
    cmd->add_flag("--explain", options->explain, "text: under each formula, what the quantity means");
    cmd->footer(
        "Example: promyk trace --pixel 3,4 --w 8   (at w = 8, (0,0) misses, (5,1) is on the dark side, (3,4) is lit)");
    return [options] { return run_trace(*options); };
}

}  // namespace promyk::app
