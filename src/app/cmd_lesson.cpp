// promyk lesson: the article's derivation replayed with the real numbers of
// chosen pixels, in Polish or English; also --list, --check and --dump, a
// worksheet with blanks (--worksheet, --key) and a check of a student's
// numbers (--answers FILE).
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/trace_limit.hpp"
#include "lesson/answers.hpp"
#include "lesson/answers_run.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "lesson/lesson_run.hpp"
#include "lesson/worksheet.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/messages.hpp"
#include "trace/trace_text.hpp"
#include "util/edit_distance.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/output_file.hpp"
#include "util/printable.hpp"
#include "util/read_input.hpp"
#include "util/standard_output.hpp"
#include "util/wrap.hpp"

namespace promyk::app {

namespace {

struct LessonOptions {
    std::string name;
    std::vector<std::string> pixels;
    std::string scene_file;
    int w = 8;
    bool w_given = false;
    std::string format = "text";
    bool list = false;
    bool check = false;
    bool step = false;
    std::string dump;
    std::string lessons;
    bool worksheet = false;
    bool key = false;
    std::string answers;
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    int spp = 1;
    bool real_given = false, formula_given = false, spp_given = false;
    std::string max_trace_size;  // --max-trace-size; empty: the default limit
};

// Flushed at once (step mode waits between steps); a failed write (a full
// disk, a reader that quit) is an error here: once flushed, the failure
// would no longer show when main flushes standard output at the end.
void print(const std::string& text) {
    write_standard_output(text);
    flush_standard_output();
}

// A lesson's name as a list shows it: a file with no name (an empty file)
// shows as its file's name, not as a blank.
std::string shown_name(const Lesson& lesson) {
    if (!lesson.header.name.empty()) return lesson.header.name;
    const std::size_t slash = lesson.file.find_last_of("/\\");
    return printable(slash == std::string::npos ? lesson.file : lesson.file.substr(slash + 1));
}

int run_check(const LessonLibrary& library, Language language) {
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    for (const Lesson& lesson : lessons) {
        // The scene a lesson names must exist and be valid, or the lesson cannot
        // run; its objects and lights are what the lesson's paths may name.
        try {
            const Scene scene = library.scene(lesson.header.scene.empty() ? "article" : lesson.header.scene);
            check_lesson(lesson, builtin_vocabulary(), problems, &scene);
        } catch (const InputError& error) {
            check_lesson(lesson, builtin_vocabulary(), problems);
            const std::string where = error.where.empty() ? error.file : error.file + ": " + error.where;
            problems.push_back({lesson.file, lesson.header.scene_line,
                                message(lesson.language, "error_scene",
                                        {{"scene", lesson.header.scene}, {"problem", where + ": " + error.what()}})});
        }
    }
    check_translations(lessons, problems);
    for (const std::string& file : library.unread())
        problems.push_back({file, 1, message(language, "error_unread_file")});
    for (const LessonProblem& problem : problems)
        fmt::print(stderr, "{}:{}: {}\n", printable(problem.file), problem.line, printable(problem.message));
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
        if (lesson.language == language) {
            lesson.header.name = shown_name(lesson);
            lessons.push_back(std::move(lesson));
        }
    for (const Lesson& lesson : lessons) width = std::max(width, lesson.header.name.size());
    // Each summary wrapped under itself, so the list fits 80 columns.
    // A name too long for a column of its own (a teacher's own lesson) puts
    // every summary under its name instead.
    const bool column = width <= 24;
    for (const Lesson& lesson : lessons) {
        if (!column) {
            out += "  " + lesson.header.name + "\n" + wrap_text("      " + lesson.header.summary, 6) + "\n";
            continue;
        }
        std::string line = wrap_text(std::string(width + 4, ' ') + lesson.header.summary, width + 4);
        out += line.replace(0, width + 4, fmt::format("  {:<{}}  ", lesson.header.name, width)) + "\n";
    }
    print(out);
    return 0;
}

// What a reader typed in step mode before Enter.
enum class StepKey { next, back, quit };

// Waits for Enter (step mode): "q" then Enter quits, "b" then Enter goes
// back a step; a closed standard input just goes on. Ctrl-C while waiting
// ends the lesson (Interrupted, util/read_input.hpp), not the wait.
StepKey wait_for_enter(Language language, std::string_view prompt_id) {
    fmt::print(stderr, "{}", message(language, prompt_id));
    std::fflush(stderr);
    std::string line = read_standard_input_line().value_or("");
    fmt::print(stderr, "\n");
    line.erase(0, line.find_first_not_of(" \t"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line == "q" || line == "Q") return StepKey::quit;
    if (line == "b" || line == "B") return StepKey::back;
    return StepKey::next;
}

std::vector<std::string> lesson_names(const LessonLibrary& library, Language language) {
    std::vector<LessonProblem> problems;
    std::vector<std::string> names;
    for (const Lesson& lesson : library.lessons(problems))
        if (lesson.language == language) names.push_back(shown_name(lesson));
    return names;
}

// --answers FILE: the student's numbers against the traces; exit 1 when any is wrong.
int run_answers(const LessonOptions& options, LessonRun& run) {
    const std::string shown = options.answers == "-" ? "(stdin)" : options.answers;
    const std::vector<AnswerCheck> checks = check_lesson_answers(
        run, cli::read_input_file(options.answers, "--answers reads", max_answer_bytes, "--answers"), shown);
    const LessonView& view = run.view();
    print(wrap_lines(message(view.lesson.language, "answers_heading",
                             {{"file", shown}, {"lesson", view.lesson.header.name}, {"scene", view.scene_name},
                              {"w", std::to_string(view.w)}, {"pane", pane_phrase(view.w)}}) +
                     "\n\n" + answers_report(checks, view.traces, view.vocabulary, view.lesson.language, view.others)));
    return all_right(checks) ? 0 : 1;
}

int run_lesson(const LessonOptions& options) {
    const Language language = ui_language();
    if (!options.dump.empty()) {
        LessonLibrary::dump_builtin(options.dump);
        fmt::print(stderr, "promyk: {}\n", ui_message("lesson_dumped", {{"dir", printable(options.dump)}}));
        return 0;
    }
    const LessonLibrary library(options.lessons);
    if (options.check) return run_check(library, language);
    if (options.list || options.name.empty()) return run_list(library, language);

    const std::optional<Lesson> found = library.find(options.name, language);
    if (!found) {
        std::string names, hint;
        for (const std::string& name : lesson_names(library, language)) {
            names += (names.empty() ? "" : ", ") + name;
            if (hint.empty() && edit_distance(options.name, name) <= 2) hint = ui_message("did_you_mean", {{"name", name}});
        }
        throw UsageError(ui_message("lesson_unknown", {{"name", options.name}, {"hint", hint.empty() ? "." : hint}, {"names", names}}));
    }
    const Lesson& lesson = *found;
    require_runnable(lesson);
    const Scene scene = options.scene_file.empty() ? library.scene(lesson.header.scene) : load_scene_file(options.scene_file);
    LessonRunOptions run_options;
    run_options.w = options.w_given ? options.w : lesson.header.w;
    const int w = run_options.w;
    for (const std::string& text : options.pixels) {
        const cli::Pixel pixel = cli::parse_pixel(text, "--pixel", w);
        run_options.pixels.push_back({pixel.i, pixel.j});
    }
    if (run_options.pixels.empty()) {
        for (const LessonPixel& pixel : lesson.header.pixels) {
            if (pixel.i >= w || pixel.j >= w)
                throw UsageError(ui_message("lesson_pixel_outside", {{"i", std::to_string(pixel.i)},
                                                                     {"j", std::to_string(pixel.j)},
                                                                     {"w", std::to_string(w)}}));
            run_options.pixels.push_back(pixel);
        }
    }
    run_options.format = options.format == "markdown" ? LessonFormat::markdown
                         : options.format == "html"   ? LessonFormat::html
                                                      : LessonFormat::text;
    run_options.digits = shown_digits(lesson.header.digits);  // 4 significant digits unless digits: or --digits
    // The numbers' type and formula: the command line's, else the lesson's header's (else double, article).
    run_options.real = options.real_given ? options.real : lesson_real(lesson);
    run_options.formula = options.formula_given ? options.formula : lesson_formula(lesson);
    run_options.spp = options.spp_given ? options.spp : lesson.header.spp;
    // Each pixel's trace, estimated from the scene before anything is traced
    // (quad for the other settings a lesson may name).
    TraceCost cost;
    cost.scene = &scene;
    cost.real = lesson_qualifiers(lesson).empty() && options.answers.empty() ? run_options.real : RealType::quad_;
    cost.spp = run_options.spp;
    require_trace_size(cost, options.max_trace_size);
    // The scene's file name, for "::: scene FILE" blocks; the lesson's own scene shows its own prose.
    run_options.scene_file = lesson.header.scene;
    if (!options.scene_file.empty()) {
        const std::size_t slash = options.scene_file.find_last_of("/\\");
        run_options.scene_file = slash == std::string::npos ? options.scene_file : options.scene_file.substr(slash + 1);
    }
    run_options.own_scene = run_options.scene_file == lesson.header.scene ||
                            (lesson.header.scene == "article" && run_options.scene_file == "article.json");
    LessonRun run(lesson, scene, run_options);
    LessonView& view = run.view();
    const char* no_color = std::getenv("NO_COLOR");
    view.color = view.format == LessonFormat::text && isatty(STDOUT_FILENO) == 1 && (no_color == nullptr || *no_color == '\0');
    if (!options.answers.empty()) return run_answers(options, run);

    // A worksheet shows blanks for the pixels' numbers and leaves the answers out (they are the teacher's).
    std::optional<Worksheet> worksheet;
    if (options.worksheet) worksheet.emplace(view);
    print(render_lesson_title(view));
    if (worksheet) print(worksheet->intro());
    if (options.step) fmt::print(stderr, "{}\n", message(language, "step_mode_keys"));
    // Back a step: the loop's ++k then shows step k − 1 (step 0 again from step 0; unsigned wrap-around).
    const auto back = [](std::size_t k) { return (k == 0 ? std::size_t(0) : k - 1) - 1; };
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        // A worksheet's HTML: its blanks become fields (worksheet.hpp).
        print("\n" + (worksheet ? worksheet->fields(render_step(view, k)) : render_step(view, k)));
        const std::string answers = worksheet ? "" : render_answers(view, k);
        if (!answers.empty()) {
            if (options.step) {
                const StepKey key = wait_for_enter(language, "press_enter_answer");
                if (key == StepKey::quit) return 0;
                if (key == StepKey::back) {
                    k = back(k);
                    continue;
                }
            }
            print(answers);
        }
        if (options.step && k + 1 < lesson.steps.size()) {
            const StepKey key = wait_for_enter(language, "press_enter_next_keys");
            if (key == StepKey::quit) return 0;
            if (key == StepKey::back) k = back(k);
        }
    }
    if (worksheet) print(worksheet->answer_template());
    if (worksheet && options.key) print(worksheet->answer_key());
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
    add_real_option(*cmd, options->real)
        ->description("The type the lesson's numbers are computed in: float, double, long-double or quad\n"
                      "(default: the lesson's real:, else double); a placeholder such as {delta@float} names another")
        ->default_str("");
    add_formula_option(*cmd, options->formula)
        ->description("How the eye's rays meet a sphere: article, stable, fma or geometric\n"
                      "(default: the lesson's formula:, else article); {t_hit@geometric} names another")
        ->default_str("");
    add_spp_option(*cmd, options->spp)
        ->description("Samples per pixel, a square (default: the lesson's spp:, else 1): the lesson follows the\n"
                      "sample nearest the pixel's centre, whose branch is the pixel's; {I_mean} is the pixel's value,\n"
                      "{sample[2].delta} another sample's step")
        ->default_str("");
    add_format_option(*cmd, options->format, {"text", "markdown", "html"},
                      "text: for the terminal; markdown: with $…$ math and tables; html: a fragment, TeX for KaTeX");
    cmd->add_flag("--list", options->list, "List the lessons with their summaries");
    cmd->add_flag("--check", options->check,
                  "Check every lesson against the vocabulary and its translation; exit 1 on a fault");
    cmd->add_flag("--step", options->step, "Wait for Enter between steps and before each answer (for class)");
    add_max_trace_size_option(*cmd, options->max_trace_size);
    cmd->add_option("--dump", options->dump, "Write the built-in lessons into DIR, for a teacher to edit")
        ->type_name("DIR")
        ->check(non_empty());
    cmd->add_option("--lessons", options->lessons,
                    "Read lessons from DIR (as --dump writes it); the built-in ones fill in what DIR lacks")
        ->type_name("DIR")
        ->check(non_empty());
    CLI::Option* worksheet = cmd->add_flag(
        "--worksheet", options->worksheet,
        "Print a worksheet: numbered blanks where the pixels' numbers go, no answers, and a form for --answers");
    cmd->add_flag("--key", options->key, "With --worksheet: add the answer key (each blank's number and value) at the end")
        ->needs(worksheet);
    cmd->add_option("--answers", options->answers,
                    "Check a student's numbers in FILE (key = value lines, [i,j] headings, or JSON; - reads standard "
                    "input); exit 1 when any is wrong")
        ->type_name("FILE")
        ->check(non_empty())
        ->excludes(worksheet);
    cmd->footer("Examples: promyk lesson sphere --pixel 0,0 --pixel 3,4 --lang en\n"
                "          promyk lesson sphere --worksheet --key > worksheet.txt\n"
                "          promyk lesson sphere --pixel 3,4 --answers answers.txt\n"
                "          promyk lesson sphere --real float --lang en     (the same lesson in float)\n"
                "          promyk lesson precision --lang en");
    return [options, cmd] {
        options->w_given = cmd->get_option("--w")->count() > 0;
        options->real_given = cmd->get_option("--real")->count() > 0;
        options->formula_given = cmd->get_option("--formula")->count() > 0;
        options->spp_given = cmd->get_option("--spp")->count() > 0;
        return run_lesson(*options);
    };
}

}  // namespace promyk::app
