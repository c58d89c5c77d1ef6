// The formulas for a ray meeting a sphere (`--formula`), PRODUCT.md and
// docs/conventions.md: the engine's conventions. The formula applies to the eye's rays;
// shadow rays keep their own test (geometry/segment.hpp).
#pragma once

#include <string_view>

namespace promyk {

enum class Formula {
    article,    // the article's literal quadratic (the default)
    stable,     // roots from q = C + sign(C) sqrt(delta) and Vieta: no cancellation in the roots
    fma,        // Kahan's discriminant with fused multiply-adds, then the article's roots
    geometric,  // the discriminant from the ray's distance to the centre (Haines et al. 2019)
};

inline constexpr Formula all_formulas[] = {Formula::article, Formula::stable, Formula::fma, Formula::geometric};

constexpr std::string_view formula_name(Formula formula) {
    switch (formula) {
        case Formula::article:
            return "article";
        case Formula::stable:
            return "stable";
        case Formula::fma:
            return "fma";
        case Formula::geometric:
            return "geometric";
    }
    return "?";
}

}  // namespace promyk
