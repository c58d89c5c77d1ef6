#include "render/isa.hpp"

#include <atomic>
#include <cstdlib>

#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace {

constexpr Isa all_isas[] = {Isa::baseline, Isa::avx2, Isa::avx512};

// -1 until chosen.
std::atomic<int> chosen{-1};

std::string names_of(const std::vector<Isa>& isas) {
    std::string text;
    for (const Isa isa : isas) text += (text.empty() ? "" : ", ") + std::string(isa_name(isa));
    return text;
}

}  // namespace

const char* isa_name(Isa isa) {
    switch (isa) {
        case Isa::avx2:
            return "avx2";
        case Isa::avx512:
            return "avx512";
        default:
            return "baseline";
    }
}

std::optional<Isa> isa_from_name(const std::string& name) {
    for (const Isa isa : all_isas)
        if (name == isa_name(isa)) return isa;
    return std::nullopt;
}

bool isa_supported(Isa isa) {
    if (isa == Isa::baseline) return true;
#if defined(PROMYK_ISA_KERNELS)
    // The flags each translation unit is compiled with (src/CMakeLists.txt).
    if (isa == Isa::avx2) return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (isa == Isa::avx512)
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
               __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
               __builtin_cpu_supports("fma");  // -mavx512f alone leaves fma a call
#endif
    return false;  // the wasm, and processors other than x86-64: the baseline only
}

std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (const Isa isa : all_isas)
        if (isa_supported(isa)) isas.push_back(isa);
    return isas;
}

void choose_isa_from_environment() {
    const char* value = std::getenv("PROMYK_ISA");
    Isa isa = supported_isas().back();  // the widest
    if (value && *value) {
        const std::optional<Isa> named = isa_from_name(value);
        if (!named)
            throw UsageError(ui_message("isa_unknown", {{"value", value}, {"paths", names_of(supported_isas())}}));
        if (!isa_supported(*named))
            throw UsageError(ui_message("isa_unsupported", {{"value", value}, {"paths", names_of(supported_isas())}}));
        isa = *named;
    }
    chosen.store(static_cast<int>(isa), std::memory_order_relaxed);
}

Isa article_isa() {
    int isa = chosen.load(std::memory_order_relaxed);
    if (isa < 0) {
        choose_isa_from_environment();
        isa = chosen.load(std::memory_order_relaxed);
    }
    return static_cast<Isa>(isa);
}

void set_article_isa(Isa isa) { chosen.store(static_cast<int>(isa), std::memory_order_relaxed); }

}  // namespace promyk
