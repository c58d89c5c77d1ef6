// Background skipping for the article's scene: where a row of the pane
// meets the sphere's silhouette, so that the pixels outside it are drawn as
// background without computing them. A pixel is skipped only when it is
// proven that the kernel's own Δ/4 (render/article_lanes.hpp: C·C − |E|²·
// (|S|² − r²), rounded as it rounds) is negative there: skipping never
// changes a pixel (tests/silhouette_test.cpp: every pixel against the
// kernel, on tangent scenes too).
//
// Along a row (y_E, z_E fixed) the exact Δ/4 is a quadratic in x_E,
//   Δ(x) = (x_S·x + c0)² − (x² + k)·m,   c0 = y_E y_S + z_E z_S, k = y_E² + z_E², m = |S|² − r²,
// whose x² coefficient r² − y_S² − z_S² is negative when the sphere does not
// cover the eye's line of sight along x (the article's scene: 1.21 − 10.24).
// Then Δ rises to its vertex x_v and falls after it, and a pixel j with
// Δ̂(x_j) + 2e < 0, e the bound on the kernel's rounding error over the row,
// and the slope Δ'(x_j) proven to point away from the others (so that they
// are farther down the same side of the vertex), proves them misses too:
//   Δ̂(x) ≤ Δ(x) + e ≤ Δ(x_j) + e ≤ Δ̂(x_j) + 2e < 0.
// The row's roots say where to look; a pixel two columns outside each root
// is checked (and, if that fails, a few farther out); otherwise nothing is
// skipped on that side.
//
// The geometric formula decides by its own delta_g = r² − |l|², l = t_mid E − S,
// t_mid = C/|E|². Exactly, |l|² = |S|² − C²/|E|², so delta_g = Δ/|E|²; the
// computed one is within g = 64u(|S|² + r²) of it (t_mid E is at most |S| long,
// as C ≤ |E||S|, and |l| ≤ |S|: a few dozen roundings of numbers of that
// size; tests/silhouette_test.cpp checks the bound against quad). So
// Δ(x) < −|E|²_max·g proves delta_g < 0, a miss: the test above takes that
// extra margin, |E|² being at most 1 + y_E² + z_E² on the pane.
//
// Kahan's discriminant (the fma formula) is within the same e: it computes
// C, |E|² and |S|² − r² as the article does, then w = fl(|E|²·c0), the
// exact rest ε = |E|²·c0 − w (one fma, exact but for underflow, which the
// bound's last term covers) and fl(fl(C² − w) + ε): two roundings, of at
// most u|C² − w| ≤ u(C² + |E|²·c0) and u|result|, where the article has
// three (C², |E|²·c0 and their difference) of at least as much. So the
// article's proof, with the article's Δ̂ at x_j, proves Kahan's misses too.
//
// A float kernel (--real float) is proven the same way, its bounds taken
// with float's unit roundoff, underflow and overflow (KernelRounding); the
// proof's own arithmetic stays in double, on the float scene's numbers
// (exact in double), its Δ̂ at x_j double's, within double's e of the exact
// Δ: Δ̂_float(x) ≤ Δ(x) + e_float ≤ Δ(x_j) + e_float ≤ Δ̂(x_j) + e + e_float,
// and e ≤ e_float.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "geometry/formula.hpp"
#include "render/article_lanes.hpp"

