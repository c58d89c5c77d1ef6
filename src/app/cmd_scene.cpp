// promyk scene check FILE, promyk scene dump: scenes as files.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "render/scene_report.hpp"
#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "util/printable.hpp"
#include "util/standard_output.hpp"
#include "util/wrap.hpp"

namespace promyk::app {

namespace {

void print_list(std::string& out, const std::string& heading, const std::vector<std::string>& items) {
    if (items.empty()) return;
    out += fmt::format("{}:\n", heading);
    // Each item wrapped to 80 columns under its own text.
    for (const std::string& item : items) out += wrap_text("  - " + printable(item), 4) + "\n";
}

int run_check(const std::string& file) {
    const Scene scene = load_scene_file(file);
    const SceneReport report = report_scene(scene);
    std::string out = wrap_text(ui_message("scene_check_valid", {{"file", printable(file)}}), 2) + "\n";
    print_list(out, ui_message("scene_check_contains"), report.contents);
    print_list(out, ui_message("scene_check_runs"), report.stages);
    print_list(out, ui_message("scene_check_skips"), report.skipped);
    print_list(out, ui_message("scene_check_warnings"), report.warnings);
    write_standard_output(out);
    return 0;
}

int run_dump(const std::string& scene_file, bool all) {
    const SceneDefaults defaults = all ? SceneDefaults::written : SceneDefaults::omitted;
    write_standard_output(scene_to_json(cli::load_scene_option(scene_file), defaults));
    return 0;
}

}  // namespace

std::function<int()> setup_scene(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("scene", "Scene files: check one, or print the article's scene to start from");
    cmd->require_subcommand(1);
    auto file = std::make_shared<std::string>();
    auto dump_file = std::make_shared<std::string>();
    auto dump_all = std::make_shared<bool>(false);
    CLI::App* check = cmd->add_subcommand(
        "check", "Validate a scene file; say what it contains, what the engine runs for it and what it skips");
    check->add_option("FILE", *file, "The scene file (JSON)")->type_name("")->required()->check(non_empty());
    CLI::App* dump = cmd->add_subcommand(
        "dump", "Print a scene as a file in the canonical form (the article's unless --scene)");
    add_scene_option(*dump, *dump_file);
    dump->add_flag("--all", *dump_all,
                   "Also write the fields that hold their defaults (\"shadows\": false, \"planes\": [], "
                   "\"materials\": [], each light's \"colour\": [1, 1, 1]), so every knob is in sight; without it "
                   "they are left out (an object without \"material\" has the default one either way)");
    dump->footer(
        "Example: promyk scene dump --all > my_scene.json   (then edit it and pass --scene my_scene.json)\n"
        "The fields, their defaults and their limits: lessons/scenes/README.md");
    return [check, file, dump_file, dump_all] {
        return check->parsed() ? run_check(*file) : run_dump(*dump_file, *dump_all);
    };
}

}  // namespace promyk::app
