// The instruction set the article's rows are drawn with, chosen once at
// start: the widest this processor has (baseline x86-64, AVX2, AVX-512), or
// the one PROMYK_ISA names. One binary runs everywhere; each path draws
// every pixel bit for bit as the literal program does.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace promyk {

enum class Isa { baseline, avx2, avx512 };

// "baseline", "avx2", "avx512": PROMYK_ISA's values, and bench's labels.
const char* isa_name(Isa isa);
std::optional<Isa> isa_from_name(const std::string& name);
// Compiled into this binary (not in the wasm) and run by this processor.
bool isa_supported(Isa isa);
// Every supported path, baseline first.
std::vector<Isa> supported_isas();

// Reads PROMYK_ISA once (unset or empty: the widest supported path).
// Throws UsageError for a value that names no path or one this processor
// lacks. Called by main; article_isa() calls it too if main did not.
void choose_isa_from_environment();
// The path in use, and a way to change it (bench speed times each path;
// not while rows are drawn).
Isa article_isa();
void set_article_isa(Isa isa);

}  // namespace promyk
