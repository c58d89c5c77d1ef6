// The step keys the tracer records. Each is defined, with its symbol, formula
// and descriptions, in lessons/vocabulary.json; a test checks the two agree.
#pragma once

#include <array>
#include <string_view>

namespace promyk {

enum class Key {
    E,      // the pixel's point on the pane, (x_E, y_E, z_E); also the ray's direction
    EE,     // |E|^2 (the program's E)
    SS,     // |S|^2 (the program's S)
    C,      // E.S
    delta,  // the program's Delta = C^2 - |E|^2 (|S|^2 - r^2), a quarter of formula (2)'s
    t,      // the nearer root, (C - sqrt(delta)) / |E|^2
    P,      // the hit point tE
    N,      // P - S (the unnormalised normal)
    K,      // L - P (the unnormalised direction to the light)
    KK,     // |K|^2 (the program's K)
    D,      // N.K
    // Quantities only the lessons need (formula (2) and section 4 of the
    // article), recorded only by a recording recorder: rendering never pays.
    Delta,       // formula (2)'s discriminant, 4 delta
    sqrt_Delta,  // its square root, 2 sqrt(delta)
    N_P,         // N / r: the unit normal
    K_len,       // |K| = sqrt(|K|^2), the distance from P to the light
    K_P,         // K / |K|: the unit direction to the light
    cos_alpha,   // N_P.K_P, the cosine of the angle between them
};

inline constexpr std::array<std::string_view, 17> key_names = {
    "E", "EE", "SS", "C", "delta", "t", "P", "N", "K", "KK", "D",
    "Delta", "sqrt_Delta", "N_P", "K_len", "K_P", "cos_alpha",
};

// The article's program's own steps, as opposed to the lessons' extra ones.
constexpr bool is_program_key(Key key) { return key <= Key::D; }

constexpr std::string_view key_name(Key key) { return key_names[static_cast<std::size_t>(key)]; }

// What the pixel's story ended in (PRODUCT.md, section 9).
enum class Branch {
    miss,  // delta <= 0: the ray misses (a tangent ray misses too, as in the article)
    dark,  // D <= 0: the hit point is on the sphere's dark side
    lit,   // D > 0: lit, I_P = I D / (r sqrt(K))
    // A value that decides the branch (delta, |K|^2, D) or the result is NaN
    // or infinite: no comparison with it may pass for a miss, dark or lit.
    non_finite,
};

constexpr std::string_view branch_name(Branch branch) {
    switch (branch) {
        case Branch::miss:
            return "miss";
        case Branch::dark:
            return "dark";
        case Branch::lit:
            return "lit";
        case Branch::non_finite:
            return "non-finite";
    }
    return "?";
}

}  // namespace promyk
