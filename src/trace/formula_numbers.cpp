#include "trace/formula_numbers.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <variant>

#include "trace/intensity_formula.hpp"
#include "trace/number_text.hpp"
#include "trace/trace_text.hpp"

namespace promyk {

namespace {

// A quantity's shown value, and its components when it is a point or vector.
struct Known {
    std::string text;
    std::vector<std::string> components;  // x, y, z; empty for a scalar
};

// Other spellings of a symbol in the vocabulary's formulas.
const std::map<std::string, std::vector<std::string>>& aliases() {
    static const std::map<std::string, std::vector<std::string>> table = {{"\\tfrac{\\Delta}{4}", {"\\Delta/4"}}};
    return table;
}

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

bool single_capital(const std::string& tex) { return tex.size() == 1 && tex[0] >= 'A' && tex[0] <= 'Z'; }

// The quantities known at a point of the derivation, by their TeX symbol.
class Scope {
public:
    void learn(const std::string& tex, const std::string& text, std::vector<std::string> components = {}) {
        if (tex.empty()) return;
        known_[tex] = Known{text, components};
        if (auto other = aliases().find(tex); other != aliases().end())
            for (const std::string& alias : other->second) known_[alias] = Known{text, components};
    }

    const Known* find(const std::string& tex) const {
        const auto it = known_.find(tex);
        return it == known_.end() ? nullptr : &it->second;
    }

