#include "app/common_options.hpp"

namespace promyk::app {

CLI::Option* add_scene_option(CLI::App& cmd, std::string& scene_file) {
    return cmd.add_option("--scene", scene_file, "Scene file (JSON); default: the article's built-in scene")
        ->type_name("FILE");
}

CLI::Option* add_w_option(CLI::App& cmd, int& w) {
    return cmd.add_option("--w", w, "Pane size: w x w pixels")->type_name("N")->capture_default_str();
}

}  // namespace promyk::app
