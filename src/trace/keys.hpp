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
    // The extensions (docs/conventions.md: the engine's conventions). Several objects:
    t_far,    // the far root (C + sqrt(delta)) / |E|^2, when the near one is not in front of the eye
    found,    // what an object's test found: near, far, behind, miss, parallel (a word)
    nearest,  // the object hit nearest the eye ("sphere 1", "plane 0"), a word
    flipped,  // why the normal was turned to face the eye: inside, back (a word)
    // Planes: n_hat = n / |n| and NQ = n_hat.Q, computed once per scene.
    n_hat,  // the plane's unit normal
    NQ,     // n_hat.Q
    NE,     // n_hat.E, the denominator: 0 for a ray parallel to the plane
    // Shadows: the segment P + sK, 0 < s < 1, towards the light.
    b_s,      // K.(S - P)
    c_s,      // |S - P|^2 - r^2
    delta_s,  // b_s^2 - |K|^2 c_s
    s_1,      // (b_s - sqrt(delta_s)) / |K|^2
    s_2,      // (b_s + sqrt(delta_s)) / |K|^2
    NK,       // n_hat.K, the shadow ray's denominator against a plane
    s,        // (NQ - n_hat.P) / n_hat.K
    s_own,    // 2D / |K|^2: where the ray from inside meets its own sphere again
    blocker,  // the first object between P and the light, or "none" (a word)
    // Lighting of one light.
    diffuse,   // I D / (r sqrt(|K|^2)), the article's term
    V_hat,     // -P / |P|: the unit direction to the eye
    R_hat,     // 2 cos_alpha N_P - K_P: the mirror of K_P about the normal
    RV,        // R_hat.V_hat
    RV_n,      // RV^n, by repeated squaring
    specular,  // I k_s RV^n
    contribution,  // c (m (k_a I + k_d diffuse) + specular)
    t_plane,  // a plane's root: n_hat.Q / n_hat.E
    t_hit,    // the nearest hit's t, over all objects
    N_plane,  // a plane's normal used for shading: n_hat, or -n_hat seen from the back
    // The other formulas for the sphere (--formula, geometry/formula.hpp).
    c_0,        // |S|^2 - r^2, the quadratic's constant term (stable, fma, geometric)
    q,          // C + sign(C) sqrt(delta): the roots' cancellation-free sum (stable, geometric)
    t_q,        // q / |E|^2: one root (the far one when C > 0)
    t_c,        // c_0 / q: the other root, by Vieta (the near one when C > 0)
    w_fma,      // |E|^2 c_0, rounded (fma)
    e_fma,      // fma(-|E|^2, c_0, w_fma): the rounding error of w_fma, exactly (fma)
    delta_fma,  // fma(C, C, -w_fma) + e_fma: Kahan's discriminant (fma)
    t_mid,      // C / |E|^2: the ray's point closest to the centre (geometric)
    l,          // t_mid E - S: from the centre to that point (geometric)
    ll,         // |l|^2, the ray's squared distance from the centre (geometric)
    delta_g,    // r^2 - |l|^2: the discriminant from the distance, delta / |E|^2 (geometric)
    // Samples per pixel (--spp, render/samples.hpp), each sample in its group.
    sample_u,  // the sample's offset from the pixel's centre along j, in pixels
    sample_v,  // the same along i (down)
    I_s,       // the sample's intensity (its r, g, b in a coloured scene)
    I_mean,    // the pixel's intensity: the mean of its samples'
    // Lesson-only steps (recorded only by a recording recorder). Phong's
    // repeated squaring: RV^2, RV^4, ... up to the largest power of two <= n
    // (n <= 10000, so at most RV^8192); the shadow ray's entry point.
    RV_2, RV_4, RV_8, RV_16, RV_32, RV_64, RV_128, RV_256, RV_512, RV_1024, RV_2048, RV_4096, RV_8192,
    P_s1,  // P + s_1 K: where the shadow ray's line enters a sphere
    d_s1,  // |P + s_1 K - S|: its distance from the sphere's centre (r, up to rounding)
};

inline constexpr std::array<std::string_view, 73> key_names = {
    "E",       "EE",     "SS",    "C",     "delta",   "t",     "P",       "N",        "K",
    "KK",      "D",      "Delta", "sqrt_Delta", "N_P", "K_len", "K_P",   "cos_alpha", "t_far",
    "found",   "nearest", "flipped", "n_hat", "NQ",   "NE",    "b_s",     "c_s",      "delta_s",
    "s_1",     "s_2",    "NK",    "s",     "s_own",   "blocker", "diffuse", "V_hat",  "R_hat",
    "RV",      "RV_n",   "specular", "contribution", "t_plane", "t_hit", "N_plane",
    "c_0",     "q",      "t_q",   "t_c",   "w_fma",   "e_fma", "delta_fma", "t_mid", "l",
    "ll",      "delta_g", "sample_u", "sample_v", "I_s", "I_mean",
    "RV_2",    "RV_4",   "RV_8",  "RV_16", "RV_32", "RV_64", "RV_128", "RV_256", "RV_512",
    "RV_1024", "RV_2048", "RV_4096", "RV_8192", "P_s1", "d_s1",
};

// The key of RV^(2^k), 1 <= k <= 13 (Phong's repeated squaring).
inline constexpr int squaring_count = 13;
constexpr Key squaring_key(int k) { return static_cast<Key>(static_cast<int>(Key::RV_2) + k - 1); }

// The article's program's own steps, as opposed to the lessons' extra ones.
constexpr bool is_program_key(Key key) { return key <= Key::D; }

constexpr std::string_view key_name(Key key) { return key_names[static_cast<std::size_t>(key)]; }

// What the pixel's story ended in (PRODUCT.md, section 9).
enum class Branch {
    miss,  // delta <= 0: the ray misses (a tangent ray misses too, as in the article)
    dark,  // D <= 0: the hit point is on the sphere's dark side
    lit,   // D > 0 and some light reaches the point (I_P by the scene's effects)
    // A value that decides the branch (delta, |K|^2, D) or the result is NaN
    // or infinite: no comparison with it may pass for a miss, dark or lit.
    non_finite,
    shadowed,  // the hit faces some light and every light it faces is blocked
};

inline constexpr int branch_count = 5;

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
        case Branch::shadowed:
            return "shadowed";
    }
    return "?";
}

}  // namespace promyk
