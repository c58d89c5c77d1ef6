// promyk lesson: the article's derivation replayed with the real numbers of
// chosen pixels, in Polish or English; also --list, --check and --dump.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "trace/messages.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "util/errors.hpp"

namespace promyk::app {

namespace {

struct LessonOptions {
    std::string name;
    std::vector<std::string> pixels;
    std::string scene_file;
    int w = 8;
    bool w_given = false;
    std::string lang;
    std::string format = "text";
    bool list = false;
    bool check = false;
    bool step = false;
    std::string dump;
    std::string lessons;
};

void print(const std::string& text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
}

int run_check(const LessonLibrary& library, Language language) {
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    for (const Lesson& lesson : lessons) check_lesson(lesson, builtin_vocabulary(), problems);
    check_translations(lessons, problems);
    for (const LessonProblem& problem : problems)
        fmt::print(stderr, "{}:{}: {}\n", problem.file, problem.line, problem.message);
    if (!problems.empty()) {
        fmt::print(stderr, "promyk: {}\n", message(language, "check_failed", {{"count", std::to_string(problems.size())}}));
        return 1;
    }
    print(message(language, "check_ok", {{"count", std::to_string(lessons.size())}}) + "\n");
    return 0;
}

int run_list(const LessonLibrary& library, Language language) {
    std::vector<LessonProblem> problems;
    std::string out = message(language, "list_heading") + "\n";
    std::size_t width = 0;
    std::vector<Lesson> lessons;
    for (Lesson& lesson : library.lessons(problems))
        if (lesson.language == language) lessons.push_back(std::move(lesson));
    for (const Lesson& lesson : lessons) width = std::max(width, lesson.header.name.size());
    for (const Lesson& lesson : lessons)
        out += fmt::format("  {:<{}}  {}\n", lesson.header.name, width, lesson.header.summary);
    print(out);
    return 0;
}

// Waits for Enter (step mode); a closed standard input just goes on.
void wait_for_enter(Language language, std::string_view prompt_id) {
    fmt::print(stderr, "{}", message(language, prompt_id));
    std::fflush(stderr);
    std::string line;
    std::getline(std::cin, line);
    fmt::print(stderr, "\n");
}

std::vector<std::string> lesson_names(const LessonLibrary& library, Language language) {
    std::vector<LessonProblem> problems;
    std::vector<std::string> names;
    for (const Lesson& lesson : library.lessons(problems))
        if (lesson.language == language) names.push_back(lesson.header.name);
    return names;
}

int run_lesson(const LessonOptions& options) {
    const Language language = options.lang.empty() ? language_from_environment() : *parse_language(options.lang);
    if (!options.dump.empty()) {
        LessonLibrary::dump_builtin(options.dump);
        fmt::print(stderr, "promyk: wrote the lessons, messages and scenes into {}\n", options.dump);
        return 0;
    }
    const LessonLibrary library(options.lessons);
    if (options.check) return run_check(library, language);
    if (options.list || options.name.empty()) return run_list(library, language);

    const std::optional<Lesson> found = library.find(options.name, language);
    if (!found) {
        std::string names;
        for (const std::string& name : lesson_names(library, language)) names += (names.empty() ? "" : ", ") + name;
        throw UsageError(fmt::format("no lesson '{}'; the lessons are {} (promyk lesson --list)", options.name, names));
    }
    const Lesson& lesson = *found;
    const Scene scene = options.scene_file.empty() ? library.scene(lesson.header.scene) : load_scene_file(options.scene_file);
    const int w = options.w_given ? options.w : lesson.header.w;
    std::vector<LessonPixel> pixels;
    for (const std::string& text : options.pixels) {
        const cli::Pixel pixel = cli::parse_pixel(text, "--pixel", w);
        pixels.push_back({pixel.i, pixel.j});
    }
    if (pixels.empty()) {
        for (const LessonPixel& pixel : lesson.header.pixels) {
            if (pixel.i >= w || pixel.j >= w)
                throw UsageError(fmt::format("the lesson's pixel ({}, {}) is outside the {} × {} pane; choose pixels with --pixel",
                                             pixel.i, pixel.j, w, w));
            pixels.push_back(pixel);
        }
    }

    LessonView view{lesson, builtin_vocabulary(), {}, scene.name, w};
    view.format = options.format == "markdown" ? LessonFormat::markdown : LessonFormat::text;
    const char* no_color = std::getenv("NO_COLOR");
    view.color = view.format == LessonFormat::text && isatty(STDOUT_FILENO) == 1 && (no_color == nullptr || *no_color == '\0');
    const ArticleWorld<double> world = article_world(scene);
    const TraceHeader header = trace_header(scene, w);
    for (const LessonPixel& pixel : pixels) view.traces.push_back(trace_pixel(world, header, pixel.i, pixel.j));

    print(render_lesson_title(view));
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        if (options.step && k > 0) wait_for_enter(language, "press_enter_next");
        print("\n" + render_step(view, k));
        if (has_answers(lesson.steps[k])) {
            if (options.step) wait_for_enter(language, "press_enter_answer");
            print(render_answers(view, k));
        }
    }
    return 0;
}

}  // namespace

std::function<int()> setup_lesson(CLI::App& app) {
    auto options = std::make_shared<LessonOptions>();
    CLI::App* cmd = app.add_subcommand(
        "lesson", "Replay a lesson of the article with the real numbers of chosen pixels, in Polish or English");
    cmd->add_option("name", options->name, "The lesson (promyk lesson --list shows them)")->type_name("NAME");
    cmd->add_option("--pixel", options->pixels, "A pixel I,J to follow (repeatable; default: the lesson's)")
        ->type_name("I,J")
        ->allow_extra_args(false);
    add_scene_option(*cmd, options->scene_file);
    add_w_option(*cmd, options->w)->description("Pane size: w × w pixels (default: the lesson's, usually 8)");
    cmd->add_option("--lang", options->lang, "pl or en (default: Polish when LANG starts with pl)")
        ->type_name("pl|en")
        ->check(CLI::IsMember({"pl", "en"}));
    cmd->add_option("--format", options->format, "text: for the terminal; markdown: with $…$ math and tables")
        ->check(CLI::IsMember({"text", "markdown"}))
        ->capture_default_str();
    cmd->add_flag("--list", options->list, "List the lessons with their summaries");
    cmd->add_flag("--check", options->check,
                  "Check every lesson against the vocabulary and its translation; exit 1 on a fault");
    cmd->add_flag("--step", options->step, "Wait for Enter between steps and before each answer (for class)");
    cmd->add_option("--dump", options->dump, "Write the built-in lessons into DIR, for a teacher to edit")
        ->type_name("DIR")
        ->check(non_empty());
    cmd->add_option("--lessons", options->lessons,
                    "Read lessons from DIR (as --dump writes it); the built-in ones fill in what DIR lacks")
        ->type_name("DIR")
        ->check(non_empty());
    cmd->footer("Example: promyk lesson sphere --pixel 0,0 --pixel 3,4 --lang en");
    return [options, cmd] {
        options->w_given = cmd->get_option("--w")->count() > 0;
        return run_lesson(*options);
    };
}

}  // namespace promyk::app
