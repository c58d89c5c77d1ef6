#include "trace/intensity_formula.hpp"

#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "trace/trace.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace embedded {
extern const std::string_view embedded_vocabulary_json;
}

namespace {

const std::vector<IntensityFormula>& formulas() {
    static const std::vector<IntensityFormula> all = [] {
        std::vector<IntensityFormula> out;
        const nlohmann::json vocabulary = nlohmann::json::parse(embedded::embedded_vocabulary_json);
        for (const nlohmann::json& item : vocabulary.at("intensity_formulas"))
            out.push_back({item.at("effects").get<std::string>(), item.at("formula").get<std::string>(),
                           item.at("formula_latex").get<std::string>(), item.value("pl", ""), item.value("en", ""),
                           item.value("contribution", ""), item.value("contribution_latex", "")});
        return out;
    }();
    return all;
}

}  // namespace

std::string effect_set(const Scene& scene) {
    bool phong = false, weights = false;
    const auto takes = [&](int index) {
        const Material& m = material_of(scene, index);
        phong = phong || m.specular > 0;
        weights = weights || m.ambient > 0 || m.diffuse != 1;
    };
    for (const Sphere& sphere : scene.spheres) takes(sphere.material);
    for (const Plane& plane : scene.planes) takes(plane.material);
    std::string out;
    const auto add = [&out](bool on, const char* flag) {
        if (on) out += (out.empty() ? "" : "+") + std::string(flag);
    };
    add(scene.lights.size() > 1, "lights");
    add(scene.shadows, "shadows");
    add(phong, "phong");
    add(weights && !phong, "weights");
    add(is_coloured(scene), "colour");
    return out.empty() ? "lambert" : out;
}

std::string effect_set(const PixelTrace& trace) {
    static thread_local std::string parsed_content;
    static thread_local std::string parsed_effects = "lambert";
    if (trace.header.scene_content.empty()) return "lambert";
    if (parsed_content != trace.header.scene_content) {
        parsed_content = trace.header.scene_content;
        try {
            parsed_effects = effect_set(parse_scene(parsed_content, "trace"));
        } catch (const InputError&) {
            parsed_effects = "lambert";
        }
    }
    return parsed_effects;
}

const IntensityFormula& intensity_formula(std::string_view effects) {
    for (const IntensityFormula& formula : formulas())
        if (formula.effects == effects) return formula;
    return formulas().front();
}

std::string intensity_formula_text(std::string_view effects, Language language) {
    const IntensityFormula& formula = intensity_formula(effects);
    const std::string& note = language == Language::pl ? formula.pl : formula.en;
    return formula.formula + (note.empty() ? "" : std::string("; ") + note);
}

std::string step_formula(const VocabularyEntry* entry, std::string_view key, std::string_view effects, bool latex) {
    if (key == "I_P" || key == "contribution") {
        const IntensityFormula& formula = intensity_formula(effects);
        if (key == "contribution") return latex ? formula.contribution_latex : formula.contribution;
        return latex ? formula.formula_latex : formula.formula;
    }
    if (entry == nullptr) return "";
    return latex ? entry->formula_latex : entry->formula;
}

std::string branch_about(const Vocabulary& vocabulary, Branch branch, std::string_view effects, Language language) {
    const BranchEntry* entry = vocabulary.find_branch(branch_name(branch));
    if (entry == nullptr) return "";
    std::string text = language == Language::pl ? entry->pl : entry->en;
    const std::string_view mark = "{formula}";
    if (const std::size_t at = text.find(mark); at != std::string::npos)
        text.replace(at, mark.size(), intensity_formula(effects).formula);
    return text;
}

std::string branch_named(const Vocabulary& vocabulary, Branch branch, std::string_view effects, Language language) {
    const std::string name = message(language, "branch_name_" + std::string(branch_name(branch)));
    const std::string about = branch_about(vocabulary, branch, effects, language);
    return about.empty() ? name : name + " — " + about;
}

}  // namespace promyk