namespace promyk {

// The columns [lo, hi) that are computed; every other column of the row is
// a proven miss (lo may equal hi: the whole row is background).
struct RowSpan {
    int lo = 0, hi = 0;
};

// The arithmetic of the kernel a proof is for: its unit roundoff, an
// absolute term that covers underflow's errors, the size of the products
// below which that term would not (the geometric formula's squares), and
// its largest finite number.
struct KernelRounding {
    double u, tiny, least_product, max;
};
template <class Real>
constexpr KernelRounding rounding_of() {
    static_assert(std::is_same_v<Real, double> || std::is_same_v<Real, float>);
    if constexpr (std::is_same_v<Real, double>)
        return {std::numeric_limits<double>::epsilon() / 2, 1e-290, 1e-250, std::numeric_limits<double>::max()};
    else
        return {std::numeric_limits<float>::epsilon() / 2, 1e-25, 1e-15, std::numeric_limits<float>::max()};
}

namespace silhouette_detail {

// Δ̂ at x as the kernel computes it (the same products and sums, in the
// same order); any evaluation of this shape is within row_error of Δ.
inline double delta_hat(const lanes::ArticleRow<double>& row, double x) {
    const double EE = (x * x + row.yy) + row.zz;
    const double C = (x * row.world.S.x + row.ySy) + row.zSz;
    return C * C - EE * row.SS_rr;
}

// A bound on |Δ̂(x) − Δ(x)| for |x| ≤ 1. Each of C, |E|² and |S|² − r² is
// a short sum of rounded products (at most 5 roundings: γ5 of the sum of
// the terms' sizes), and Δ̂ two products and a difference of those, so
// |Δ̂ − Δ| ≤ γ12·(A² + |E|²·B) with A = |x x_S| + |y_E y_S| + |z_E z_S| and
// B = |S|² + r². 64 units of roundoff instead of 12 cover the bound's own
// rounding with room to spare; the last term covers underflow. Infinite
// when the kernel's products could overflow (every one is below A² + |E|²B).
inline double row_error(const lanes::ArticleRow<double>& row, KernelRounding kernel = rounding_of<double>()) {
    const double A = std::fabs(row.world.S.x) + std::fabs(row.ySy) + std::fabs(row.zSz);
    const double EE = (1 + row.yy) + row.zz;
    const double B = row.SS + row.world.r * row.world.r;
    const double size = A * A + EE * B;
    if (!(16 * size <= kernel.max)) return std::numeric_limits<double>::infinity();
    return 64 * kernel.u * size + kernel.tiny;
}

// The geometric formula's bound g on |computed delta_g − Δ/|E|²| (above).
inline double geometric_error(const lanes::ArticleRow<double>& row, KernelRounding kernel = rounding_of<double>()) {
    return 64 * kernel.u * (row.SS + row.rr) + kernel.tiny;
}

// The geometric formula's margin: |E|²_max·g, or NaN when the bound cannot
// be trusted (the squares of l near overflow, or products so small that
// underflow's absolute errors outgrow g).
inline double geometric_margin(const lanes::ArticleRow<double>& row, KernelRounding kernel = rounding_of<double>()) {
    const double B = row.SS + row.rr;
    if (!(16 * B <= kernel.max) || !(std::sqrt(row.SS) * std::fabs(row.world.z_E) >= kernel.least_product))
        return std::numeric_limits<double>::quiet_NaN();
    const double EE_max = ((1 + row.yy) + row.zz) * (1 + 8 * kernel.u);
    return EE_max * geometric_error(row, kernel);
}

}  // namespace silhouette_detail

// The columns of a w-pixel row (x_E[j] = pane_x(j, w), the kernel's own:
// double or float) that may be hit with the formula (the article's, stable
// and fma: the program's Δ/4, fma's computed with Kahan's fmas; geometric:
// delta_g) by a kernel of rounding `kernel`; the whole row when nothing can be
// proven (a sphere around the line of sight, numbers near the ends of the
// kernel's range). A float kernel's row: its numbers, in double.
template <class X>
RowSpan row_hit_span(const lanes::ArticleRow<double>& row, const X* x_E, int w, Formula formula = Formula::article,
                     KernelRounding kernel = rounding_of<double>()) {
    using namespace silhouette_detail;
    const RowSpan all{0, w};
    const double margin = formula == Formula::geometric ? geometric_margin(row, kernel) : 0.0;
    const double xS = row.world.S.x;
    // The quadratic's coefficients, exactly enough to find where to look.
    const double a = row.world.r * row.world.r - (row.world.S.y * row.world.S.y + row.world.S.z * row.world.S.z);
    const double scale = row.world.r * row.world.r + row.world.S.y * row.world.S.y + row.world.S.z * row.world.S.z;
    if (!(a < -1e-6 * scale)) return all;  // not surely concave (or not finite)
    const double c0 = row.ySy + row.zSz;
    const double k = row.yy + row.zz;
    const double b = 2 * xS * c0;
    const double c = c0 * c0 - k * row.SS_rr;
    const double x_v = -b / (2 * a);
    const double e = row_error(row, kernel);
    if (!std::isfinite(x_v) || !std::isfinite(e) || !std::isfinite(c) || !std::isfinite(margin)) return all;
    // Where Δ = 0 (a root pair, or the vertex when the row misses the sphere).
    double x1 = x_v, x2 = x_v;
    const double disc = b * b - 4 * a * c;
    if (disc > 0) {
        const double root = std::sqrt(disc);
        x1 = (-b + root) / (2 * a);  // a < 0: the smaller root
        x2 = (-b - root) / (2 * a);
    }
    if (!std::isfinite(x1) || !std::isfinite(x2)) return all;
    // Column of x (rounded down), clamped to [-1, w] before any conversion.
    const auto column = [&](double x) {
        const double j = std::floor(((x + 1) * w - 1) / 2);
        return static_cast<int>(std::max(-1.0, std::min(static_cast<double>(w), j)));
    };
    // Which side of the vertex x lies on, proven: the slope Δ'(x) = 2a·x + b
    // against its rounding error (a, b: sums of at most 3 and 4 rounded
    // terms), with room to spare. x_v above only says where to look.
    const double u = std::numeric_limits<double>::epsilon() / 2;
    const double b_size = 2 * std::fabs(xS) * (std::fabs(row.ySy) + std::fabs(row.zSz));
    const auto slope_sign = [&](double x) {
        const double slope = 2 * a * x + b;
        const double error = 64 * u * (2 * std::fabs(x) * scale + b_size) + 1e-290;
        return slope > error ? 1 : slope < -error ? -1 : 0;
    };
    // Left of the vertex: the first column that proves itself and all before it.
    RowSpan span = all;
    for (int step = 2; step <= 32; step *= 4) {
        const int j = std::min(column(x1) - step, w - 1);
        if (j < 0) break;
        const double x = x_E[j];
        if (slope_sign(x) > 0 && delta_hat(row, x) + 2 * e + margin < 0) {
            span.lo = j + 1;
            break;
        }
    }
    for (int step = 2; step <= 32; step *= 4) {
        const int j = std::max(column(x2) + 1 + step, 0);
        if (j > w - 1) break;
        const double x = x_E[j];
        if (slope_sign(x) < 0 && delta_hat(row, x) + 2 * e + margin < 0) {
            span.hi = j;
            break;
        }
    }
    if (span.hi < span.lo) span.hi = span.lo;  // both sides proven: an empty row
    return span;
}

}  // namespace promyk
