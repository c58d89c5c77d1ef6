// The web page's entry points into promyk (web_export/wasm/API.md): plain C
// functions over the project's own tracer, formatter and readers, each
// returning a JSON text that the module owns until the next call. No
// exception leaves them: a failure is {"error": ..., "code": N}.
#include <cmath>
#include <cstdint>
#include <memory>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/map_colours.hpp"
#include "lesson/answers.hpp"
#include "lesson/answers_run.hpp"
#include "lesson/lesson_library.hpp"
#include "lesson/lesson_run.hpp"
#include "lesson/worksheet.hpp"
#include "render/kernel.hpp"
#include "render/map_overlay.hpp"
#include "render/maps.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/intensity_formula.hpp"
#include "trace/digits_alarm.hpp"
#include "trace/digits_lost.hpp"
#include "trace/formula_numbers.hpp"
#include "trace/messages.hpp"
#include "trace/number_text.hpp"
#include "trace/trace_compare.hpp"
#include "trace/trace_read.hpp"
#include "trace/trace_text.hpp"
#include "trace/vocabulary.hpp"
#include "util/errors.hpp"
#include "util/embedded_files.hpp"

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#define PROMYK_EXPORT EMSCRIPTEN_KEEPALIVE
#else
#define PROMYK_EXPORT
#endif

using namespace promyk;
using json = nlohmann::ordered_json;

namespace {

constexpr int max_w = 32768;  // as the CLI's --w (app/cli_values.hpp)

// The kernel promyk_render_rows made last, kept while the scene and the
// settings stay (a worker renders its rows in several calls).
struct RowKernel {
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    int spp = 1;
    std::unique_ptr<Kernel> kernel;
};

struct State {
    std::string answer;  // the last result, owned here
    std::optional<Scene> scene;
    std::string scene_file;  // the name promyk_open_scene was given, for lessons' "::: scene FILE"
    int w = 0;
    std::optional<TraceFile> traces;
    RowKernel rows;                    // made for `scene`; reset when another opens
    std::vector<std::uint8_t> pixels;  // promyk_render_rows' image rows
    std::vector<std::uint8_t> branch;  // and their branch categories
};

State& state() {
    static State s;
    return s;
}

std::string error_json(const std::string& what, int code, const json& extra = json::object()) {
    json out = {{"error", what}, {"code", code}};
    for (auto it = extra.begin(); it != extra.end(); ++it) out[it.key()] = it.value();
    return out.dump();
}

// "file: where: what", as the CLI words a bad input.
std::string input_error_text(const InputError& e) {
    std::string out;
    if (!e.file.empty()) out += e.file + ": ";
    if (!e.where.empty()) out += e.where + ": ";
    return out + e.what();
}

template <class F>
const char* answer(F&& compute) {
    std::string& out = state().answer;
    try {
        out = compute();
    } catch (const UsageError& e) {
        out = error_json(e.what(), 2);
    } catch (const SceneErrors& e) {
        json faults = json::array();
        for (const SceneFault& f : e.faults) faults.push_back({{"where", f.where}, {"what", f.what}});
        out = error_json(input_error_text(e), 3, {{"faults", faults}, {"more", e.more}});
    } catch (const InputError& e) {
        out = error_json(input_error_text(e), 3, {{"file", e.file}, {"where", e.where}});
    } catch (const std::exception& e) {
        out = error_json(e.what(), 3);
    } catch (...) {
        out = error_json("unknown error", 3);
    }
    return out.c_str();
}

// A JSON object argument ("" is {}); a bad one is a usage error.
nlohmann::json object_argument(const char* text, const char* name) {
    const std::string_view t = text ? text : "";
    if (t.empty()) return nlohmann::json::object();
    nlohmann::json j = nlohmann::json::parse(t, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        throw UsageError(ui_message("wasm_bad_argument", {{"name", name}, {"problem", "not a JSON object"}}));
    return j;
}

std::string string_field(const nlohmann::json& j, const char* key, const std::string& fallback, const char* name) {
    if (!j.contains(key)) return fallback;
    if (!j.at(key).is_string())
        throw UsageError(ui_message("wasm_bad_argument", {{"name", std::string(name) + "." + key}, {"problem", "not a string"}}));
    return j.at(key).get<std::string>();
}

Language language_of(const std::string& code) {
    const std::optional<Language> language = parse_language(code);
    if (!language) throw UsageError(ui_message("wasm_bad_argument", {{"name", "lang"}, {"problem", code}}));
    return *language;
}

// The view argument: {"lang", "digits"}; sets the language of messages too.
struct View {
    Language language = Language::en;
    int digits = 4;
};

View view_of(const char* text) {
    const nlohmann::json j = object_argument(text, "view");
    View view;
    view.language = language_of(string_field(j, "lang", "en", "view"));
    set_ui_language(view.language);
    if (j.contains("digits")) {
        if (!j.at("digits").is_number_integer() || j.at("digits").get<int>() < 0 || j.at("digits").get<int>() > 40)
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "view.digits"}, {"problem", "not 0 ... 40"}}));
        view.digits = j.at("digits").get<int>();
    }
    return view;
}

RealType real_of(const std::string& name) {
    if (name == "float") return RealType::float_;
    if (name == "double") return RealType::double_;
    if (name == "quad") return RealType::quad_;
    if (name == "long-double") throw UsageError(ui_message("wasm_no_long_double"));
    throw UsageError(ui_message("wasm_bad_argument", {{"name", "real"}, {"problem", name}}));
}

