#include "app/common_options.hpp"

#include <algorithm>
#include <string>

#include "app/cli_values.hpp"
#include "render/samples.hpp"
#include "trace/messages.hpp"

namespace promyk::app {

CLI::Validator whole_number(long min, long max) {
    return CLI::Validator(
        [min, max](std::string& text) { return cli::whole_number_problem(text, min, max).value_or(std::string()); },
        "", "");
}

CLI::Validator non_empty() {
    return CLI::Validator([](std::string& text) { return text.empty() ? ui_message("cli_empty_value") : std::string(); },
                          "", "");
}

CLI::Validator one_of(const std::string& option, const std::vector<std::string>& names, const std::vector<int>& values) {
    return CLI::Validator(
        [option, names, values](std::string& text) {
            std::string problem = cli::choice_problem(text, option, names);
            if (!problem.empty()) return problem;
            if (!values.empty()) {
                const auto k = static_cast<std::size_t>(std::find(names.begin(), names.end(), text) - names.begin());
                text = std::to_string(values[k]);
            }
            return std::string();
        },
        "", "");
}

std::string names_shown(const std::vector<std::string>& names) {
    std::string shown;
    for (const std::string& name : names) shown += (shown.empty() ? "" : "|") + name;
    return shown;
}

CLI::Option* add_scene_option(CLI::App& cmd, std::string& scene_file) {
    return cmd.add_option("--scene", scene_file, "Scene file (JSON); default: the article's built-in scene")
        ->type_name("FILE")
        ->check(non_empty());
}

CLI::Option* add_w_option(CLI::App& cmd, int& w) {
    return cmd.add_option("--w", w, "Pane size: w × w pixels")
        ->type_name("N")
        ->check(whole_number(1, cli::max_w))
        ->capture_default_str();
}

CLI::Option* add_threads_option(CLI::App& cmd, int& threads) {
    return cmd.add_option("--threads", threads, "Threads to use; 0 means all cores")
        ->type_name("N")
        ->check(whole_number(0, cli::max_threads))
        ->capture_default_str();
}

CLI::Option* add_real_option(CLI::App& cmd, RealType& real) {
    std::vector<std::string> names;
    std::vector<int> values;
    for (const RealType type : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_}) {
        names.emplace_back(real_type_name(type));
        values.push_back(static_cast<int>(type));
    }
    return cmd.add_option("--real", real,
                          "The type every number is computed in: float (24-bit significand), double (53, the\n"
                          "default), long-double (x87, 64) or quad (__float128, 113)")
        ->type_name(names_shown(names))
        ->transform(one_of("--real", names, values))
        ->default_str("double");
}

CLI::Option* add_format_option(CLI::App& cmd, std::string& format, const std::vector<std::string>& names,
                               const std::string& description) {
    return cmd.add_option("--format", format, description)
        ->type_name(names_shown(names))
        ->check(one_of("--format", names))
        ->default_str(names.front());
}

CLI::Option* add_formula_option(CLI::App& cmd, Formula& formula) {
    // Only the names: the text becomes the enum's number here, so a number
    // typed on the command line is refused like any other unknown word.
    std::vector<std::string> names;
    std::vector<int> values;
    for (const Formula f : all_formulas) {
        names.emplace_back(formula_name(f));
        values.push_back(static_cast<int>(f));
    }
    return cmd.add_option("--formula", formula,
                          "How the eye's rays meet a sphere: article (the article's quadratic, the default);\n"
                          "stable (roots from q = C + sign(C)·√delta and Vieta: no cancellation in the near\n"
                          "root); fma (Kahan's discriminant with fused multiply-adds, then the article's roots);\n"
                          "geometric (the discriminant from the ray's distance to the centre, Haines et al.\n"
                          "2019: keeps small far spheres). Shadow rays keep their own test")
        ->type_name(names_shown(names))
        ->transform(one_of("--formula", names, values))
        ->default_str("article");
}

CLI::Option* add_spp_option(CLI::App& cmd, int& spp) {
    const CLI::Validator square(
        [](std::string& text) {
            if (auto problem = cli::whole_number_problem(text, 1, max_spp)) return *problem;
            const int n = std::stoi(text);
            if (!valid_spp(n)) {
                const int below = spp_side(n) * spp_side(n), above = (spp_side(n) + 1) * (spp_side(n) + 1);
                return ui_message("cli_spp_square", {{"value", text},
                                                     {"below", std::to_string(below)},
                                                     {"above", std::to_string(above)}});
            }
            return std::string();
        },
        "", "");
    return cmd.add_option("--spp", spp,
                          "Samples per pixel: 1 (the default) is the pixel's centre, the article's ray; a square\n"
                          "N = n² splits the pixel into n × n cells with one sample in each, jittered by a hash of\n"
                          "(i, j, sample), the same in every run. The pixel is their mean; its branch is the\n"
                          "branch of the sample nearest the centre")
        ->type_name("N")
        ->check(square)
        ->capture_default_str();
}

}  // namespace promyk::app
