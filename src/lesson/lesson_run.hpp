// A lesson made ready to render: its scene's kernel, the chosen pixels'
// traces, those of the other settings its qualifiers name, and any pixel of
// the pane on demand. The command line (`promyk lesson`) and the web page's
// wasm (web_export/wasm) both run lessons through this, so the page shows
// what the CLI prints.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lesson/lesson.hpp"
#include "lesson/lesson_render.hpp"
#include "render/kernel.hpp"
#include "scene/scene.hpp"
#include "trace/trace.hpp"

namespace promyk {

struct LessonRunOptions {
    // The scene's file name, for "::: scene FILE" blocks ("article" for the
    // built-in one); and whether the scene is the lesson's own.
    std::string scene_file;
    bool own_scene = true;
    int w = 8;
    std::vector<LessonPixel> pixels;  // at least one, inside the pane (the caller checks)
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    int spp = 1;
    int digits = 4;
    LessonFormat format = LessonFormat::text;
};

// Faults --check would report stop a lesson as they stop --check: the first
// one as an InputError (file, line); so does a "columns:" other than
// double/article and a settings qualifier that names no setting.
void require_runnable(const Lesson& lesson);

// The settings ("float", "quad,geometric") the lesson's qualifiers name.
std::vector<std::string> lesson_qualifiers(const Lesson& lesson);

// The numbers' real type and formula a lesson's header asks for.
RealType lesson_real(const Lesson& lesson);
Formula lesson_formula(const Lesson& lesson);

class LessonRun {
public:
    // Traces the chosen pixels and every setting the lesson's qualifiers name.
    // `lesson` and `scene` must outlive the run.
    LessonRun(const Lesson& lesson, const Scene& scene, const LessonRunOptions& options);
    LessonRun(const LessonRun&) = delete;
    LessonRun& operator=(const LessonRun&) = delete;

    LessonView& view() { return view_; }
    const Kernel& kernel() const { return *kernel_; }
    const TraceHeader& header() const { return header_; }

    // The traces of the pixels in each other setting a qualifier names,
    // added to view().others once a setting; with `only`, of those pixels alone.
    void trace_settings(const std::vector<std::string>& qualifiers, const std::set<std::pair<int, int>>* only = nullptr);

    // The whole lesson at once: the title, then each step and its answers.
    std::string document() const;

private:
    const Scene& scene_;
    std::unique_ptr<Kernel> kernel_;
    TraceHeader header_;
    std::shared_ptr<std::map<std::pair<int, int>, PixelTrace>> pane_;
    LessonView view_;
};

}  // namespace promyk