Formula formula_of(const std::string& name) {
    if (name == "article") return Formula::article;
    if (name == "stable") return Formula::stable;
    if (name == "fma") return Formula::fma;
    if (name == "geometric") return Formula::geometric;
    throw UsageError(ui_message("wasm_bad_argument", {{"name", "formula"}, {"problem", name}}));
}

// The numeric settings of a trace or a render: {"real", "formula", "spp"}.
struct Settings {
    RealType real = RealType::double_;
    Formula formula = Formula::article;
    int spp = 1;
};

Settings settings_of(const char* settings_json) {
    const nlohmann::json j = object_argument(settings_json, "settings");
    Settings settings;
    settings.real = real_of(string_field(j, "real", "double", "settings"));
    settings.formula = formula_of(string_field(j, "formula", "article", "settings"));
    if (j.contains("spp")) {
        if (!j.at("spp").is_number_integer())
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "settings.spp"}, {"problem", "not a whole number"}}));
        settings.spp = j.at("spp").get<int>();
    }
    return settings;
}

const Scene& open_scene() {
    if (!state().scene) throw UsageError(ui_message("wasm_no_scene"));
    return *state().scene;
}

// ---- the view model -------------------------------------------------------

std::string path_of(const PixelTrace& trace, int group) {
    std::string path;
    for (int g = group; g >= 0; g = trace.groups[static_cast<std::size_t>(g)].parent) {
        const TraceGroup& t = trace.groups[static_cast<std::size_t>(g)];
        path = t.kind + "[" + std::to_string(t.index) + "]" + (path.empty() ? "" : "." + path);
    }
    return path;
}

json given_json(const GivenValue& value, const Vocabulary& vocabulary, const View& view) {
    const VocabularyEntry* entry = vocabulary.find(value.key);
    const std::string kind = entry ? entry->kind : "point";
    return {{"key", value.key},
            {"symbol", trace_symbol(vocabulary, value.key, view.language)},
            {"symbol_tex", entry ? entry->latex : value.key},
            {"value_full", shown_value_text(value.value, kind, view.language, 0)},
            {"value_shown", shown_value_text(value.value, kind, view.language, view.digits)}};
}

// The header's given values, from the scene the trace carries.
void fill_given(PixelTrace& trace) {
    if (trace.header.scene_content.empty()) return;
    try {
        const Scene scene = parse_scene(trace.header.scene_content, trace.header.scene_file);
        const TraceHeader made = trace_header(scene, trace.header.w);
        trace.header.given = made.given;
        trace.header.given_groups = made.given_groups;
    } catch (const std::exception&) {
        // A trace whose scene this version cannot read: shown without its given values.
    }
}

