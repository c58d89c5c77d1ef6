#include "app/common_options.hpp"

#include <map>
#include <string>

#include "app/cli_values.hpp"
#include "render/samples.hpp"

namespace promyk::app {

CLI::Validator whole_number(long min, long max) {
    return CLI::Validator(
        [min, max](std::string& text) { return cli::whole_number_problem(text, min, max).value_or(std::string()); },
        "", "");
}

CLI::Validator non_empty() {
    return CLI::Validator(
        [](std::string& text) { return text.empty() ? std::string("needs a value; got an empty one") : std::string(); },
        "", "");
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
    const std::map<std::string, RealType> types = {{"float", RealType::float_},
                                                   {"double", RealType::double_},
                                                   {"long-double", RealType::long_double},
                                                   {"quad", RealType::quad_}};
    return cmd.add_option("--real", real,
                          "The type every number is computed in: float (24-bit significand), double (53, the\n"
                          "default), long-double (x87, 64) or quad (__float128, 113)")
        ->type_name("TYPE")
        ->transform(CLI::CheckedTransformer(types))
        ->default_str("double");
}

CLI::Option* add_lang_option(CLI::App& cmd, std::string& lang, const std::string& applies_to) {
    return cmd.add_option("--lang", lang, applies_to + "pl or en (default: Polish when LANG starts with pl)")
        ->check(CLI::IsMember({"pl", "en"}))
        ->option_text("pl|en");
}

CLI::Option* add_formula_option(CLI::App& cmd, Formula& formula) {
    // Only the names: the text becomes the enum's number here, so a number
    // typed on the command line is refused like any other unknown word.
    const CLI::Validator names(
        [](std::string& text) {
            for (const Formula f : all_formulas) {
                if (text == formula_name(f)) {
                    text = std::to_string(static_cast<int>(f));
                    return std::string();
                }
            }
            return "expects article, stable, fma or geometric, got " + text;
        },
        "", "");
    return cmd.add_option("--formula", formula,
                          "How the eye's rays meet a sphere: article (the article's quadratic, the default);\n"
                          "stable (roots from q = C + sign(C)·√delta and Vieta: no cancellation in the near\n"
                          "root); fma (Kahan's discriminant with fused multiply-adds, then the article's roots);\n"
                          "geometric (the discriminant from the ray's distance to the centre, Haines et al.\n"
                          "2019: keeps small far spheres). Shadow rays keep their own test")
        ->type_name("article|stable|fma|geometric")
        ->transform(names)
        ->default_str("article");
}

CLI::Option* add_spp_option(CLI::App& cmd, int& spp) {
    const CLI::Validator square(
        [](std::string& text) {
            if (auto problem = cli::whole_number_problem(text, 1, max_spp)) return *problem;
            const int n = std::stoi(text);
            if (!valid_spp(n)) {
                const int below = spp_side(n) * spp_side(n), above = (spp_side(n) + 1) * (spp_side(n) + 1);
                return "must be a square (1, 4, 9, 16, ...), so that the pixel splits into n × n cells; got " + text +
                       ", try " + std::to_string(below) + " or " + std::to_string(above);
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
