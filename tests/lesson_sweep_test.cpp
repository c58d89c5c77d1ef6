// The sweep (issue 15): every built-in lesson, in both languages, at every
// pixel of an 8 × 8 pane (and a pixel of every branch at the lesson's w), on
// its own scene and on article.json and everything.json. No "—" inside a
// sentence or an arithmetic line, no pixel named that was not chosen (but
// the one a step's needs name), every group path shown exists in the scene,
// no fault --check would report (the runner's exit 3), no line wider than 80
// columns nor ending early before a bracketed group. Hidden from the
// default run ([.]): CTest runs it in the release pass only.
#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <regex>
#include <set>

#include "geometry/formula.hpp"
#include "lesson/lesson_check.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_render.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "util/wrap.hpp"
#include "flat_text.hpp"

using namespace promyk;

namespace {

RealType real_named(const std::string& name) {
    for (const RealType type : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
        if (real_type_name(type) == name) return type;
    return RealType::double_;
}

Formula formula_named(const std::string& name) {
    for (const Formula formula : all_formulas)
        if (formula_name(formula) == name) return formula;
    return Formula::article;
}

// Every pixel of one scene at one w in every setting a lesson names, traced once.
class Traces {
public:
    Traces(const Scene& scene, int w) : scene_(scene), header_(trace_header(scene, w)) {}
    const PixelTrace& get(int i, int j, const std::string& real = "double", const std::string& formula = "article") {
        const auto key = std::make_tuple(i, j, real, formula);
        auto at = cache_.find(key);
        if (at != cache_.end()) return at->second;
        auto& kernel = kernels_[{real, formula}];
        if (!kernel) kernel = make_kernel(scene_, real_named(real), formula_named(formula), 1);
        return cache_.emplace(key, kernel->trace(header_, i, j)).first->second;
    }

private:
    const Scene& scene_;
    TraceHeader header_;
    std::map<std::pair<std::string, std::string>, std::unique_ptr<Kernel>> kernels_;
    std::map<std::tuple<int, int, std::string, std::string>, PixelTrace> cache_;
};

// True when a text names the step's pixel ({i}, {j}): the runner leaves it
// out when no chosen pixel has what the step needs.
bool names_pixel_in(const std::string& text) {
    for (const Placeholder& p : find_placeholders(text))
        if (p.valid && (p.name == "i" || p.name == "j") && p.path == p.name) return true;
    return false;
}

// Every line fits 80 columns, and none ends right before a bracketed group
// that would have fitted on it: the whole group when it is one the wrapper
// keeps whole (util/wrap.hpp's group_columns), else its first word.
void check_lines(const std::string& text) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    const auto depth = [](const std::string& piece) {
        long open = 0;
        for (const char c : piece) open += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
        return open;
    };
    for (std::size_t k = 0; k < lines.size(); ++k) {
        if (display_width(lines[k]) > text_columns) FAIL_CHECK("wider than 80 columns: " << lines[k]);
        if (k + 1 == lines.size() || lines[k].find_first_not_of(' ') == std::string::npos) continue;
        const std::string& next = lines[k + 1];
        const std::size_t first = next.find_first_not_of(' ');
        if (first == std::string::npos || (next[first] != '(' && next[first] != '[')) continue;
        // A deeper indent under a line that opens no list item or block is a
        // table's cell ("  t = …" over "    (2, 5): 1.675"), not a wrapped line.
        static const std::regex opens_item(R"(^ *([-*] |\d+\. |▸ ))");
        if (first > lines[k].find_first_not_of(' ') && !std::regex_search(lines[k], opens_item)) continue;
        // A table's next cell ("    (5, 1): [2.354, …]" under "    (0, 0): …").
        static const std::regex cell(R"(^ {4,}\(\d+, \d+\): )");
        if (std::regex_search(next, cell) && lines[k].find_first_not_of(' ') >= 2) continue;
        // Code kept as written: lines of one indent of 4 or more; and a
        // shallower line is a new row, never a wrapped line's continuation.
        if (first >= 4 && first == lines[k].find_first_not_of(' ')) continue;
        if (first < lines[k].find_first_not_of(' ')) continue;
        std::size_t end = next.find(' ', first);
        if (end == std::string::npos) end = next.size();
        std::string unit = next.substr(first, end - first);
        for (std::size_t group_end = end; depth(next.substr(first, group_end - first)) > 0 && group_end < next.size();) {
            const std::size_t more = next.find(' ', group_end + 1);
            group_end = more == std::string::npos ? next.size() : more;
            const std::string group = next.substr(first, group_end - first);
            if (depth(group) <= 0 && display_width(group) <= group_columns) unit = group;
        }
        if (display_width(lines[k]) + 1 + display_width(unit) <= text_columns)
            FAIL_CHECK("a line ends before a group that fits on it:\n" << lines[k] << "\n" << next);
    }
}

struct Case {
    const Lesson* lesson;
    std::string scene_file;  // as --scene names it (the lesson's own when it is)
    std::vector<std::pair<int, int>> pixels;
};

// Renders the lesson as promyk lesson does, and checks it.
void sweep_one(const Case& c, const Scene& scene, Traces& traces, int w) {
    const Lesson& lesson = *c.lesson;
    LessonView view{lesson, builtin_vocabulary(), {}, scene.name, w};
    view.scene = &scene;
    view.scene_file = c.scene_file;
    view.own_scene = c.scene_file == lesson.header.scene || (lesson.header.scene == "article" && c.scene_file == "article.json");
    view.digits = lesson.header.digits == 0 ? 0 : lesson.header.digits;
    view.pane_pixel = [&traces, &lesson](int i, int j) -> const PixelTrace& {
        return traces.get(i, j, lesson.header.real, lesson.header.formula);
    };
    for (const auto& [i, j] : c.pixels) view.traces.push_back(traces.get(i, j, lesson.header.real, lesson.header.formula));
    std::set<std::pair<std::string, std::string>> settings;
    for (const SettingsUse& use : settings_used(lesson))
        settings.insert(resolve_settings(use.settings, lesson.header.real, lesson.header.formula));
    for (const auto& [real, formula] : settings)
        for (const auto& [i, j] : c.pixels) view.others.push_back(traces.get(i, j, real, formula));

    std::string text = render_lesson_title(view);
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) text += render_step(view, k) + render_answers(view, k);
    std::string where = lesson.file + " on " + c.scene_file + " at";
    for (const auto& [i, j] : c.pixels) where += " " + std::to_string(i) + "," + std::to_string(j);
    INFO(where);
    for (const Placeholder& p : find_placeholders(text)) FAIL_CHECK("left in the output: " << p.name);
    check_lines(text);
    // A value in a sentence (prose, a block, an answer) that the pixel did not
    // reach, or the scene does not have, would print "—": none may be shown.
    // And every group path a shown part names exists in the scene.
    const auto names_special = [](const Placeholder& p) {
        return p.path == p.name && (p.name == "i" || p.name == "j" || p.name == "w" || p.name == "branch");
    };
    for (const LessonStep& step : lesson.steps) {
        const PixelTrace* named = step_pixel(view, step);
        for (const LessonPart& part : step.parts) {
            std::vector<const PixelTrace*> shown_for;
            switch (part.kind) {
                case PartKind::prose:
                    if (named != nullptr || !names_pixel_in(part.text)) shown_for.push_back(&view.traces.front());
                    break;
                case PartKind::scene:
                    if (part.scene.empty() ? view.own_scene : part.scene == view.scene_file)
                        if (named != nullptr || !names_pixel_in(part.text)) shown_for.push_back(&view.traces.front());
                    break;
                case PartKind::answer:
                    if (named != nullptr) shown_for.push_back(named);
                    break;
                case PartKind::block:
                    for (const PixelTrace& trace : view.traces)
                        if (block_shown_for(view, part, trace)) shown_for.push_back(&trace);
                    break;
                default:
                    break;
            }
            if (shown_for.empty()) continue;
            for (const Placeholder& p : find_placeholders(part.text)) {
                if (!p.valid || p.symbol || names_special(p)) continue;
                const PathCheck check = check_path(p.path, builtin_vocabulary(), &scene);
                if (check.fault == PathFault::index)
                    FAIL_CHECK(lesson.file << ":" << part.line << ": {" << p.path << "} names " << check.group << ", which "
                                           << c.scene_file << " lacks");
                const VocabularyEntry* entry = builtin_vocabulary().find(p.name);
                if (entry != nullptr && entry->term_of_sum && part.kind != PartKind::prose) continue;  // shows 0
                for (const PixelTrace* trace : shown_for)
                    if (!lesson_number(view, *trace, qualified_path(p)))
                        FAIL_CHECK(lesson.file << ":" << part.line << ": {" << qualified_path(p) << "} shows — for pixel ("
                                               << trace->header.i << ", " << trace->header.j << ")");
            }
        }
    }
    // Pixels named: the chosen ones, and the one a step's needs name ("(1, 3): promyk lesson … --pixel 1,3").
    // A block about the lesson's own scene may name its pixels (true there); so may the pane's geometry
    // in lesson pane ("the top left square is (0, 0)"). An interval "in (0, 1)", "w przedziale (0, 1)" is no pixel.
    LessonView others = view;
    others.own_scene = false;
    others.scene_file = "";
    std::string unscened;
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) unscened += render_step(others, k) + render_answers(others, k);
    std::set<std::pair<int, int>> chosen(c.pixels.begin(), c.pixels.end());
    static const std::regex hint(R"(\((\d+), (\d+)\): promyk lesson \S+ --pixel (\d+),(\d+))");
    static const std::regex pixel(R"(\((\d+), (\d+)\))");
    std::string joined = std::regex_replace(flat(unscened), hint, "");
    if (lesson.header.name == "pane")
        for (const LessonStep& step : lesson.steps)
            for (const LessonPart& part : step.parts)
                if (part.kind == PartKind::prose || part.kind == PartKind::answer)
                    for (auto it = std::sregex_iterator(part.text.begin(), part.text.end(), pixel); it != std::sregex_iterator(); ++it)
                        chosen.emplace(std::stoi((*it)[1]), std::stoi((*it)[2]));
    for (auto it = std::sregex_iterator(joined.begin(), joined.end(), pixel); it != std::sregex_iterator(); ++it) {
        const std::pair<int, int> named{std::stoi((*it)[1]), std::stoi((*it)[2])};
        const std::size_t at = static_cast<std::size_t>(it->position());
        const bool interval = at >= 3 && (joined.compare(at - 3, 3, "in ") == 0 ||
                                           (at >= 11 && joined.compare(at - 11, 11, "przedziale ") == 0));
        if (chosen.count(named) == 0 && !interval)
            FAIL_CHECK("pixel (" << named.first << ", " << named.second << ") named, not chosen: …"
                                 << joined.substr(at < 60 ? 0 : at - 60, 120) << "…");
    }
}

}  // namespace

