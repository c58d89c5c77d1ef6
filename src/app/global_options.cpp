#include "app/global_options.hpp"

#include <optional>

#include "app/cli_values.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "util/errors.hpp"

namespace promyk::app {

namespace {

// The value of `option` if args[k] is it ("--lang pl" or "--lang=pl"),
// erasing what it took from args; nothing if args[k] is another argument.
std::optional<std::string> take(std::vector<std::string>& args, std::size_t k, const std::string& option) {
    const std::string& arg = args[k];
    if (arg == option) {
        if (k + 1 >= args.size())
            throw UsageError(ui_message("cli_missing_value", {{"option", option}}));
        std::string value = args[k + 1];
        args.erase(args.begin() + static_cast<long>(k), args.begin() + static_cast<long>(k) + 2);
        return value;
    }
    if (arg.compare(0, option.size() + 1, option + "=") == 0) {
        std::string value = arg.substr(option.size() + 1);
        args.erase(args.begin() + static_cast<long>(k));
        return value;
    }
    return std::nullopt;
}

// Every value of `option` in args (the last one counts), removed from args.
std::optional<std::string> take_all(std::vector<std::string>& args, const std::string& option) {
    std::optional<std::string> last;
    for (std::size_t k = 0; k < args.size() && args[k] != "--";) {
        if (auto value = take(args, k, option))
            last = std::move(value);
        else
            ++k;
    }
    return last;
}

}  // namespace

void take_global_options(std::vector<std::string>& args) {
    // The language first: the other option's errors are worded in it.
    if (const auto lang = take_all(args, "--lang")) {
        const std::string problem = cli::choice_problem(*lang, "--lang", {"pl", "en"});
        if (!problem.empty()) throw UsageError(problem);
        set_ui_language(*parse_language(*lang));
    }
    if (const auto digits = take_all(args, "--digits"))
        set_chosen_digits(cli::parse_whole_number(*digits, "--digits", min_digits, max_digits));
}

void describe_global_options(CLI::App& app) {
    // Never parsed (take_global_options removed them): the targets only
    // give CLI11 something to describe.
    static std::string lang, digits;
    app.add_option("--lang", lang,
                   "The language of everything this run prints but --help (which stays English):\n"
                   "Polish or English (default: Polish when LC_ALL, LC_MESSAGES or LANG starts with pl)")
        ->type_name("pl|en")
        ->group("Options of every command");
    app.add_option("--digits", digits,
                   "Significant digits shown; JSON, answer checking and diff stay exact; default: trace\n"
                   "every digit, lessons and worksheets 4")
        ->type_name("N")
        ->group("Options of every command");
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) describe_global_options(*sub);
}

}  // namespace promyk::app
