// `promyk diff`'s reader (lesson/answers.hpp: read_answers without a pane or
// forgiveness: a whole trace, a flat JSON object or key = value lines) and
// the comparison (lesson/trace_diff.hpp): the input against the article's
// pixel (3, 4), and against itself, which must agree everywhere.
#include "fuzz_check.hpp"
#include "lesson/trace_diff.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

DiffInput article_pixel() {
    const Scene scene = article_scene();
    std::string json;
    append_trace_json(json, make_kernel(scene)->trace(trace_header(scene, 8), 3, 4));
    return {"article.json", read_answers(json, "article.json", builtin_vocabulary(), Language::en, diff_first_pixel, {})};
}

void compare(const DiffInput& a, const DiffInput& b, Language language, bool same) {
    DiffResult result;
    try {
        result = diff_inputs(a, b, builtin_vocabulary(), {}, language);
    } catch (const InputError&) {
        return;
    }
    if (same && result.first) fuzz::broken("an input differs from itself");
    (void)diff_report(result, a, b, {}, builtin_vocabulary(), language);
    (void)diff_json(result, a, b, {});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const DiffInput article = article_pixel();
    const Language language = fuzz::language_of(size);
    set_ui_language(language);
    DiffInput input{"fuzz.json", {}};
    try {
        input.answers = read_answers(fuzz::bytes_of(data, size), "fuzz.json", builtin_vocabulary(), language,
                                     diff_first_pixel, {});
    } catch (const InputError&) {
        return 0;
    }
    compare(input, article, language, false);
    compare(article, input, language, false);
    compare(input, input, language, true);
    return 0;
}