    // The symbols, longest first: a longer one (|\vec{E}|^2) wins over its part (\vec{E}).
    std::vector<std::string> literals() const {
        std::vector<std::string> out;
        for (const auto& [tex, known] : known_) out.push_back(tex);
        std::stable_sort(out.begin(), out.end(), [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
        return out;
    }

private:
    std::map<std::string, Known> known_;
};

std::vector<std::string> components_of(const StepValue& value, Language language, int digits) {
    const Vec3d* v = std::get_if<Vec3d>(&value);
    if (!v) return {};
    return {shown_number(v->x, language, digits), shown_number(v->y, language, digits), shown_number(v->z, language, digits)};
}

// The right-hand side of `tex` (after its last '=' outside braces) with the
// known quantities replaced by their numbers; "" when nothing is known.
std::string with_numbers(const std::string& tex, const Scope& scope) {
    int depth = 0;
    std::optional<std::size_t> last;
    for (std::size_t k = 0; k < tex.size(); ++k) {
        if (tex[k] == '{') ++depth;
        else if (tex[k] == '}') --depth;
        else if (tex[k] == '=' && depth == 0) last = k;
    }
    if (!last) return "";
    const std::string rhs = tex.substr(*last + 1);
    // A minimum over a set or a sum over samples has no single number per symbol.
    if (rhs.find("\\min\\{") != std::string::npos || rhs.find("\\sum") != std::string::npos) return "";
    const std::vector<std::string> literals = scope.literals();
    const auto at = [&](std::size_t k) -> char { return k < rhs.size() ? rhs[k] : '\0'; };
    std::string out;
    int replaced = 0;
    bool previous_was_number = false;
    for (std::size_t k = 0; k < rhs.size();) {
        const char before = k > 0 ? rhs[k - 1] : '\0';
        std::optional<std::string> value;
        std::size_t length = 0;
        // x_E, y_{S}: a component of a point or vector.
        if ((at(k) == 'x' || at(k) == 'y' || at(k) == 'z') && at(k + 1) == '_' && !is_letter(before)) {
            std::string name;
            std::size_t used = 0;
            if (at(k + 2) == '{' && is_letter(at(k + 3)) && at(k + 4) == '}') name = std::string(1, at(k + 3)), used = 5;
            else if (is_letter(at(k + 2))) name = std::string(1, at(k + 2)), used = 3;
            const Known* known = name.empty() ? nullptr : scope.find(name);
            if (!known || known->components.empty()) known = name.empty() ? nullptr : scope.find("\\vec{" + name + "}");
            if (known && known->components.size() == 3) {
                value = known->components[static_cast<std::size_t>(at(k) - 'x')];
                length = used;
            }
        }
        if (!value) {
            for (const std::string& literal : literals) {
                if (rhs.compare(k, literal.size(), literal) != 0) continue;
                const char after = at(k + literal.size());
                if (is_letter(literal.front()) && (is_letter(before) || before == '\\')) continue;
                if (is_letter(literal.back()) && (is_letter(after) || after == '_')) continue;
                value = scope.find(literal)->text;
                length = literal.size();
                break;
            }
        }
        if (value) {
            // A product written by juxtaposition (2j, 4|E|², C·C) keeps its dot.
            std::size_t end = out.find_last_not_of(' ');
            const bool after_operand =
                end != std::string::npos && (std::isdigit(static_cast<unsigned char>(out[end])) || out[end] == '}' || out[end] == ')');
            if (previous_was_number || after_operand) out += "\\cdot ";
            out += tex_number(*value);
            k += length;
            ++replaced;
            previous_was_number = true;
            continue;
        }
        std::size_t piece = 1;
        if (rhs[k] == '\\')
            while (is_letter(at(k + piece))) ++piece;
        out.append(rhs, k, piece);
        if (!(piece == 1 && std::isspace(static_cast<unsigned char>(rhs[k])))) previous_was_number = false;
        k += piece;
    }
    return replaced > 0 ? out : "";
}

bool in_kind(const PixelTrace& trace, int group, const std::string& kind) {
    for (int g = group; g >= 0 && g < static_cast<int>(trace.groups.size()); g = trace.groups[static_cast<std::size_t>(g)].parent)
        if (trace.groups[static_cast<std::size_t>(g)].kind == kind) return true;
    return false;
}

bool in_object(const PixelTrace& trace, int group) {
    for (int g = group; g >= 0 && g < static_cast<int>(trace.groups.size()); g = trace.groups[static_cast<std::size_t>(g)].parent) {
        const std::string& kind = trace.groups[static_cast<std::size_t>(g)].kind;
        if (kind == "sphere" || kind == "plane") return true;
    }
    return false;
}

}  // namespace

std::string tex_number(const std::string& shown) {
    std::string safe;
    for (const char c : shown) {
        if (c == '\\') safe += "\\backslash ";
        else if (std::string_view("{}$%#&_^~").find(c) != std::string_view::npos) safe += std::string("\\") + c;
        else safe += c;
    }
    const bool plain = !shown.empty() && shown.find_first_not_of("0123456789.,") == std::string::npos;
    const bool bracketed = !shown.empty() && (shown.front() == '(' || shown.front() == '[');
    return plain || bracketed ? "\\text{" + safe + "}" : "\\left(\\text{" + safe + "}\\right)";
}

std::vector<std::string> formulas_with_numbers(const PixelTrace& trace, const Vocabulary& vocabulary,
                                               Language language, int digits) {
    const TraceHeader& h = trace.header;
    Scope scope;
    scope.learn("i", std::to_string(h.i));
    scope.learn("j", std::to_string(h.j));
    scope.learn("w", std::to_string(h.w));
    const auto learn_given = [&](const GivenValue& given) {
        const VocabularyEntry* entry = vocabulary.find(given.key);
        const std::string tex = entry ? entry->latex : given.key;
        const std::string text = shown_value_text(given.value, entry ? entry->kind : "point", language, digits);
        std::vector<std::string> components = components_of(given.value, language, digits);
        scope.learn(tex, text, components);
        if (single_capital(tex)) scope.learn("\\vec{" + tex + "}", text, components);
    };
    for (const GivenValue& given : h.given) learn_given(given);
    const auto learn_group = [&](const std::string& kind, int index) {
        for (const GivenGroup& group : h.given_groups)
            if (group.kind == kind && group.index == index)
                for (const GivenValue& given : group.values) learn_given(given);
    };
    // A group's given values (an object's S, r; a light's L, I) are learned
    // as the derivation enters it, its enclosing groups first.
    std::set<int> opened;
    const auto open = [&](int group, const auto& self) -> void {
        if (group < 0 || group >= static_cast<int>(trace.groups.size()) || opened.count(group)) return;
        const TraceGroup& g = trace.groups[static_cast<std::size_t>(group)];
        self(g.parent, self);
        opened.insert(group);
        learn_group(g.kind, g.index);
    };
    // After the objects' tests, S, r, Q, n are the hit object's again.
    std::string hit_kind;
    int hit_index = -1;
    if (const std::size_t space = trace.hit_object.find(' '); space != std::string::npos) {
        hit_kind = trace.hit_object.substr(0, space);
        hit_index = std::atoi(trace.hit_object.c_str() + space + 1);
    }
    bool objects_learned = false;

    // I_P's and a light's contribution's formulas are the scene's effect set's.
    const std::string effects = effect_set(trace);
    std::vector<std::string> out;
    out.reserve(trace.steps.size());
    for (const Step& step : trace.steps) {
        if (in_object(trace, step.group)) objects_learned = true;
        else if (objects_learned && hit_index >= 0) {
            learn_group(hit_kind, hit_index);
            objects_learned = false;
        }
        open(step.group, open);
        const std::string key(key_name(step.key));
        const VocabularyEntry* entry = vocabulary.find(key);
        // A sample's E is the pixel's centre moved by (u, v): the centre's
        // formula with i, j, w put in would not give its value.
        const bool jittered = step.key == Key::E && in_kind(trace, step.group, "sample");
        const std::string formula_latex = entry ? step_formula(entry, key, effects, true) : std::string();
        out.push_back(!formula_latex.empty() && !jittered ? with_numbers(formula_latex, scope) : "");
        if (!entry || entry->latex.empty()) continue;
        // What this step found is known from here on, under its symbol.
        const std::string text = trace_step_value_text(step, vocabulary, key, language, h.real, digits);
        std::vector<std::string> components;
        if (const Vec3d* v = std::get_if<Vec3d>(&step.value)) {
            const double c[3] = {v->x, v->y, v->z};
            for (std::size_t n = 0; n < 3; ++n) {
                const Step one{step.key, StepValue{c[n]}, step.group,
                               step.real_text.size() == 3 ? std::vector<std::string>{step.real_text[n]} : std::vector<std::string>{}};
                components.push_back(trace_step_value_text(one, vocabulary, "t", language, h.real, digits));
            }
        }
        scope.learn(entry->latex, text, components);
        // The program's name on the formula's left (C for E·S, D for N·K).
        const std::string& formula = formula_latex;
        const std::size_t name = formula.find_first_not_of(' ');
        if (name != std::string::npos && is_letter(formula[name])) {
            const std::size_t equals = formula.find_first_not_of(' ', name + 1);
            if (equals != std::string::npos && formula[equals] == '=' && std::string(1, formula[name]) != entry->latex)
                scope.learn(std::string(1, formula[name]), text, components);
        }
        if (single_capital(entry->latex) || (entry->latex.size() == 3 && single_capital(entry->latex.substr(0, 1)) &&
                                             entry->latex.compare(1, 2, "_P") == 0))
            scope.learn("\\vec{" + entry->latex + "}", text, components);
    }
    return out;
}

}  // namespace promyk
