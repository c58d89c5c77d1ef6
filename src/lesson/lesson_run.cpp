#include "lesson/lesson_run.hpp"

#include <sstream>

#include <fmt/format.h>

#include "lesson/lesson_check.hpp"
#include "render/trace_pixel.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"

namespace promyk {

namespace {

std::optional<RealType> real_type_named(const std::string& name) {
    for (const RealType type : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
        if (real_type_name(type) == name) return type;
    return std::nullopt;
}

std::optional<Formula> formula_named(const std::string& name) {
    for (const Formula formula : all_formulas)
        if (formula_name(formula) == name) return formula;
    return std::nullopt;
}

}  // namespace

void require_runnable(const Lesson& lesson) {
    std::vector<LessonProblem> problems;
    check_lesson(lesson, builtin_vocabulary(), problems);
    if (!problems.empty())
        throw InputError(lesson.file, fmt::format("line {}", problems.front().line), problems.front().message);
    std::istringstream columns(lesson.header.columns);
    for (std::string column; columns >> column;)
        if (column != "double/article")
            throw InputError(lesson.file, "columns", ui_message("lesson_columns", {{"column", column}}));
    lesson_qualifiers(lesson);
}

std::vector<std::string> lesson_qualifiers(const Lesson& lesson) {
    std::vector<std::string> qualifiers;
    for (const SettingsUse& use : settings_used(lesson)) {
        if (!parse_settings(use.settings))
            throw InputError(lesson.file, fmt::format("line {}", use.line),
                             message(lesson.language, "error_unknown_setting", {{"key", use.qualified}, {"settings", use.settings}}));
        qualifiers.push_back(use.settings);
    }
    return qualifiers;
}

RealType lesson_real(const Lesson& lesson) { return real_type_named(lesson.header.real).value_or(RealType::double_); }

Formula lesson_formula(const Lesson& lesson) { return formula_named(lesson.header.formula).value_or(Formula::article); }

LessonRun::LessonRun(const Lesson& lesson, const Scene& scene, const LessonRunOptions& options)
    : scene_(scene),
      kernel_(make_kernel(scene, options.real, options.formula, options.spp)),
      header_(trace_header(scene, options.w)),
      pane_(std::make_shared<std::map<std::pair<int, int>, PixelTrace>>()),
      view_{lesson, builtin_vocabulary(), {}, scene.name, options.w} {
    view_.format = options.format;
    view_.digits = options.digits;
    view_.scene = &scene_;
    view_.scene_file = options.scene_file;
    view_.own_scene = options.own_scene;
    // Any pixel of the pane, traced once when a step's needs or the figure ask for it.
    const Kernel* kernel = kernel_.get();
    const TraceHeader header = header_;
    auto pane = pane_;
    view_.pane_pixel = [pane, kernel, header](int i, int j) -> const PixelTrace& {
        // A step's needs may search a large pane, pixel by pixel: a signal stops it.
        throw_if_interrupted();
        auto at = pane->find({i, j});
        if (at == pane->end()) at = pane->emplace(std::make_pair(i, j), kernel->trace(header, i, j)).first;
        return at->second;
    };
    view_.traces.reserve(options.pixels.size());
    for (const LessonPixel& pixel : options.pixels) view_.traces.push_back(kernel_->trace(header_, pixel.i, pixel.j));
    trace_settings(lesson_qualifiers(lesson));
}

void LessonRun::trace_settings(const std::vector<std::string>& qualifiers, const std::set<std::pair<int, int>>* only) {
    const TraceHeader& own = view_.traces.front().header;
    std::set<std::pair<std::string, std::string>> done;
    for (const PixelTrace& other : view_.others) done.emplace(other.header.real, other.header.formula);
    for (const std::string& qualifier : qualifiers) {
        const auto [real, formula] = resolve_settings(qualifier, own.real, own.formula);
        if ((real == own.real && formula == own.formula) || !done.emplace(real, formula).second) continue;
        const std::unique_ptr<Kernel> kernel =
            make_kernel(scene_, *real_type_named(real), *formula_named(formula), kernel_->spp());
        std::set<std::pair<int, int>> traced;
        for (const PixelTrace& trace : view_.traces)
            if ((only == nullptr || only->count({trace.header.i, trace.header.j}) > 0) &&
                traced.emplace(trace.header.i, trace.header.j).second)
                view_.others.push_back(kernel->trace(header_, trace.header.i, trace.header.j));
    }
}

std::string LessonRun::document() const {
    std::string out = render_lesson_title(view_);
    for (std::size_t k = 0; k < view_.lesson.steps.size(); ++k)
        out += "\n" + render_step(view_, k) + render_answers(view_, k);
    return out;
}

}  // namespace promyk