TEST_CASE("every lesson holds on every pixel and on other scenes, in both languages", "[.][sweep]") {
    const auto started = std::chrono::steady_clock::now();
    const LessonLibrary library;
    std::vector<LessonProblem> problems;
    const std::vector<Lesson> lessons = library.lessons(problems);
    REQUIRE(problems.empty());
    std::map<std::string, Scene> scenes;
    const auto scene_of = [&](const std::string& file) -> const Scene& {
        auto at = scenes.find(file);
        if (at == scenes.end()) at = scenes.emplace(file, library.scene(file)).first;
        return at->second;
    };
    std::map<std::pair<std::string, int>, std::unique_ptr<Traces>> traced;
    const auto traces_of = [&](const std::string& file, int w) -> Traces& {
        auto& t = traced[{file, w}];
        if (!t) t = std::make_unique<Traces>(scene_of(file), w);
        return *t;
    };
    std::size_t runs = 0;
    for (const Lesson& lesson : lessons) {
        // The runner's check (exit 3 on a fault).
        std::vector<LessonProblem> faults;
        check_lesson(lesson, builtin_vocabulary(), faults);
        for (const LessonProblem& fault : faults) FAIL_CHECK(fault.file << ":" << fault.line << ": " << fault.message);
        const std::string own = lesson.header.scene;
        const int w = lesson.header.w;
        std::vector<std::pair<int, int>> defaults;
        for (const LessonPixel& p : lesson.header.pixels) defaults.emplace_back(p.i, p.j);
        // Every pixel of an 8 × 8 pane, one at a time.
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j, ++runs) sweep_one({&lesson, own, {{i, j}}}, scene_of(own), traces_of(own, 8), 8);
        // The lesson's w: its default pixels, and the first pixel of every branch alone.
        const auto branch_pixels = [&](const std::string& file, int size) {
            std::vector<std::pair<int, int>> out;
            std::set<Branch> seen;
            for (int i = 0; i < size; ++i)
                for (int j = 0; j < size; ++j)
                    if (seen.insert(traces_of(file, size).get(i, j, lesson.header.real, lesson.header.formula).branch).second)
                        out.emplace_back(i, j);
            return out;
        };
        sweep_one({&lesson, own, defaults}, scene_of(own), traces_of(own, w), w);
        for (const auto& p : branch_pixels(own, w)) sweep_one({&lesson, own, {p}}, scene_of(own), traces_of(own, w), w), ++runs;
        // Other scenes: the lesson's default pixels, and one pixel of every branch.
        for (const std::string other : {"article.json", "everything.json"}) {
            std::vector<std::pair<int, int>> pixels;
            for (const auto& p : defaults)
                if (p.first < w && p.second < w) pixels.push_back(p);
            sweep_one({&lesson, other, pixels}, scene_of(other), traces_of(other, w), w);
            for (const auto& p : branch_pixels(other, w)) sweep_one({&lesson, other, {p}}, scene_of(other), traces_of(other, w), w), ++runs;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    WARN(runs << " lesson runs in " << seconds << " s");
    CHECK(seconds < 60);
}