json make_view(PixelTrace trace, const View& view) {
    fill_given(trace);
    const Vocabulary& vocabulary = builtin_vocabulary();
    const Language language = view.language;
    const TraceHeader& h = trace.header;
    json header = {{"scene", h.scene_name}, {"scene_file", h.scene_file}, {"scene_hash", h.scene_hash},
                   {"w", h.w}, {"i", h.i}, {"j", h.j}, {"real", h.real}, {"formula", h.formula}, {"spp", h.spp},
                   {"effects", h.effects}};
    json skipped = json::array();
    for (const auto& [stage, reason] : h.skipped) skipped.push_back({{"id", stage}, {"reason", message(language, reason)}});
    header["skipped"] = skipped;
    json given = json::array();
    for (const GivenValue& value : h.given) given.push_back(given_json(value, vocabulary, view));
    header["given"] = given;
    json groups_given = json::array();
    for (const GivenGroup& group : h.given_groups) {
        json values = json::array();
        for (const GivenValue& value : group.values) values.push_back(given_json(value, vocabulary, view));
        groups_given.push_back({{"kind", group.kind}, {"index", group.index},
                                {"title", group_text(language, group.kind, group.index)}, {"values", values}});
    }
    header["given_groups"] = groups_given;

    json groups = json::array();
    for (std::size_t g = 0; g < trace.groups.size(); ++g) {
        const TraceGroup& t = trace.groups[g];
        groups.push_back({{"kind", t.kind}, {"index", t.index}, {"parent", t.parent},
                          {"title", group_text(language, t.kind, t.index)}, {"path", path_of(trace, static_cast<int>(g))}});
    }

    // Each formula with the pixel's numbers put in (trace/formula_numbers.hpp).
    const std::vector<std::string> numbers = formulas_with_numbers(trace, vocabulary, language, view.digits);
    // The trace's effect set picks each step's formula: computed once per trace.
    const std::string effects = effect_set(trace);
    json steps = json::array();
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const Step& step = trace.steps[k];
        const std::string key(key_name(step.key));
        const VocabularyEntry* entry = vocabulary.find(key);
        const std::string prefix = path_of(trace, step.group);
        const bool word = std::holds_alternative<std::string>(step.value);
        json s = {{"n", k + 1},
                  {"key", key},
                  {"path", prefix.empty() ? key : prefix + "." + key},
                  {"group", step.group},
                  {"kind", word ? std::string("word") : trace_kind(vocabulary, key)},
                  {"symbol", trace_symbol(vocabulary, key, language)},
                  {"symbol_tex", entry ? entry->latex : key},
                  {"formula_text", step_formula(entry, key, effects)},
                  {"formula_tex", step_formula(entry, key, effects, true)},
                  {"numbers_tex", numbers[k]},
                  {"description", entry ? (language == Language::pl ? entry->pl : entry->en) : ""},
                  {"value_full", trace_step_value_text(step, vocabulary, key, language, h.real, 0)},
                  {"value_shown", trace_step_value_text(step, vocabulary, key, language, h.real, view.digits)}};
        if (const Vec3d* v = std::get_if<Vec3d>(&step.value)) {
            json full = json::array(), shown = json::array();
            const double c[3] = {v->x, v->y, v->z};
            for (std::size_t n = 0; n < 3; ++n) {
                const Step one{step.key, StepValue{c[n]}, step.group,
                               step.real_text.size() == 3 ? std::vector<std::string>{step.real_text[n]}
                                                          : std::vector<std::string>{}};
                full.push_back(trace_step_value_text(one, vocabulary, "t", language, h.real, 0));
                shown.push_back(trace_step_value_text(one, vocabulary, "t", language, h.real, view.digits));
            }
            s["components_full"] = full;
            s["components_shown"] = shown;
        }
        if (std::isnan(step.digits_lost))
            s["digits_lost"] = nullptr;
        else
            s["digits_lost"] = rounded_digits(step.digits_lost);
        s["digits_lost_text"] = trace_digits_lost_mark(step, trace, language);
        s["alarm"] = !std::isnan(step.digits_lost) && loses_many_digits(step.digits_lost) && trace_step_alarm(step, trace);
        bool non_finite = false;
        if (const double* number = std::get_if<double>(&step.value)) non_finite = !std::isfinite(*number);
        if (const Vec3d* v = std::get_if<Vec3d>(&step.value))
            non_finite = !std::isfinite(v->x) || !std::isfinite(v->y) || !std::isfinite(v->z);
        s["non_finite"] = non_finite;
        steps.push_back(s);
    }

    const std::string branch(branch_name(trace.branch));
    const BranchEntry* about = vocabulary.find_branch(branch);
    const VocabularyEntry* result = vocabulary.find("I_P");
    const VocabularyEntry* mean = vocabulary.find("I_mean");
    auto result_text = [&](int digits) {
        if (!trace.result_real_text.empty()) {
            const Step exact{Key::E, StepValue{0.0}, -1, trace.result_real_text};
            return trace_step_value_text(exact, vocabulary, trace.result_rgb ? "m" : "I_P", language, h.real, digits);
        }
        return trace.result_rgb ? shown_value_text(StepValue{*trace.result_rgb}, "colour", language, digits)
                                : shown_number(trace.result, language, digits);
    };
    const bool computed = trace.branch == Branch::lit || trace.branch == Branch::shadowed || trace.samples;
    const std::string formula = !computed         ? ""
                                : trace.samples   ? (mean ? mean->formula : "")
                                : trace.hit_object.empty() ? (result ? result->formula : "")
                                                           : message(language, "trace_result_sum");
    json out = {{"lang", std::string(language_code(language))}, {"digits", view.digits}, {"header", header},
                {"groups", groups}, {"steps", steps}, {"branch", branch},
                {"branch_name", message(language, "branch_name_" + branch)},
                {"reason", about ? branch_about(vocabulary, trace.branch, effects, language) : ""},
                {"hit_object", trace.hit_object},
                {"hit_object_text", trace.hit_object.empty() ? "" : word_text(language, trace.hit_object)},
                {"I_P_full", result_text(0)}, {"I_P_shown", result_text(view.digits)}, {"I_P_formula", formula},
                {"grey", trace.grey}};
    out["rgb"] = trace.result_rgb ? json::array({trace.rgb[0], trace.rgb[1], trace.rgb[2]}) : json(nullptr);
    std::string samples;
    if (trace.samples) {
        std::string counts, only;
        for (int b = 0; b < branch_count; ++b) {
            const int n = trace.samples->branches[static_cast<std::size_t>(b)];
            if (n == 0) continue;
            only = message(language, "branch_name_" + std::string(branch_name(static_cast<Branch>(b))));
            counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + only;
        }
        samples = trace.samples->agree()
                      ? message(language, "trace_samples_agree", {{"spp", std::to_string(h.spp)}, {"branch", only}})
                      : message(language, "trace_samples_disagree",
                                {{"counts", counts}, {"centre", std::to_string(trace.samples->centre)},
                                 {"spp", std::to_string(h.spp)}});
    }
    out["samples_text"] = samples;
    out["first_non_finite"] = trace.first_non_finite ? json(*trace.first_non_finite + 1) : json(nullptr);
    // The text trace's closing notes, unwrapped.
    json notes = json::array();
    for (const Step& step : trace.steps)
        if (step.key == Key::cos_alpha && step.group < 0)
            if (const double* c = std::get_if<double>(&step.value); c && std::fabs(*c) > 1 + 1e-6)
                notes.push_back(message(language, "trace_cos_above_one", {{"cos", shown_number(*c, language, 4)}}));
    if (trace.first_non_finite && *trace.first_non_finite < trace.steps.size()) {
        const std::size_t k = *trace.first_non_finite;
        const std::string key(key_name(trace.steps[k].key));
        notes.push_back(message(language,
                                trace.branch == Branch::non_finite ? "trace_non_finite_decides" : "trace_non_finite_lesson",
                                {{"k", std::to_string(k + 1)},
                                 {"symbol", trace_symbol(vocabulary, key, language)},
                                 {"value", shown_value_text(trace.steps[k].value, trace_kind(vocabulary, key), language, 0)}}));
    }
    bool marked = false;
    for (const Step& step : trace.steps)
        if (!std::isnan(step.digits_lost) && loses_many_digits(step.digits_lost) && trace_step_alarm(step, trace))
            marked = true;
    if (marked)
        notes.push_back(message(language, "trace_digits_lost_about",
                                {{"half", number_text(full_digits_of(h.real) / 2, language, 1)}}));
    out["notes"] = notes;
    return out;
}

// ---- lessons -----------------------------------------------------------------

