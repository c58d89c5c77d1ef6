// The article's program (section 5 of ARTICLE.md, Fig. 5), transcribed line
// by line into C++ from the pseudocode alone, as a yardstick for the tracer.
// Nothing here comes from src/: the only shared thing is the compiler flags
// (-ffp-contract=off via promyk_fp), which any faithful compilation of the
// pseudocode needs so that no a*b + c is fused into one rounding.
//
// Conventions of the transcription:
// - x^2 is written x * x; a sum of three terms is added left to right, as the
//   pseudocode reads: x_E^2 + y_E^2 + z_E^2 is (x_E*x_E + y_E*y_E) + z_E*z_E.
// - "C^2 - E(S - r^2)" is C * C - E * (S - r * r).
// - "I D / (r sqrt(K))" is I * D / (r * sqrt(K)): (I*D) / (r*sqrt(K)).
// - The program's locals keep the program's names: E, S and K are squared
//   lengths, Delta is a quarter of formula (2)'s discriminant.
// - "return 1/2" is the article's background; a scene may choose another,
//   so the yardstick returns the scene's `background` (1/2 by default).
#pragma once

#include <cmath>
#include <vector>

namespace promyk_literal {

// The numbers the article gives for Fig. 5 (I is not given; I = 1) by
// default; tests fill in other scenes.
struct LiteralScene {
    double z_E = 2;
    double x_S = 0, y_S = 0, z_S = 3.2;  // S = (0, 0, 3 1/5)
    double r = 1.1;                      // r = 1 1/10
    double x_L = 1.5, y_L = 1, z_L = 1;  // L = (1 1/2, 1, 1)
    double I = 1;
    double background = 1.0 / 2.0;  // the article's "return 1/2"
};

// Which `return` the function left by.
enum class LiteralReturn {
    half,       // "if Delta <= 0 then return 1/2" (the background)
    zero,       // "if D <= 0 then return 0"
    intensity,  // "return I D / (r sqrt(K))"
};

// Every local of `intensity`, in the order the program assigns them. Locals
// the program never reached keep their initial value (NaN).
struct LiteralLocals {
    static constexpr double unset = NAN;
    double x_E = unset, y_E = unset, z_E = unset;
    double E = unset;
    double S = unset;
    double C = unset;
    double Delta = unset;
    double t = unset;
    double x_P = unset, y_P = unset, z_P = unset;
    double x_N = unset, y_N = unset, z_N = unset;
    double x_K = unset, y_K = unset, z_K = unset;
    double K = unset;
    double D = unset;
    double result = unset;
    LiteralReturn returned = LiteralReturn::half;
};

//   function intensity(x_E, y_E, z_E)
inline double literal_intensity(double x_E, double y_E, double z_E, double x_S, double y_S, double z_S, double r,
                                double x_L, double y_L, double z_L, double I, double background,
                                LiteralLocals* locals = nullptr) {
    LiteralLocals scratch;
    LiteralLocals& v = locals ? *locals : scratch;
    v = LiteralLocals{};
    v.x_E = x_E;
    v.y_E = y_E;
    v.z_E = z_E;
    //     E := x_E^2 + y_E^2 + z_E^2
    const double E = x_E * x_E + y_E * y_E + z_E * z_E;
    v.E = E;
    //     S := x_S^2 + y_S^2 + z_S^2
    const double S = x_S * x_S + y_S * y_S + z_S * z_S;
    v.S = S;
    //     C := x_E x_S + y_E y_S + z_E z_S
    const double C = x_E * x_S + y_E * y_S + z_E * z_S;
    v.C = C;
    //     Delta := C^2 - E(S - r^2)
    const double Delta = C * C - E * (S - r * r);
    v.Delta = Delta;
    //     if Delta <= 0 then return 1/2   (1/2 is the article's background)
    if (Delta <= 0) {
        v.returned = LiteralReturn::half;
        return v.result = background;
    }
    //     t := (C - sqrt(Delta)) / E
    const double t = (C - std::sqrt(Delta)) / E;
    v.t = t;
    //     (x_P, y_P, z_P) := (t x_E, t y_E, t z_E)
    const double x_P = t * x_E, y_P = t * y_E, z_P = t * z_E;
    v.x_P = x_P;
    v.y_P = y_P;
    v.z_P = z_P;
    //     (x_N, y_N, z_N) := (x_P - x_S, y_P - y_S, z_P - z_S)
    const double x_N = x_P - x_S, y_N = y_P - y_S, z_N = z_P - z_S;
    v.x_N = x_N;
    v.y_N = y_N;
    v.z_N = z_N;
    //     (x_K, y_K, z_K) := (x_L - x_P, y_L - y_P, z_L - z_P)
    const double x_K = x_L - x_P, y_K = y_L - y_P, z_K = z_L - z_P;
    v.x_K = x_K;
    v.y_K = y_K;
    v.z_K = z_K;
    //     K := x_K^2 + y_K^2 + z_K^2
    const double K = x_K * x_K + y_K * y_K + z_K * z_K;
    v.K = K;
    //     D := x_N x_K + y_N y_K + z_N z_K
    const double D = x_N * x_K + y_N * y_K + z_N * z_K;
    v.D = D;
    //     if D <= 0 then return 0
    if (D <= 0) {
        v.returned = LiteralReturn::zero;
        return v.result = 0.0;
    }
    //     return I D / (r sqrt(K))
    v.returned = LiteralReturn::intensity;
    return v.result = I * D / (r * std::sqrt(K));
}

inline double literal_intensity(double x_E, double y_E, double z_E, const LiteralScene& s,
                                LiteralLocals* locals = nullptr) {
    return literal_intensity(x_E, y_E, z_E, s.x_S, s.y_S, s.z_S, s.r, s.x_L, s.y_L, s.z_L, s.I, s.background, locals);
}

// The article's pixel loop (section 2), filling t[i, j] row by row:
//   for i := 0 to w - 1
//     for j := 0 to w - 1
//       y_E := -(2i + 1)/w + 1
//       x_E := (2j + 1)/w - 1
//       t[i, j] := intensity(x_E, y_E, z_E)
// t[i, j] is t[i * w + j]. If `locals` is given it receives every pixel's
// locals in the same order.
inline std::vector<double> literal_program(int w, const LiteralScene& s = {},
                                           std::vector<LiteralLocals>* locals = nullptr) {
    std::vector<double> t(static_cast<std::size_t>(w) * static_cast<std::size_t>(w));
    if (locals) locals->assign(t.size(), LiteralLocals{});
    for (int i = 0; i <= w - 1; ++i) {
        for (int j = 0; j <= w - 1; ++j) {
            // 2i + 1 and 2j + 1 are integers; "/" divides reals.
            const double y_E = -static_cast<double>(2 * i + 1) / static_cast<double>(w) + 1;
            const double x_E = static_cast<double>(2 * j + 1) / static_cast<double>(w) - 1;
            const std::size_t index = static_cast<std::size_t>(i) * static_cast<std::size_t>(w) + j;
            t[index] = literal_intensity(x_E, y_E, s.z_E, s, locals ? &(*locals)[index] : nullptr);
        }
    }
    return t;
}

}  // namespace promyk_literal
