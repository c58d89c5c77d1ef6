// The answer-file reader and checker (lesson/answers.hpp) as `promyk lesson
// precision --answers FILE` runs them on the article's scene at w = 8: any
// bytes are answers to judge or an InputError (exit 3), never a crash, a
// leak or undefined behaviour; the report is written for every judgement.
#include <map>
#include <memory>
#include <set>

#include "fuzz_check.hpp"
#include "lesson/answers.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

constexpr int w = 8;

// Every pixel of the pane in every real type and formula, traced once.
struct Pane {
    Scene scene = article_scene();
    TraceHeader header = trace_header(scene, w);
    std::map<std::pair<std::string, std::string>, std::vector<PixelTrace>> traces;  // (real, formula) -> i * w + j
    std::vector<std::string> keys;

    Pane() {
        for (const RealType real : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
            for (const Formula formula : all_formulas) {
                const std::unique_ptr<Kernel> kernel = make_kernel(scene, real, formula);
                auto& pixels = traces[{std::string(real_type_name(real)), std::string(formula_name(formula))}];
                for (int i = 0; i < w; ++i)
                    for (int j = 0; j < w; ++j) pixels.push_back(kernel->trace(header, i, j));
            }
        if (const std::optional<Lesson> lesson = LessonLibrary().find("precision", Language::en))
            keys = lesson_keys(*lesson, builtin_vocabulary());
    }

    const PixelTrace& at(const std::string& real, const std::string& formula, LessonPixel pixel) const {
        return traces.at({real, formula}).at(static_cast<std::size_t>(pixel.i * w + pixel.j));
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Pane pane;
    const Language language = fuzz::language_of(size);
    set_ui_language(language);
    AnswerLimits limits;
    limits.w = w;
    limits.scene_hash = pane.header.scene_hash;
    limits.settings = true;
    limits.forgiving = true;
    limits.keys = pane.keys;
    std::vector<PixelAnswers> answers;
    try {
        answers = read_answers(fuzz::bytes_of(data, size), "fuzz.txt", builtin_vocabulary(), language, {3, 4}, limits).pixels;
    } catch (const InputError&) {
        return 0;
    }
    // The traces of the pixels named, in the lesson's settings and in every
    // setting a key names (delta@float) and the exact values' (quad).
    std::vector<PixelTrace> traces, others;
    std::set<std::pair<std::string, std::string>> settings;
    std::set<std::pair<int, int>> pixels;
    for (const PixelAnswers& pixel : answers) {
        if (pixel.pixel.i < 0 || pixel.pixel.i >= w || pixel.pixel.j < 0 || pixel.pixel.j >= w)
            fuzz::broken("an answer's pixel is outside the pane");
        if (pixels.emplace(pixel.pixel.i, pixel.pixel.j).second) traces.push_back(pane.at("double", "article", pixel.pixel));
        for (const Answer& answer : pixel.answers)
            if (answer.unreadable.empty()) {
                const std::string qualifier = split_settings(answer.key).second;
                for (const std::string& s : {qualifier, exact_settings(qualifier)})
                    if (parse_settings(s)) settings.insert(resolve_settings(s, "double", "article"));
            }
    }
    settings.erase({"double", "article"});
    for (const auto& [real, formula] : settings)
        for (const auto& [i, j] : pixels) others.push_back(pane.at(real, formula, {i, j}));
    const std::vector<AnswerCheck> checks = check_answers(answers, traces, others);
    (void)answers_report(checks, traces, builtin_vocabulary(), language, others);
    (void)all_right(checks);
    return 0;
}