// The pixels argument: [[i, j], ...], each inside a pane of w.
std::vector<LessonPixel> pixels_of(const nlohmann::json& j, int w) {
    std::vector<LessonPixel> pixels;
    if (!j.contains("pixels")) return pixels;
    const nlohmann::json& list = j.at("pixels");
    const auto bad = [] { return UsageError(ui_message("wasm_bad_argument", {{"name", "lesson.pixels"}, {"problem", "not [[i, j], ...]"}})); };
    if (!list.is_array()) throw bad();
    for (const nlohmann::json& p : list) {
        if (!p.is_array() || p.size() != 2 || !p[0].is_number_integer() || !p[1].is_number_integer()) throw bad();
        const int i = p[0].get<int>(), jj = p[1].get<int>();
        if (i < 0 || jj < 0 || i >= w || jj >= w)
            throw UsageError(ui_message(
                "wasm_bad_pixel", {{"i", std::to_string(i)}, {"j", std::to_string(jj)}, {"w", std::to_string(w)}}));
        pixels.push_back({i, jj});
    }
    return pixels;
}

// A file name without its folders ("lessons/scenes/x.json" -> "x.json").
std::string base_name(const std::string& path) {
    const std::size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Rows first_row .. first_row + row_count - 1 of a w-row pane, or UsageError
// (promyk_render_rows and promyk_map_values share a worker's share of rows).
void require_rows(int first_row, int row_count, int w) {
    if (first_row < 0 || row_count < 1 || first_row >= w || row_count > w - first_row)
        throw UsageError(ui_message("wasm_bad_argument", {{"name", "rows"},
                                                         {"problem", std::to_string(first_row) + " + " +
                                                                         std::to_string(row_count)}}));
}

}  // namespace

