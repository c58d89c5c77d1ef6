// A lesson: a header (name, title, summary, scene, w, pixels) and steps, each
// a sequence of parts: prose, value tables, blocks shown per pixel for some
// branches, and answers. lessons/README.md describes the file format.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "trace/number_text.hpp"

namespace promyk {

// A placeholder's format: N >= 0 decimals ({key:N}); or the lesson's shown
// significant digits ({key}: 4, or --digits N); or every digit ({key:all},
// the shortest text that reads back to the same number, for the steps that
// are about digits).
inline constexpr int shown_digits_default = -1;
inline constexpr int every_digit = -2;

struct LessonPixel {
    int i = 0, j = 0;
};

struct LessonHeader {
    std::string name, title, summary;
    std::string scene = "article";  // "article" or a file name in lessons/scenes/
    int w = 8;
    std::vector<LessonPixel> pixels = {{0, 0}, {5, 1}, {3, 4}};
    std::string columns = "double/article";
    // The numbers' real type and formula (--real, --formula): the names
    // real_type_name and formula_name give them.
    std::string real = "double";
    std::string formula = "article";
    int spp = 1;  // samples per pixel (spp:, --spp): the centre sample tells the story
    // Significant digits of the values shown without a format of their own
    // (digits:, --digits): 4, as every lesson; 0 ("all") every digit, for a
    // lesson about digits (precision).
    int digits = 4;
    int name_line = 1;   // the line of "name:", for messages about the name
    int scene_line = 1;  // the line of "scene:", for messages about the scene
    // The effect the lesson is about (effect:): spheres, lights, plane,
    // shadows, phong or colour; on a scene without it the lesson says so.
    std::string effect;
};

enum class PartKind {
    prose,   // Markdown; placeholders only of the scene's values
    values,  // "= key key ...": a table, one row a key, one column a pixel
    block,   // "::: branch ...": shown once per pixel whose branch is listed
    answer,  // "::: answer": revealed on request
    scene,   // "::: scene [FILE]": prose shown only on that scene (none: the lesson's own)
    figure,  // "::: figure pane": the chosen pane drawn by branch (one line, no body)
};

// A condition on a pixel's values, in a block's or a step's "needs" line:
// "has:t" (the computation reached t), "no:t", "D>0", "light[0].D<=0", "t<1.5";
// and "on:own" (the lesson runs on its own scene) or "on:FILE" (on that scene).
struct Condition {
    enum class Op { exists, missing, less, less_equal, greater, greater_equal, on_scene, is_word };
    std::string path;  // a path, with a settings qualifier if written; on_scene: the file, empty for the own
    Op op = Op::exists;
    double bound = 0;
    std::string word;  // is_word: the step's word as the trace writes it ("plane 0" for plane[0])
    std::string text;  // as written, for messages
};

// Reads one condition token; nothing when it has no condition's form.
std::optional<Condition> parse_condition(const std::string& token);

struct LessonPart {
    PartKind kind = PartKind::prose;
    int line = 0;                       // the part's first line in the file (a block's ":::")
    int text_line = 0;                  // the line where `text` starts
    std::string text;                   // prose, block, answer: the lines, joined by '\n'
    std::vector<std::string> keys;      // values
    std::vector<std::string> branches;  // block: the branch names; empty for "pixel" (every pixel)
    std::vector<Condition> conditions;  // block: every one must hold too
    std::string scene;                  // scene: the scene's file name; empty: the lesson's own
    std::string figure;                 // figure: what to draw ("pane")
};

struct LessonStep {
    std::string id, title;
    int line = 0;
    std::vector<LessonPart> parts;
    // "::: needs lit has:light[0].s_1": the step is about a pixel of one of
    // these branches (none: any) where every condition holds.
    std::vector<std::string> needs_branches;
    std::vector<Condition> needs;
    int needs_line = 0;
};

struct Lesson {
    std::string file;  // as shown in messages, e.g. "pl/03-sphere.md"
    Language language = Language::en;
    LessonHeader header;
    std::vector<LessonStep> steps;
};

// A fault in a lesson file, with its line, worded in the lesson's language.
struct LessonProblem {
    std::string file;
    int line = 0;
    std::string message;
};

// Reads a lesson. Faults of form (header, blocks, headings) are appended to
// `problems`; the lesson is returned as far as it could be read.
Lesson parse_lesson(std::string_view text, const std::string& file, Language language,
                    std::vector<LessonProblem>& problems);

// Where a value is in a trace: the groups from the top level down (none for
// a top-level step), then the key. "light[0].sphere[1].delta_s" is
// {{light, 0}, {sphere, 1}}, delta_s; "t" is the top level's t.
struct PathGroup {
    std::string kind;  // sphere, plane, light (lesson_check says which exist)
    int index = 0;
};

struct ValuePath {
    std::vector<PathGroup> groups;
    std::string key;
};

// Reads "kind[N].kind[N].key" (any number of groups, N at most 6 digits);
// nothing if the text has another form. A component (.x) is not part of a path.
std::optional<ValuePath> parse_value_path(std::string_view text);

// The key a path ends in: "sphere[1].t" -> "t", "t" -> "t".
std::string path_key(const std::string& path);

// A placeholder inside a part's text: {key}, {key:N}, {key.x}, {symbol:key},
// {i}, {j}, {w}, {branch}, and each key also inside groups: {sphere[1].t},
// {light[0].sphere[1].delta_s:4}, {light[0].K.x}.
struct Placeholder {
    std::size_t begin = 0, end = 0;  // the braces' span in the text
    std::string name;                // the key, or i, j, w, branch
    std::string path;                // the groups and the key ("sphere[1].t"); the name when there are no groups
    char component = 0;              // 'x', 'y', 'z' or 0
    std::string settings;            // "@float,geometric" without the @; empty: the lesson's
    int decimals = shown_digits_default;  // N decimals ({key:N}); or as below
    bool symbol = false;             // {symbol:key}
    bool valid = true;               // false: malformed (text kept in `name`)
};

// The path with its component and settings qualifier, as lessons, worksheets
// and answer files write it: "P.x@float", "delta@float,geometric", "t".
std::string qualified_path(const Placeholder& placeholder);
std::string qualified_path(const std::string& path, char component, const std::string& settings);

// A settings qualifier ("float", "geometric", "float,geometric"): a real type
// and/or a formula, each at most once, either order.
struct SettingsQualifier {
    std::string real;     // empty: the lesson's
    std::string formula;  // empty: the lesson's
};

// Nothing when an item is not a real type or formula name, or names two of a kind.
std::optional<SettingsQualifier> parse_settings(std::string_view text);

// "delta@float" -> {"delta", "float"}; "P.x@quad" -> {"P.x", "quad"}; "t" -> {"t", ""}.
std::pair<std::string, std::string> split_settings(const std::string& qualified);

// The real types' and formulas' names, as --real and --formula take them.
bool is_real_name(std::string_view name);
bool is_formula_name(std::string_view name);

// The placeholders of a text, in order. "{{" and "}}" stand for literal
// braces, and a brace right after a letter, '\', '^', '_' or '}' is LaTeX's
// ($\frac{a}{b}$, $x^{2}$), not a placeholder.
std::vector<Placeholder> find_placeholders(std::string_view text);

}  // namespace promyk
