// A lesson with the real numbers of its pixels, as terminal text, as
// Markdown ($…$ math, tables, <details> for answers), or as HTML for the web
// page (every text escaped, TeX in <span class="math"> for KaTeX, each step a
// <section data-step>, its answers in <details> after it).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson.hpp"
#include "scene/scene.hpp"
#include "trace/trace.hpp"
#include "trace/vocabulary.hpp"

namespace promyk {

enum class LessonFormat { text, markdown, html };

struct LessonView {
    const Lesson& lesson;
    const Vocabulary& vocabulary;
    std::vector<PixelTrace> traces;  // one a pixel column, in the order chosen
    std::string scene_name;
    int w = 8;
    LessonFormat format = LessonFormat::text;
    bool color = false;  // terminal text only: bold headings
    // Worksheets (lesson/worksheet.hpp): when set, each value of a pixel that
    // a table or a block shows is asked for here first; a text returned takes
    // the number's place (a blank), nothing keeps the number.
    std::function<std::optional<std::string>(const PixelTrace& trace, const std::string& key, char component)> shown_value{};
    // The same pixels in the other numeric settings the lesson's qualifiers
    // name ({delta@float}, = t@geometric): looked up by pixel, real and formula.
    std::vector<PixelTrace> others{};
    // Significant digits of a value shown without a format of its own
    // ({key}, tables): 4, or the command line's --digits.
    int digits = 4;
    // The scene the lesson runs on: its objects (wildcard rows, sphere[*].t)
    // and effects; nullptr: rows are not expanded.
    const Scene* scene = nullptr;
    // The scene's file name ("two_lights.json"; "article" for the built-in
    // one), for "::: scene FILE" blocks; and whether it is the lesson's own.
    std::string scene_file{};
    bool own_scene = true;
    // Any pixel of the pane at the view's w (a step's needs, the figure);
    // empty: none is searched.
    std::function<const PixelTrace&(int i, int j)> pane_pixel{};
};

// True when the scene has the effect a lesson's "effect:" names (spheres:
// more than one; lights: more than one; plane; shadows; phong; colour).
bool scene_has_effect(const Scene& scene, const std::string& effect);

// True when the condition holds for the pixel ("has:t", "D>0").
bool condition_holds(const LessonView& view, const PixelTrace& trace, const Condition& condition);

// True when a block is shown for the pixel: its branch is listed (or none
// is) and every condition holds.
bool block_shown_for(const LessonView& view, const LessonPart& part, const PixelTrace& trace);

// The pixel a step is about: the first chosen one that has what the step
// needs (its "::: needs" line) and reached every value its answers name;
// nullptr when none has.
const PixelTrace* step_pixel(const LessonView& view, const LessonStep& step);

// The first pixel of the pane (row by row) that has what the step needs, or nullptr.
std::optional<LessonPixel> pane_pixel_for(const LessonView& view, const LessonStep& step);

// A table's keys with every wildcard (sphere[*].t) made one key an object
// of the scene, and rows naming an object the scene lacks left out.
std::vector<std::string> expanded_keys(const LessonView& view, const std::vector<std::string>& keys);



// The lesson's title, summary and setup (scene, pane, pixels).
std::string render_lesson_title(const LessonView& view);

// Step k (0-based) without its answers; with `numbered`, "Step k of n".
std::string render_step(const LessonView& view, std::size_t k);

// Step k's answers, or an empty string when it has none.
std::string render_answers(const LessonView& view, std::size_t k);

bool has_answers(const LessonStep& step);

// The value a placeholder or a value table names, for one pixel's trace;
// nothing where the pixel's computation did not reach it.
// `key` is a path (lesson.hpp): "t" is the top level's t, "sphere[1].t" the
// t of sphere 1's test, "light[0].sphere[1].delta_s" that of the shadow ray
// towards light 0 against sphere 1. A one-group path also names the scene's
// values of that object: sphere[1].S, sphere[1].r, light[0].L, light[0].I.
std::optional<StepValue> lesson_value(const PixelTrace& trace, const std::string& key);

// A value with its exact text in its own real type: `real_text` holds one
// text (or three, a point's or vector's) for a non-double trace, none for
// double and for the scene's values.
struct LessonNumber {
    StepValue value;
    std::vector<std::string> real_text;
    std::string real = "double";
};

// The value a qualified path names ("delta@float", "t@geometric",
// "sphere[0].delta@quad,geometric"; a component is the caller's): in the
// trace of the same pixel in those settings, which `others` holds (a setting
// the qualifier leaves out is `trace`'s own). Nothing where the pixel did not
// reach it, or no trace of those settings is at hand.
std::optional<LessonNumber> lesson_number(const PixelTrace& trace, const std::string& qualified,
                                          const std::vector<PixelTrace>& others);

// The same, through the view's traces.
std::optional<LessonNumber> lesson_number(const LessonView& view, const PixelTrace& trace, const std::string& qualified);

// The trace of `trace`'s pixel in the settings the qualifier names ("float",
// "quad,geometric", "" for `trace` itself), or nullptr.
const PixelTrace* settings_trace(const PixelTrace& trace, const std::string& settings, const std::vector<PixelTrace>& others);

// The (real, formula) a qualifier means on top of the lesson's own.
std::pair<std::string, std::string> resolve_settings(const std::string& settings, const std::string& real,
                                                     const std::string& formula);

// One component ('x', 'y', 'z') of a point's or vector's number; the number itself for 0.
LessonNumber component_of(const LessonNumber& number, char component);

// A number as a lesson shows it: in double (and for the scene's values) as
// value_text does; in another real type its exact text in that type, or with
// `decimals` >= 0 that exact value rounded to so many decimals. The Polish way in Polish.
// `decimals` shown_digits_default: rounded to `digits` significant digits;
// every_digit: the exact shortest text.
std::string lesson_number_text(const LessonNumber& number, const std::string& kind, Language language,
                               int decimals = every_digit, int digits = 4);

// True for a value of the scene, the same for every pixel: a top-level given
// key (S, r, L, I, z_E, background) and sphere[k].S, sphere[k].r, light[k].L,
// light[k].I, plane[k].n_hat, plane[k].NQ. Prose may name them; a worksheet
// keeps them filled in.
bool is_scene_value(const std::string& key);

// Where a value comes in the pixel's derivation, for sorting (smaller first):
// the scene's values, then the trace's steps in their order; a value the
// pixel never reached goes after the last step whose key comes before its
// own in the vocabulary (t of a miss after Δ/4), and I_P comes last.
std::size_t derivation_rank(const PixelTrace& trace, const Vocabulary& vocabulary, const std::string& key);

}  // namespace promyk