extern "C" {

PROMYK_EXPORT const char* promyk_version() {
    return answer([] {
        json out = {{"version", PROMYK_VERSION},
                    {"reals", {"float", "double", "quad"}},
                    {"formulas", {"article", "stable", "fma", "geometric"}},
                    {"long_double", PROMYK_HAS_X87_LONG_DOUBLE != 0},
                    {"long_double_why", message(ui_language(), "wasm_no_long_double")}};
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_open_scene(const char* scene_json, const char* scene_file, int w) {
    return answer([&] {
        if (w < 1 || w > max_w)
            throw UsageError(ui_message("wasm_bad_w", {{"w", std::to_string(w)}, {"max", std::to_string(max_w)}}));
        const std::string_view text = scene_json ? scene_json : "";
        const std::string file = scene_file && *scene_file ? scene_file : "(scene)";
        Scene scene = text.empty() ? article_scene() : load_scene_text(text, file);
        json out = {{"ok", true}, {"scene", scene.name}, {"scene_hash", scene_hash(scene)}, {"w", w}};
        out["effects"] = trace_header(scene, w).effects;
        out["scene_content"] = json::parse(scene_to_json(scene, SceneDefaults::written));
        state().rows = RowKernel{};  // made for the scene it replaces
        state().scene = std::move(scene);
        state().scene_file = scene_file && *scene_file ? scene_file : "";
        state().w = w;
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_trace(int i, int j, const char* settings_json) {
    return answer([&] {
        const Scene& scene = open_scene();
        const int w = state().w;
        if (i < 0 || j < 0 || i >= w || j >= w)
            throw UsageError(ui_message(
                "wasm_bad_pixel", {{"i", std::to_string(i)}, {"j", std::to_string(j)}, {"w", std::to_string(w)}}));
        const Settings settings = settings_of(settings_json);
        std::string out;
        append_trace_json(out, trace_pixel(scene, w, i, j, settings.real, settings.formula, settings.spp));
        return out;
    });
}

PROMYK_EXPORT const char* promyk_render_rows(int first_row, int row_count, const char* settings_json) {
    return answer([&] {
        const Scene& scene = open_scene();
        const int w = state().w;
        require_rows(first_row, row_count, w);
        const Settings settings = settings_of(settings_json);
        RowKernel& made = state().rows;
        if (!made.kernel || made.real != settings.real || made.formula != settings.formula || made.spp != settings.spp)
            made = RowKernel{settings.real, settings.formula, settings.spp,
                             make_kernel(scene, settings.real, settings.formula, settings.spp)};
        const Kernel& kernel = *made.kernel;
        const std::size_t width = static_cast<std::size_t>(w);
        const std::size_t row_bytes = width * static_cast<std::size_t>(kernel.channels());
        std::vector<std::uint8_t>& pixels = state().pixels;
        std::vector<std::uint8_t>& branch = state().branch;
        pixels.assign(row_bytes * static_cast<std::size_t>(row_count), 0);
        branch.assign(width * static_cast<std::size_t>(row_count), 0);
        for (int k = 0; k < row_count; ++k) {
            const int i = first_row + k;
            // The row as `promyk render` computes it (the same kernel), and
            // each pixel's category as `render --map branch` draws it.
            kernel.row(w, i, pixels.data() + row_bytes * static_cast<std::size_t>(k));
            for (int j = 0; j < w; ++j)
                branch[width * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)] =
                    static_cast<std::uint8_t>(branch_category(kernel.notes(w, i, j)));
        }
        json out = {{"ok", true}, {"first_row", first_row}, {"rows", row_count}, {"w", w},
                    {"channels", kernel.channels()},
                    {"image", reinterpret_cast<std::uintptr_t>(pixels.data())}, {"image_bytes", pixels.size()},
                    {"branch", reinterpret_cast<std::uintptr_t>(branch.data())}, {"branch_bytes", branch.size()}};
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_view(const char* trace_json, const char* view_json) {
    return answer([&] {
        const View view = view_of(view_json);
        return make_view(read_trace_json(trace_json ? trace_json : "", "(trace)"), view).dump();
    });
}

PROMYK_EXPORT const char* promyk_compare(const char* trace_a_json, const char* trace_b_json, const char* view_json) {
    return answer([&] {
        const View view = view_of(view_json);
        const PixelTrace a = read_trace_json(trace_a_json ? trace_a_json : "", "(trace A)");
        const PixelTrace b = read_trace_json(trace_b_json ? trace_b_json : "", "(trace B)");
        const Vocabulary& vocabulary = builtin_vocabulary();
        auto settings = [](const TraceHeader& h) { return json{{"real", h.real}, {"formula", h.formula}, {"spp", h.spp}}; };
        // Each step by its path and occurrence ("t" twice: t#0, t#1), in A's order then B's extra ones.
        auto keyed = [](const PixelTrace& trace) {
            std::vector<std::pair<std::string, const Step*>> out;
            std::map<std::string, int> seen;
            for (const Step& step : trace.steps) {
                const std::string prefix = path_of(trace, step.group);
                const std::string path = (prefix.empty() ? "" : prefix + ".") + std::string(key_name(step.key));
                out.emplace_back(path + "#" + std::to_string(seen[path]++), &step);
            }
            return out;
        };
        const auto steps_a = keyed(a), steps_b = keyed(b);
        auto texts = [](const Step& step) {
            // The exact texts compared: real_text, else the double's shortest text.
            std::vector<std::string> out = step.real_text;
            if (!out.empty()) return out;
            if (const double* x = std::get_if<double>(&step.value)) return std::vector<std::string>{number_text(*x, Language::en)};
            if (const Vec3d* v = std::get_if<Vec3d>(&step.value))
                return std::vector<std::string>{number_text(v->x, Language::en), number_text(v->y, Language::en),
                                                number_text(v->z, Language::en)};
            return std::vector<std::string>{};
        };
        json steps = json::array();
        auto add = [&](const std::string& id, const Step* sa, const Step* sb) {
            const Step& any = sa ? *sa : *sb;
            const std::string key(key_name(any.key));
            const std::string path = id.substr(0, id.rfind('#'));
            json s = {{"path", path}, {"symbol", trace_symbol(vocabulary, key, view.language)},
                      {"kind", trace_kind(vocabulary, key)}};
            s["a_full"] = sa ? trace_step_value_text(*sa, vocabulary, key, view.language, a.header.real, 0) : "";
            s["b_full"] = sb ? trace_step_value_text(*sb, vocabulary, key, view.language, b.header.real, 0) : "";
            s["a_shown"] = sa ? trace_step_value_text(*sa, vocabulary, key, view.language, a.header.real, view.digits) : "";
            s["b_shown"] = sb ? trace_step_value_text(*sb, vocabulary, key, view.language, b.header.real, view.digits) : "";
            json agree = nullptr;
            std::string marked;
            if (sa && sb) {
                const std::vector<std::string> ta = texts(*sa), tb = texts(*sb);
                if (!ta.empty() && ta.size() == tb.size()) {
                    int least = -1;
                    for (std::size_t n = 0; n < ta.size(); ++n) {
                        const int d = agreeing_digits(ta[n], a.header.real, tb[n], b.header.real);
                        if (d >= 0 && (least < 0 || d < least)) least = d;
                        marked += (n ? (view.language == Language::pl ? "; " : ", ") : "") +
                                  local_number_text(d < 0 ? ta[n] : mark_digits(ta[n], d), view.language);
                    }
                    agree = least;
                    if (ta.size() == 3) marked = "[" + marked + "]";
                }
            }
            s["a_marked"] = marked;
            s["agree"] = agree;
            steps.push_back(s);
        };
        for (const auto& [id, sa] : steps_a) {
            const Step* sb = nullptr;
            for (const auto& [other, step] : steps_b)
                if (other == id) sb = step;
            add(id, sa, sb);
        }
        for (const auto& [id, sb] : steps_b) {
            bool in_a = false;
            for (const auto& [other, step] : steps_a) in_a = in_a || other == id;
            if (!in_a) add(id, nullptr, sb);
        }
        json out = {{"a", settings(a.header)}, {"b", settings(b.header)}, {"steps", steps},
                    {"branch_a", std::string(branch_name(a.branch))}, {"branch_b", std::string(branch_name(b.branch))}};
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_open_traces(const char* bytes, int length) {
    return answer([&] {
        if (length < 0 || (length > 0 && bytes == nullptr))
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "length"}, {"problem", std::to_string(length)}}));
        TraceFile file = read_trace_file(std::string_view(bytes ? bytes : "", static_cast<std::size_t>(length)), "(trace file)");
        const TraceHeader& h = file.traces.front().header;
        json pixels = json::array();
        for (const PixelTrace& trace : file.traces) pixels.push_back({trace.header.i, trace.header.j});
        json out = {{"ok", true}, {"count", file.traces.size()}, {"w", h.w}, {"scene", h.scene_name},
                    {"scene_file", h.scene_file}, {"scene_hash", h.scene_hash}, {"real", h.real}, {"formula", h.formula}, {"spp", h.spp},
                    {"pixels", pixels}};
        state().traces = std::move(file);
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_trace_from_file(int i, int j) {
    return answer([&]() -> std::string {
        if (!state().traces) throw UsageError(ui_message("wasm_no_trace_file"));
        const TraceFile& file = *state().traces;
        for (std::size_t k = 0; k < file.traces.size(); ++k)
            if (file.traces[k].header.i == i && file.traces[k].header.j == j) return file.lines[k];
        return error_json(ui_message("wasm_no_trace_pixel", {{"i", std::to_string(i)}, {"j", std::to_string(j)}}), 1);
    });
}

PROMYK_EXPORT const char* promyk_legend(const char* lang) {
    return answer([&] {
        const Language language = language_of(lang ? lang : "en");
        set_ui_language(language);
        json categories = json::array();
        for (int k = 0; k < branch_category_count; ++k) {
            const LegendColour& c = branch_colour(static_cast<BranchCategory>(k));
            const std::string name_id = branch_category_message(static_cast<BranchCategory>(k));
            const std::string id = name_id.substr(name_id.find("_name_") + 6);  // miss, ..., tangent, behind
            categories.push_back({{"index", k}, {"id", id}, {"name", message(language, name_id)},
                                  {"colour", std::string(c.colour)}, {"hex", std::string(c.hex)},
                                  {"rgb", {c.rgb.r, c.rgb.g, c.rgb.b}}});
        }
        return json{{"categories", categories}}.dump();
    });
}

PROMYK_EXPORT const char* promyk_messages(const char* lang) {
    return answer([&] {
        const Language language = language_of(lang ? lang : "en");
        set_ui_language(language);
        json messages = json::object();
        for (const std::string& id : message_ids(language)) messages[id] = message(language, id);
        json vocabulary = json::object();
        for (const VocabularyEntry& e : builtin_vocabulary().keys)
            vocabulary[e.key] = {{"kind", e.kind}, {"symbol", trace_symbol(builtin_vocabulary(), e.key, language)},
                                 {"symbol_tex", e.latex}, {"formula_text", e.formula}, {"formula_tex", e.formula_latex},
                                 {"description", language == Language::pl ? e.pl : e.en}};
        json branches = json::object();
        for (const BranchEntry& b : builtin_vocabulary().branches)
            branches[b.branch] = language == Language::pl ? b.pl : b.en;
        return json{{"lang", std::string(language_code(language))}, {"messages", messages},
                    {"vocabulary", vocabulary}, {"branches", branches}}
            .dump();
    });
}

// --- lessons and worksheets (issue 17) ---------------------------------------
}  // extern "C"

namespace {

// A lesson run as promyk_lesson, promyk_worksheet_file and promyk_check_answers
// run it (API.md): the lesson and its scene live as long as the run.
struct LessonCall {
    Language language = Language::en;
    std::optional<Lesson> lesson;
    std::optional<Scene> own;
    LessonRunOptions options;
    std::unique_ptr<LessonRun> run;
    std::unique_ptr<Worksheet> worksheet;  // with "worksheet": true
    std::string html;                       // the lesson's HTML, or the worksheet's
};

std::unique_ptr<LessonCall> lesson_call(const char* name, const char* options_json, bool worksheet) {
    auto call = std::make_unique<LessonCall>();
    const nlohmann::json j = object_argument(options_json, "lesson");
    const Language language = language_of(string_field(j, "lang", "en", "lesson"));
    call->language = language;
    set_ui_language(language);
    const std::string where = string_field(j, "scene", "own", "lesson");
    if (where != "own" && where != "open")
        throw UsageError(ui_message("wasm_bad_argument", {{"name", "lesson.scene"}, {"problem", where}}));
    if (j.contains("worksheet")) {
        if (!j.at("worksheet").is_boolean())
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "lesson.worksheet"}, {"problem", "not true or false"}}));
        worksheet = worksheet || j.at("worksheet").get<bool>();
    }
    const LessonLibrary library;
    const std::string wanted = name ? name : "";
    call->lesson = library.find(wanted, language);
    if (!call->lesson) throw UsageError(ui_message("wasm_bad_argument", {{"name", "lesson"}, {"problem", wanted}}));
    const Lesson& lesson = *call->lesson;
    require_runnable(lesson);
    call->own.emplace(library.scene(lesson.header.scene));
    // "open": the page's scene at the page's w, the lesson's own when it is
    // the same scene (by hash), else another scene as `lesson --scene FILE`.
    const bool open = where == "open";
    const Scene& scene = open ? open_scene() : *call->own;
    LessonRunOptions& options = call->options;
    options.w = open ? state().w : lesson.header.w;
    options.own_scene = !open || scene_hash(scene) == scene_hash(*call->own);
    options.scene_file = options.own_scene ? lesson.header.scene : base_name(state().scene_file);
    options.pixels = pixels_of(j, options.w);
    if (options.pixels.empty())
        for (const LessonPixel& pixel : lesson.header.pixels) {
            if (pixel.i >= options.w || pixel.j >= options.w)
                throw UsageError(ui_message("lesson_pixel_outside", {{"i", std::to_string(pixel.i)},
                                                                     {"j", std::to_string(pixel.j)},
                                                                     {"w", std::to_string(options.w)}}));
            options.pixels.push_back(pixel);
        }
    options.digits = lesson.header.digits;
    if (j.contains("digits")) {
        if (!j.at("digits").is_number_integer() || j.at("digits").get<int>() < 0 || j.at("digits").get<int>() > 40)
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "lesson.digits"}, {"problem", "not 0 ... 40"}}));
        options.digits = j.at("digits").get<int>();
    }
    options.real = lesson_real(lesson);
    options.formula = lesson_formula(lesson);
    if (options.real == RealType::long_double) throw UsageError(ui_message("wasm_no_long_double"));
    options.spp = lesson.header.spp;
    options.format = LessonFormat::html;
    call->run = std::make_unique<LessonRun>(lesson, scene, options);
    if (!worksheet) {
        call->html = call->run->document();
        return call;
    }
    // The worksheet as `promyk lesson NAME --worksheet --format html` prints
    // it with --key: the blanks are fields, the answers left out, the answer
    // file's form at the end, then the answer key (the page shows it only
    // when a teacher prints the key, as it shows a lesson's answers).
    LessonView& view = call->run->view();
    call->worksheet = std::make_unique<Worksheet>(view);
    call->html = render_lesson_title(view) + call->worksheet->intro();
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) call->html += "\n" + call->worksheet->fields(render_step(view, k));
    call->html += call->worksheet->answer_template() + call->worksheet->answer_key();
    return call;
}

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::right: return "right";
        case Verdict::right_more_digits: return "right_more_digits";
        case Verdict::right_nearer: return "right_nearer";
        case Verdict::wrong_way: return "wrong_way";
        case Verdict::wrong: return "wrong";
        case Verdict::not_reached: return "not_reached";
        case Verdict::wrong_shape: return "wrong_shape";
        case Verdict::blank: return "blank";
        case Verdict::unreadable: return "unreadable";
    }
    return "wrong";
}

