#include "trace/vocabulary.hpp"

#include <nlohmann/json.hpp>

#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace embedded {
extern const std::string_view embedded_vocabulary_json;
}

namespace {

std::string required_string(const nlohmann::json& object, const char* field, const std::string& source,
                            const std::string& pointer) {
    const auto it = object.find(field);
    if (it == object.end() || !it->is_string())
        throw InputError(source, pointer + "/" + field, ui_message("vocabulary_missing_field", {{"field", field}}));
    return it->get<std::string>();
}

}  // namespace

const VocabularyEntry* Vocabulary::find(std::string_view key) const {
    for (const VocabularyEntry& entry : keys)
        if (entry.key == key) return &entry;
    return nullptr;
}

const BranchEntry* Vocabulary::find_branch(std::string_view branch) const {
    for (const BranchEntry& entry : branches)
        if (entry.branch == branch) return &entry;
    return nullptr;
}

Vocabulary parse_vocabulary(std::string_view text, const std::string& source) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        throw InputError(source, "", error.what());
    }
    if (!document.is_object() || !document.contains("keys") || !document["keys"].is_array())
        throw InputError(source, "/keys", ui_message("vocabulary_needs_keys"));
    Vocabulary vocabulary;
    for (std::size_t k = 0; k < document["keys"].size(); ++k) {
        const nlohmann::json& item = document["keys"][k];
        const std::string pointer = "/keys/" + std::to_string(k);
        VocabularyEntry entry;
        entry.key = required_string(item, "key", source, pointer);
        entry.kind = required_string(item, "kind", source, pointer);
        entry.symbol = required_string(item, "symbol", source, pointer);
        entry.latex = required_string(item, "latex", source, pointer);
        entry.program = required_string(item, "program", source, pointer);
        entry.formula = required_string(item, "formula", source, pointer);
        entry.formula_latex = required_string(item, "formula_latex", source, pointer);
        entry.pl = required_string(item, "pl", source, pointer);
        entry.en = required_string(item, "en", source, pointer);
        if (const auto given = item.find("given"); given != item.end()) {
            if (!given->is_boolean()) throw InputError(source, pointer + "/given", ui_message("vocabulary_given_boolean"));
            entry.given = given->get<bool>();
        }
        if (const auto term = item.find("term_of_sum"); term != item.end()) {
            if (!term->is_boolean())
                throw InputError(source, pointer + "/term_of_sum", ui_message("vocabulary_term_of_sum_boolean"));
            entry.term_of_sum = term->get<bool>();
        }
        if (vocabulary.find(entry.key)) throw InputError(source, pointer + "/key", ui_message("vocabulary_duplicate_key", {{"key", entry.key}}));
        vocabulary.keys.push_back(std::move(entry));
    }
    const auto branches = document.find("branches");
    if (branches != document.end() && branches->is_array()) {
        for (std::size_t k = 0; k < branches->size(); ++k) {
            const std::string pointer = "/branches/" + std::to_string(k);
            vocabulary.branches.push_back({required_string((*branches)[k], "branch", source, pointer),
                                           required_string((*branches)[k], "pl", source, pointer),
                                           required_string((*branches)[k], "en", source, pointer)});
        }
    }
    return vocabulary;
}

const Vocabulary& builtin_vocabulary() {
    static const Vocabulary vocabulary =
        parse_vocabulary(embedded::embedded_vocabulary_json, "lessons/vocabulary.json (built in)");
    return vocabulary;
}

}  // namespace promyk
