#include "app/cli_errors.hpp"

#include <vector>

#include "app/cli_values.hpp"
#include "trace/messages.hpp"
#include "util/printable.hpp"

namespace promyk::app {

namespace {

// The deepest command the parser entered.
const CLI::App& deepest(const CLI::App& app) {
    const CLI::App* command = &app;
    for (auto entered = command->get_subcommands(); !entered.empty(); entered = command->get_subcommands())
        command = entered.front();
    return *command;
}

// The text of `what` after `prefix` and before `suffix` (both must be there), or empty.
std::string between(const std::string& what, const std::string& prefix, const std::string& suffix) {
    const std::size_t start = what.find(prefix);
    if (start == std::string::npos) return "";
    const std::size_t from = start + prefix.size();
    const std::size_t end = suffix.empty() ? what.size() : what.find(suffix, from);
    return end == std::string::npos ? "" : what.substr(from, end - from);
}

// Every name a command's options answer to ("--pixel", "-o", "--help").
std::vector<std::string> option_names(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

std::string extra_argument_message(const std::string& argument, const CLI::App& command, const std::string& path) {
    if (argument.size() < 2 || argument[0] != '-')
        return ui_message("cli_extra_argument", {{"argument", printable(argument)}, {"command", path}});
    const std::string option = argument.substr(0, argument.find('='));
    const std::string suggestion = cli::closest_name(option, option_names(command));
    if (suggestion.empty())
        return ui_message("cli_unknown_option", {{"option", printable(option)}, {"command", path}});
    return ui_message("cli_unknown_option_suggest",
                      {{"option", printable(option)}, {"command", path}, {"suggestion", suggestion}});
}

std::string subcommand_names(const CLI::App& command) {
    std::string names;
    for (const CLI::App* sub : command.get_subcommands([](const CLI::App*) { return true; }))
        names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

}  // namespace

std::string command_path(const CLI::App& app) {
    std::string path = app.get_name();
    const CLI::App* command = &app;
    for (auto entered = command->get_subcommands(); !entered.empty(); entered = command->get_subcommands()) {
        command = entered.front();
        path += " " + command->get_name();
    }
    return path;
}

std::string run_help_line(const std::string& path) { return ui_message("cli_run_help", {{"command", path}}); }

std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app) {
    const std::string what = error.what();
    const CLI::App& command = deepest(app);
    const std::string path = command_path(app);
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        std::vector<std::string> extras = app.remaining(true);
        if (extras.empty()) {
            const std::string list = between(what, "expected: ", "");
            if (!list.empty()) extras.push_back(list.substr(0, list.find(' ')));
        }
        if (!extras.empty()) return extra_argument_message(extras.front(), command, path);
    } else if (dynamic_cast<const CLI::RequiredError*>(&error)) {
        if (what.rfind("A subcommand", 0) == 0 || what.rfind("Requires at least", 0) == 0)
            return ui_message("cli_command_required", {{"command", path}, {"names", subcommand_names(command)}});
        const std::string name = between(what, "", " is required");
        if (!name.empty()) return ui_message("cli_required", {{"command", path}, {"name", name}});
    } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
        const std::string option = what.substr(0, what.find(':'));
        if (what.find("missing") != std::string::npos && option != what)
            return ui_message("cli_missing_value", {{"option", option}});
    } else if (dynamic_cast<const CLI::ValidationError*>(&error)) {
        // "--real: unknown value ... for --real": our checks name the option
        // when they word the whole message; else "--w: expects ...".
        const std::size_t colon = what.find(": ");
        if (colon != std::string::npos && what.find(what.substr(0, colon), colon) != std::string::npos)
            return what.substr(colon + 2);
        return what;
    } else if (dynamic_cast<const CLI::ConversionError*>(&error)) {
        const std::string option = between(what, "Could not convert: ", " = ");
        if (!option.empty())
            return ui_message("cli_not_a_number", {{"option", option}, {"value", between(what, " = ", "")}});
    } else if (dynamic_cast<const CLI::ExcludesError*>(&error)) {
        const std::size_t at = what.find(" excludes ");
        if (at != std::string::npos)
            return ui_message("cli_excludes", {{"option", what.substr(0, at)}, {"other", what.substr(at + 10)}});
    } else if (dynamic_cast<const CLI::RequiresError*>(&error)) {
        const std::size_t at = what.find(" requires ");
        if (at != std::string::npos)
            return ui_message("cli_requires", {{"option", what.substr(0, at)}, {"other", what.substr(at + 10)}});
    }
    return what;
}

}  // namespace promyk::app
