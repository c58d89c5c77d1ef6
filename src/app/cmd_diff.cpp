// promyk diff A B: two traces of a pixel (two real types, two formulas), or a
// trace and a student's numbers, compared step by step; exit 1 when they
// diverge beyond the tolerance.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "util/wrap.hpp"
#include "app/common_options.hpp"
#include "app/trace_limit.hpp"
#include "lesson/trace_diff.hpp"
#include "trace/messages.hpp"
#include "trace/vocabulary.hpp"
#include "util/errors.hpp"
#include "util/standard_output.hpp"

namespace promyk::app {

namespace {

struct DiffCommandOptions {
    std::string a, b;
    std::optional<double> tol;
    std::string format = "text";
    std::string max_trace_size;  // --max-trace-size; empty: the default limit
};

// Each side is read up to the trace limit (at least 128 MiB), so that any
// trace promyk builds within the limit can be compared.
DiffInput read_input(const std::string& path, Language language, const std::string& max_trace_size) {
    const std::string shown = path == "-" ? "(stdin)" : path;
    const double limit = std::max(static_cast<double>(cli::max_diff_input_bytes), trace_size_limit(max_trace_size));
    const std::size_t max_bytes = limit >= 1.8e19 ? static_cast<std::size_t>(-1) - 1 : static_cast<std::size_t>(limit);
    return {shown, read_answers(cli::read_input_file(path, "diff reads", max_bytes, "diff"), shown, builtin_vocabulary(), language,
                                diff_first_pixel, AnswerLimits{})};
}

int run_diff(const DiffCommandOptions& options) {
    if (options.a == "-" && options.b == "-")
        throw UsageError("only one of A and B can be - (standard input)");
    const Language language = ui_language();
    const DiffInput a = read_input(options.a, language, options.max_trace_size);
    const DiffInput b = read_input(options.b, language, options.max_trace_size);
    DiffOptions diff_options;
    diff_options.relative_tolerance = options.tol;
    const DiffResult result = diff_inputs(a, b, builtin_vocabulary(), diff_options, language);
    const std::string out = options.format == "json" ? diff_json(result, a, b, diff_options)
                                                     : wrap_lines(diff_report(result, a, b, diff_options,
                                                                              builtin_vocabulary(), language));
    write_standard_output(out);
    return result.first ? 1 : 0;
}

// --tol REL: a number from 0 to 1, in plain decimal or with an exponent (1e-6).
CLI::Validator relative_tolerance() {
    return CLI::Validator(
        [](std::string& text) {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || std::isspace(static_cast<unsigned char>(text[0])))
                return ui_message("cli_not_a_number", {{"option", "--tol"}, {"value", text}});
            if (!(value >= 0 && value <= 1))
                return ui_message("cli_number_range", {{"option", "--tol"}, {"min", "0"}, {"max", "1"}, {"value", text}});
            return std::string();
        },
        "", "");
}

}  // namespace

std::function<int()> setup_diff(CLI::App& app) {
    auto options = std::make_shared<DiffCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "diff", "Compare two traces of a pixel, or a trace and a student's numbers, step by step; name the first divergence");
    cmd->add_option("A", options->a,
                    "A trace (promyk trace --format json) or a student's numbers (key = value lines, a flat JSON "
                    "object); - reads standard input")
        ->required()
        ->type_name("");
    cmd->add_option("B", options->b, "The other side, in any of the same forms")->required()->type_name("");
    cmd->add_option("--tol", options->tol,
                    "A relative tolerance: steps agree when |a - b| <= REL * max(|a|, |b|)\n"
                    "(default: each step, the less precise side's precision: a trace's type\n"
                    "float 2^-24, double 2^-53, long-double 2^-64, quad 2^-113; a typed number\n"
                    "half a unit in its last digit)")
        ->type_name("REL")
        ->check(relative_tolerance());
    add_format_option(*cmd, options->format, {"text", "json"},
                      "text: a table of the digits that agree; json: the result as one JSON object");
    add_max_trace_size_option(*cmd, options->max_trace_size)
        ->description("Read each side up to SIZE bytes (default 250MB, at least 128MiB): the limit\n"
                      "promyk trace keeps to, so that its traces can be compared");
    cmd->footer(
        "Examples: promyk trace --real float --format json > a.json\n"
        "          promyk trace --real quad --format json > b.json\n"
        "          promyk diff a.json b.json        (the first step where float loses more than its precision)\n"
        "          promyk diff b.json answers.txt   (a student's C = 6,4 and t = 1,058 against the trace)\n"
        "Steps are matched by path (t, P, light[0].D, sphere[1].t) and compared as exact decimals.\n"
        "Exit codes: 0 within the tolerance at every common step, 1 a divergence,\n"
        "2 bad command line, 3 an input that cannot be read.");
    return [options] { return run_diff(*options); };
}

}  // namespace promyk::app
