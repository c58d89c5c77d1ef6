// The shared vocabulary (lessons/vocabulary.json, embedded at build time):
// for every trace key its symbol, formula and descriptions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace promyk {

struct VocabularyEntry {
    std::string key;
    std::string kind;    // "scalar", "point" or "vector"
    std::string symbol;  // as the article writes it, in Unicode
    std::string latex;
    std::string program;  // the name the article's program uses
    std::string formula;  // plain Unicode text
    std::string formula_latex;
    std::string pl, en;  // short descriptions
    bool given = false;  // a value of the scene (S, r, ...), the same for every pixel
    // A term of the intensity's sum (a light's diffuse part, its highlight,
    // its contribution): where the computation did not reach it, it adds
    // nothing, and prose shows 0, never a dash inside a sum.
    bool term_of_sum = false;
};

struct BranchEntry {
    std::string branch;
    std::string pl, en;
};

struct Vocabulary {
    std::vector<VocabularyEntry> keys;
    std::vector<BranchEntry> branches;

    const VocabularyEntry* find(std::string_view key) const;
    const BranchEntry* find_branch(std::string_view branch) const;
};

// Parses vocabulary text; throws InputError naming `source` on a malformed file.
Vocabulary parse_vocabulary(std::string_view text, const std::string& source);

// The vocabulary built into the binary (parsed once).
const Vocabulary& builtin_vocabulary();

}  // namespace promyk
