#include "lesson/lesson_check.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "lesson/lesson_render.hpp"
#include "trace/messages.hpp"
#include "util/text.hpp"

namespace promyk {

namespace {

bool is_special(const std::string& name) { return name == "i" || name == "j" || name == "w" || name == "branch"; }

std::string branch_list(const Vocabulary& vocabulary) {
    std::string out;
    for (const BranchEntry& branch : vocabulary.branches) out += (out.empty() ? "" : ", ") + branch.branch;
    return out;
}

// The keys the tracer records in each group (render/general_tracer.hpp), and
// the scene's values a one-group path names. A new step in a group is added
// here too; a test traces scenes of every shape and finds each step allowed.
struct GroupShape {
    std::string_view path;  // the kinds from the top level: "light.sphere"
    std::vector<std::string_view> keys;
};

const std::vector<GroupShape>& group_shapes() {
    static const std::vector<GroupShape> shapes = {
        {"sphere", {"EE", "SS", "C", "delta", "Delta", "sqrt_Delta", "t", "t_far", "found", "S", "r"}},
        {"plane", {"n_hat", "NQ", "NE", "t_plane", "found", "Q", "n"}},
        {"light", {"K", "KK", "K_len", "K_P", "D", "cos_alpha", "blocker", "diffuse", "R_hat", "RV", "RV_2", "RV_4",
                   "RV_8", "RV_16", "RV_32", "RV_64", "RV_128", "RV_256", "RV_512", "RV_1024", "RV_2048", "RV_4096",
                   "RV_8192", "RV_n", "specular", "contribution", "L", "I", "c"}},
        {"material", {"k_a", "k_d", "k_s", "exponent", "m"}},  // the scene's only: no trace group
        {"light.sphere", {"b_s", "c_s", "delta_s", "s_1", "P_s1", "d_s1", "s_2", "found", "s_own"}},
        {"light.plane", {"NK", "s", "found"}},
    };
    return shapes;
}

// How many objects of a kind the scene has.
std::size_t count_of(const Scene& scene, const std::string& kind) {
    return kind == "sphere"   ? scene.spheres.size()
           : kind == "plane"  ? scene.planes.size()
           : kind == "light"  ? scene.lights.size()
                              : scene.materials.size();
}

// Calls f(placeholder, line) for each placeholder of the part, with the
// file line it stands on. The placeholders come in order: the lines are
// counted once, not from the start for each.
template <class F>
void for_each_placeholder(const LessonPart& part, F&& f) {
    int line = part.text_line;
    std::size_t counted = 0;
    for (const Placeholder& placeholder : find_placeholders(part.text)) {
        line += static_cast<int>(std::count(part.text.begin() + static_cast<long>(counted),
                                            part.text.begin() + static_cast<long>(placeholder.begin), '\n'));
        counted = placeholder.begin;
        f(placeholder, line);
    }
}

}  // namespace

PathCheck check_path(const std::string& text, const Vocabulary& vocabulary, const Scene* scene) {
    const std::optional<ValuePath> path = parse_value_path(text);
    if (!path) return {PathFault::malformed, "", ""};
    if (vocabulary.find(path->key) == nullptr) return {PathFault::unknown_key, "", ""};
    std::string kinds;
    // A sample (--spp) holds a whole pixel's computation: what follows it is
    // checked as a path from the top level.
    const std::size_t first = !path->groups.empty() && path->groups.front().kind == "sample" ? 1 : 0;
    for (std::size_t g = first; g < path->groups.size(); ++g) {
        const PathGroup& group = path->groups[g];
        const std::string name = group.kind + "[" + std::to_string(group.index) + "]";
        if (group.kind != "sphere" && group.kind != "plane" && group.kind != "light" && group.kind != "material")
            return {PathFault::unknown_group, group.kind, "sphere, plane, light, material, sample (first)"};
        kinds += (kinds.empty() ? "" : ".") + group.kind;
        const auto shape = std::find_if(group_shapes().begin(), group_shapes().end(),
                                        [&](const GroupShape& s) { return s.path == kinds; });
        if (shape == group_shapes().end()) return {PathFault::nesting, name, ""};
        if (scene != nullptr && static_cast<std::size_t>(group.index) >= count_of(*scene, group.kind))
            return {PathFault::index, name, std::to_string(count_of(*scene, group.kind))};
        if (g + 1 == path->groups.size() &&
            std::find(shape->keys.begin(), shape->keys.end(), path->key) == shape->keys.end())
            return {PathFault::not_in_group, name, joined(shape->keys)};
    }
    return {};
}

bool depends_on_pixel(const std::string& name, const Vocabulary& vocabulary) {
    if (name == "w") return false;
    if (is_special(name)) return true;
    if (parse_value_path(name) && !parse_value_path(name)->groups.empty()) return !is_scene_value(name);
    const VocabularyEntry* entry = vocabulary.find(name);
    return entry == nullptr || !entry->given;
}

void check_lesson(const Lesson& lesson, const Vocabulary& vocabulary, std::vector<LessonProblem>& problems,
                  const Scene* scene) {
    const auto problem = [&](int line, std::string_view id, const MessageArgs& args) {
        problems.push_back({lesson.file, line, message(lesson.language, id, args)});
    };
    // A path's fault, if any, reported at `line`; true when there was none.
    const auto path_ok = [&](const std::string& path, int line) {
        const PathCheck check = check_path(path, vocabulary, scene);
        switch (check.fault) {
            case PathFault::none:
                return true;
            case PathFault::malformed:
            case PathFault::unknown_key:
                problem(line, "error_unknown_key", {{"key", path}});
                break;
            case PathFault::unknown_group:
                problem(line, "error_unknown_group", {{"path", path}, {"kind", check.group}, {"kinds", check.keys}});
                break;
            case PathFault::nesting:
                problem(line, "error_group_nesting", {{"path", path}, {"group", check.group}});
                break;
            case PathFault::not_in_group:
                problem(line, "error_key_not_in_group",
                        {{"path", path}, {"key", path_key(path)}, {"group", check.group}, {"keys", check.keys}});
                break;
            case PathFault::index:
                problem(line, "error_group_index",
                        {{"path", path}, {"group", check.group}, {"count", check.keys}, {"scene", lesson.header.scene}});
                break;
        }
        return false;
    };
    // A settings qualifier (after @) names a real type and/or a formula, each once.
    const auto settings_ok = [&](const std::string& qualified, const std::string& settings, int line) {
        if (settings.empty() && qualified.find('@') == std::string::npos) return true;
        if (parse_settings(settings)) return true;
        problem(line, "error_unknown_setting", {{"key", qualified}, {"settings", settings}});
        return false;
    };
    // A wildcard (sphere[*]) stands for every object of its kind: checked as the first.
    const auto unstarred = [](std::string path) {
        for (std::size_t star = path.find("[*]"); star != std::string::npos; star = path.find("[*]", star))
            path.replace(star, 3, "[0]");
        return path;
    };
    const auto conditions_ok = [&](const std::vector<Condition>& conditions, int line) {
        for (const Condition& condition : conditions) {
            if (condition.op == Condition::Op::on_scene) continue;
            const auto [bare, settings] = split_settings(condition.path);
            if (settings_ok(condition.path, settings, line)) path_ok(bare, line);
        }
    };
    const auto branches_ok = [&](const std::vector<std::string>& branches, int line) {
        for (const std::string& branch : branches)
            if (vocabulary.find_branch(branch) == nullptr)
                problem(line, "error_unknown_branch", {{"branch", branch}, {"branches", branch_list(vocabulary)}});
    };
    for (const LessonStep& step : lesson.steps) {
        branches_ok(step.needs_branches, step.needs_line);
        conditions_ok(step.needs, step.needs_line);
        for (const LessonPart& part : step.parts) {
            if (part.kind == PartKind::values) {
                for (const std::string& key : part.keys) {
                    const auto [bare, settings] = split_settings(key);
                    const bool star = bare.find("[*]") != std::string::npos;
                    if (settings_ok(key, settings, part.line)) {
                        const PathCheck check = check_path(unstarred(bare), vocabulary, scene);
                        // A wildcard in a scene without that kind of object is no fault: it shows no row.
                        if (!(star && check.fault == PathFault::index)) path_ok(unstarred(bare), part.line);
                    }
                }
                continue;
            }
            branches_ok(part.branches, part.line);
            conditions_ok(part.conditions, part.line);
            for_each_placeholder(part, [&](const Placeholder& placeholder, int line) {
                if (!placeholder.valid) {
                    problem(line, "error_bad_placeholder", {{"text", placeholder.name}});
                    return;
                }
                // {i}, {j}, {w}, {branch} are no keys; anything else is a path to check.
                const bool special = placeholder.path == placeholder.name && is_special(placeholder.name);
                if (special && !placeholder.settings.empty()) {
                    problem(line, "error_bad_placeholder", {{"text", std::string(part.text.substr(placeholder.begin, placeholder.end - placeholder.begin))}});
                    return;
                }
                if (!settings_ok(qualified_path(placeholder), placeholder.settings, line)) return;
                if (!special && !path_ok(placeholder.path, line)) return;
                // Prose names the step's pixel ({i}, {j}), never its numbers.
                const bool step_pixel = placeholder.path == "i" || placeholder.path == "j";
                if ((part.kind == PartKind::prose || part.kind == PartKind::scene) && !placeholder.symbol && !step_pixel &&
                    depends_on_pixel(placeholder.path, vocabulary))
                    problem(line, "error_pixel_outside_block", {{"key", placeholder.path}});
            });
        }
    }
}

std::vector<std::string> lesson_keys(const Lesson& lesson, const Vocabulary& vocabulary) {
    std::vector<std::string> out;
    std::set<std::string> seen;
    const auto add = [&](const std::string& qualified) {
        std::string path = split_settings(qualified).first;
        // P.x: the key is P.
        if (path.size() > 2 && path[path.size() - 2] == '.' && std::string_view("xyz").find(path.back()) != std::string_view::npos)
            path.resize(path.size() - 2);
        const VocabularyEntry* entry = vocabulary.find(path_key(path));
        if (entry == nullptr || entry->kind == "word" || is_scene_value(path)) return;
        if (seen.insert(qualified).second) out.push_back(qualified);
    };
    for (const LessonStep& step : lesson.steps) {
        for (const LessonPart& part : step.parts) {
            if (part.kind == PartKind::values) {
                for (const std::string& key : part.keys) add(key);
                continue;
            }
            for (const Placeholder& placeholder : find_placeholders(part.text))
                if (placeholder.valid && !placeholder.symbol && !(placeholder.path == placeholder.name && is_special(placeholder.name)))
                    add(qualified_path(placeholder));
        }
    }
    return out;
}

std::vector<SettingsUse> settings_used(const Lesson& lesson) {
    std::vector<SettingsUse> out;
    for (const LessonStep& step : lesson.steps) {
        for (const LessonPart& part : step.parts) {
            if (part.kind == PartKind::values) {
                for (const std::string& key : part.keys)
                    if (key.find('@') != std::string::npos) out.push_back({split_settings(key).second, key, part.line});
                continue;
            }
            for_each_placeholder(part, [&](const Placeholder& placeholder, int line) {
                if (placeholder.valid && !placeholder.settings.empty())
                    out.push_back({placeholder.settings, qualified_path(placeholder), line});
            });
        }
    }
    return out;
}

void check_translations(const std::vector<Lesson>& lessons, std::vector<LessonProblem>& problems) {
    std::map<std::string, std::vector<const Lesson*>> by_name;
    for (const Lesson& lesson : lessons) by_name[lesson.header.name].push_back(&lesson);
    const auto step_ids = [](const Lesson& lesson) {
        std::string ids;
        for (const LessonStep& step : lesson.steps) ids += (ids.empty() ? "" : ", ") + step.id;
        return ids;
    };
    for (const auto& [name, versions] : by_name) {
        if (name.empty()) continue;  // a lesson without a name is already reported at its header
        // Two files of one language with the same name: only the first would ever run.
        for (std::size_t a = 0; a < versions.size(); ++a)
            for (std::size_t b = 0; b < a; ++b)
                if (versions[a]->language == versions[b]->language) {
                    problems.push_back({versions[a]->file, versions[a]->header.name_line,
                                        message(versions[a]->language, "error_name_twice",
                                                {{"name", name}, {"other", versions[b]->file}})});
                    break;
                }
        for (const Language language : {Language::pl, Language::en}) {
            const bool present = std::any_of(versions.begin(), versions.end(),
                                             [&](const Lesson* lesson) { return lesson->language == language; });
            if (present) continue;
            for (const Lesson* lesson : versions)
                problems.push_back({lesson->file, 1,
                                    message(lesson->language, "error_missing_translation",
                                            {{"name", name}, {"lang", std::string(language_code(language))}})});
        }
        for (const Lesson* lesson : versions) {
            for (const Lesson* other : versions) {
                if (other == lesson || other->language == lesson->language) continue;
                if (step_ids(*lesson) != step_ids(*other))
                    problems.push_back({lesson->file, lesson->steps.empty() ? 1 : lesson->steps.front().line,
                                        message(lesson->language, "error_step_mismatch",
                                                {{"lang", std::string(language_code(other->language))},
                                                 {"other", other->file},
                                                 {"here", step_ids(*lesson)},
                                                 {"there", step_ids(*other)}})});
            }
        }
    }
}

}  // namespace promyk