// The worksheet's blanks, as the page fills them in.
json blanks_json(const Worksheet& worksheet) {
    json blanks = json::array();
    for (const WorksheetBlank& blank : worksheet.blanks()) {
        const auto [path, settings] = split_settings(blank.key);
        blanks.push_back({{"n", blank.number}, {"i", blank.i}, {"j", blank.j},
                          {"key", qualified_path(path, blank.component, settings)}});
    }
    return blanks;
}

}  // namespace

extern "C" {

PROMYK_EXPORT const char* promyk_lessons(const char* lang) {
    return answer([&] {
        const Language language = language_of(lang ? lang : "en");
        set_ui_language(language);
        const LessonLibrary library;
        std::vector<LessonProblem> problems;
        json lessons = json::array();
        for (const Lesson& lesson : library.lessons(problems)) {
            if (lesson.language != language) continue;
            const Scene scene = library.scene(lesson.header.scene);
            json pixels = json::array();
            for (const LessonPixel& p : lesson.header.pixels) pixels.push_back({p.i, p.j});
            lessons.push_back({{"name", lesson.header.name}, {"title", lesson.header.title},
                               {"summary", lesson.header.summary}, {"scene", lesson.header.scene},
                               {"scene_name", scene.name}, {"scene_hash", scene_hash(scene)},
                               {"w", lesson.header.w}, {"pixels", pixels}, {"effect", lesson.header.effect},
                               {"steps", lesson.steps.size()}});
        }
        return json{{"lang", std::string(language_code(language))}, {"lessons", lessons}}.dump();
    });
}

PROMYK_EXPORT const char* promyk_lesson(const char* name, const char* options_json) {
    return answer([&] {
        const std::unique_ptr<LessonCall> call = lesson_call(name, options_json, false);
        const Lesson& lesson = *call->lesson;
        const LessonRunOptions& options = call->options;
        json pixels = json::array();
        for (const LessonPixel& p : options.pixels) pixels.push_back({p.i, p.j});
        json out = {{"name", lesson.header.name}, {"lang", std::string(language_code(call->language))},
                    {"title", lesson.header.title}, {"scene", call->run->view().scene_name},
                    {"scene_file", options.scene_file}, {"own_scene", options.own_scene}, {"w", options.w},
                    {"pixels", pixels}, {"steps", lesson.steps.size()}, {"html", call->html}};
        if (call->worksheet) {
            out["blanks"] = blanks_json(*call->worksheet);
            out["command"] = call->worksheet->check_command();
            out["file"] = message(call->language, "worksheet_file");
        }
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_worksheet_file(const char* name, const char* options_json, const char* typed_json) {
    return answer([&] {
        const std::unique_ptr<LessonCall> call = lesson_call(name, options_json, true);
        const nlohmann::json typed = object_argument(typed_json, "typed");
        std::map<int, std::string> values;
        for (auto it = typed.begin(); it != typed.end(); ++it) {
            const std::string& key = it.key();
            if (key.empty() || key.size() > 9 || key.find_first_not_of("0123456789") != std::string::npos || !it.value().is_string())
                throw UsageError(ui_message("wasm_bad_argument", {{"name", "typed." + key}, {"problem", "not a blank's text"}}));
            values[std::stoi(key)] = it.value().get<std::string>();
        }
        const Worksheet& worksheet = *call->worksheet;
        // A comment first: which command checks the file (the reader skips it).
        const std::string text = "# " + worksheet.check_command() + "\n" + worksheet.answer_lines(values);
        return json{{"file", message(call->language, "worksheet_file")}, {"command", worksheet.check_command()}, {"text", text}}
            .dump();
    });
}

PROMYK_EXPORT const char* promyk_check_answers(const char* name, const char* options_json, const char* answers_text) {
    return answer([&] {
        const std::unique_ptr<LessonCall> call = lesson_call(name, options_json, true);
        const std::string file = message(call->language, "worksheet_file");
        const std::vector<AnswerCheck> checks = check_lesson_answers(*call->run, answers_text ? answers_text : "", file);
        const LessonView& view = call->run->view();
        // Each mark with its blank, by pixel and key.
        std::map<std::tuple<int, int, std::string>, int> blank_of;
        for (const WorksheetBlank& blank : call->worksheet->blanks()) {
            const auto [path, settings] = split_settings(blank.key);
            blank_of[{blank.i, blank.j, qualified_path(path, blank.component, settings)}] = blank.number;
        }
        std::map<std::pair<int, int>, const PixelTrace*> trace_of;
        for (const PixelTrace& trace : view.traces) trace_of.emplace(std::make_pair(trace.header.i, trace.header.j), &trace);
        json marks = json::array();
        for (const AnswerCheck& check : checks) {
            const auto [path, settings] = split_settings(check.answer.key);
            const std::string key = check.answer.key.empty() ? "" : qualified_path(path, check.answer.component, settings);
            const auto found = trace_of.find({check.pixel.i, check.pixel.j});
            const AnswerMark mark = answer_mark(check, found == trace_of.end() ? nullptr : found->second, view.vocabulary,
                                                call->language, view.others);
            const auto blank = blank_of.find({check.pixel.i, check.pixel.j, key});
            marks.push_back({{"i", check.pixel.i}, {"j", check.pixel.j}, {"key", key},
                             {"blank", blank == blank_of.end() ? json(nullptr) : json(blank->second)},
                             {"verdict", verdict_name(check.verdict)}, {"id", mark.id}, {"text", mark.text},
                             {"line", check.answer.line}});
        }
        const std::string report = answers_report(checks, view.traces, view.vocabulary, call->language, view.others);
        std::string summary = report.substr(0, report.size() - 1);
        summary = summary.substr(summary.rfind('\n') + 1);
        return json{{"marks", marks}, {"all_right", all_right(checks)}, {"summary", summary}, {"report", report}}.dump();
    });
}

}  // extern "C"

// ---- the precision lab (issue 17): the error and digits-lost overlays ----
// (API.md, "The precision lab"). The map's values are computed by the render
// workers, a share of the rows each, as export computes them natively
// (MapKernel::pixel_value); the page's own instance colours the whole pane
// and gives the legend (render/map_overlay.hpp), the same C++ as
// `render --map`.

namespace {

MapKind lab_map_kind(const char* name) {
    const std::optional<MapKind> kind = parse_map_name(name ? name : "");
    if (!kind || *kind == MapKind::branch)
        throw UsageError(ui_message("wasm_bad_argument", {{"name", "kind"}, {"problem", name ? name : ""}}));
    return *kind;
}

struct LabState {
    std::string key;                 // scene hash, w, kind, settings of `map`
    std::unique_ptr<MapKernel> map;  // its values do not depend on the range given
    std::vector<double> values;      // promyk_map_values' rows
    std::vector<std::uint8_t> rgb;   // promyk_map_colour's pane
};

LabState& lab() {
    static LabState s;
    return s;
}

}  // namespace

extern "C" {

PROMYK_EXPORT const char* promyk_map_values(const char* kind_name, int first_row, int row_count,
                                            const char* settings_json) {
    return answer([&] {
        const MapKind kind = lab_map_kind(kind_name);
        const Scene& scene = open_scene();
        const int w = state().w;
        require_rows(first_row, row_count, w);
        const Settings settings = settings_of(settings_json);
        const std::string key = scene_hash(scene) + "|" + std::to_string(w) + "|" + std::string(map_name(kind)) + "|" +
                                std::string(real_type_name(settings.real)) + "|" +
                                std::string(formula_name(settings.formula)) +
                                "|" + std::to_string(settings.spp);
        LabState& made = lab();
        if (!made.map || made.key != key) {
            made.map = make_map_kernel(kind, scene, settings.real, settings.formula, settings.spp, w,
                                       std::pair<double, double>{1e-20, 1});
            made.key = key;
        }
        made.values.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(row_count), 0);
        for (int k = 0; k < row_count; ++k)
            for (int j = 0; j < w; ++j)
                made.values[static_cast<std::size_t>(k) * static_cast<std::size_t>(w) + static_cast<std::size_t>(j)] =
                    made.map->pixel_value(w, first_row + k, j);
        json out = {{"ok", true}, {"first_row", first_row}, {"rows", row_count}, {"w", w},
                    {"values", reinterpret_cast<std::uintptr_t>(made.values.data())},
                    {"values_bytes", made.values.size() * sizeof(double)}};
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_map_colour(const char* kind_name, const char* settings_json, const double* values,
                                            int count, const char* options_json) {
    return answer([&] {
        const MapKind kind = lab_map_kind(kind_name);
        const Settings settings = settings_of(settings_json);
        if (count < 0 || (count > 0 && values == nullptr))
            throw UsageError(ui_message("wasm_bad_argument", {{"name", "count"}, {"problem", std::to_string(count)}}));
        const nlohmann::json options = object_argument(options_json, "options");
        const Language language = language_of(string_field(options, "lang", "en", "options"));
        set_ui_language(language);
        std::optional<std::pair<double, double>> range;
        if (options.contains("range") && !options.at("range").is_null()) {
            const nlohmann::json& r = options.at("range");
            if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
                !(r[0].get<double>() > 0) || !(r[1].get<double>() > r[0].get<double>()) ||
                !std::isfinite(r[1].get<double>()))
                throw UsageError(ui_message("wasm_bad_argument", {{"name", "options.range"}, {"problem", r.dump()}}));
            range = std::pair<double, double>{r[0].get<double>(), r[1].get<double>()};
        }
        LabState& made = lab();
        json out = map_overlay(kind, settings.real, values, static_cast<std::size_t>(count), range, language, made.rgb);
        out["ok"] = true;
        out["rgb"] = reinterpret_cast<std::uintptr_t>(made.rgb.data());
        out["rgb_bytes"] = made.rgb.size();
        return out.dump();
    });
}

PROMYK_EXPORT const char* promyk_map_value_text(const char* kind_name, double stored, const char* lang) {
    return answer([&] {
        const MapKind kind = lab_map_kind(kind_name);
        const Language language = language_of(lang ? lang : "en");
        return json{{"text", map_value_text(kind, stored, language)}}.dump();
    });
}

}  // extern "C"
