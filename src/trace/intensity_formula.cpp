#include "trace/intensity_formula.hpp"

#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"
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
    if (is_coloured(scene)) return "colour";
    for (const Material& material : scene.materials)
        if (material.specular > 0 || material.ambient > 0) return "phong";
    if (scene.shadows) return "shadows";
    if (scene.lights.size() > 1) return "lights";
    return "lambert";
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
    return formula.formula + (note.empty() ? "" : (language == Language::pl ? "; " : "; ") + note);
}

}  // namespace promyk
