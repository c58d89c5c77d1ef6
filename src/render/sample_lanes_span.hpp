// Background skipping for sampled rows (render/sample_lanes.hpp): the
// columns of a row whose every sample is a proven miss. A pixel's samples
// spread over its whole square, so render/silhouette.hpp's proof for the
// centre row does not cover them; this one covers the band of heights
// |y − y_E| ≤ 1/w (plus the samples' own roundings) and the pixels' full
// widths. Baseline code only (render/article_row.cpp).
//
// Δ(x, y) = (x x_S + y y_S + z_E z_S)² − (x² + y² + z_E²)·m, m = |S|² − r², has
// the Hessian 2(s sᵀ − m I), s = (x_S, y_S), whose eigenvalues are
// 2(r² − z_S²) and −2m: with r² < z_S² (then m > 0) Δ is concave in (x, y)
// together. So at any point q, Δ(p) ≤ Δ(q) + ∇Δ(q)·(p − q) for every p.
// Take q = (X, y_E) at the outer edge of column J; where ∂Δ/∂x ≥ 0, every
// p with x ≤ X and |y − y_E| ≤ h has Δ(p) ≤ Δ(q) + |∂Δ/∂y|·h, and
//   Δ̂(p) ≤ Δ(p) + e ≤ Δ̂(q) + 2e + |∂Δ/∂y|·h < 0
// proves every sample of columns 0 .. J a miss (e: silhouette.hpp's bound
// over the band; the geometric formula takes its extra margin the same way).
// The right side is the mirror image. Where nothing is proven, nothing is
// skipped; tests/sample_lanes_test.cpp checks every pixel, tangent cases too.
// A float kernel's rows (kernel = rounding_of<float>(), the scene's float numbers
// in double) take float's e, margin and sample roundings: silhouette.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/formula.hpp"
#include "render/pane.hpp"
#include "render/silhouette.hpp"

namespace promyk {

inline RowSpan sampled_row_hit_span(const ArticleWorld<double>& world, int w, int i, Formula formula,
                                    KernelRounding kernel = rounding_of<double>()) {
    using namespace silhouette_detail;
    const RowSpan all{0, w};
    const double u = std::numeric_limits<double>::epsilon() / 2;  // the proof's own arithmetic
    const double xS = world.S.x, yS = world.S.y, zS = world.S.z;
    const double rr = world.r * world.r;
    // Concave in (x, y): r² < z_S², with room for the two roundings.
    if (!(rr < zS * zS * (1 - 1e-6)) || !(w >= 1)) return all;
    // The samples' heights: y_E ± 1/w, and a computed sample point is within
    // a few of the kernel's units of roundoff of its exact one (|x|, |y| ≤
    // 1 + 2/w): 1024 of them (1.1e-13 in double) cover that with room.
    const double slack = 1024 * kernel.u;
    const double y_c = pane_y<double>(i, w);
    const double h = 1.0 / w + slack;
    const double y_far = std::fabs(y_c) + h;
    // silhouette.hpp's bounds, taken at the band's farthest height (both grow
    // with |y|); their 64 units of roundoff cover |x| ≤ 1 + slack.
    const lanes::ArticleRow<double> far_row(world, y_far);
    const double e = row_error(far_row, kernel);
    const double margin = formula == Formula::geometric ? geometric_margin(far_row, kernel) : 0.0;
    if (!std::isfinite(e) || !std::isfinite(margin)) return all;
    const lanes::ArticleRow<double> row(world, y_c);
    const double m = row.SS_rr;
    const double B = row.SS + rr;
    // Proven: every sample with x on the far side of X (left: x ≤ X, side
    // +1; right: x ≥ X, side −1) is a miss.
    const auto proven = [&](double X, int side) {
        const double C = (X * xS + row.ySy) + row.zSz;
        const double A = std::fabs(X * xS) + std::fabs(row.ySy) + std::fabs(row.zSz);
        const double gx = 2 * xS * C - 2 * X * m;
        const double gy = 2 * yS * C - 2 * y_c * m;
        const double gx_error = 64 * u * (2 * std::fabs(xS) * A + 2 * std::fabs(X) * B) + 1e-290;
        const double gy_error = 64 * u * (2 * std::fabs(yS) * A + 2 * std::fabs(y_c) * B) + 1e-290;
        if (!(side * gx > gx_error)) return false;  // not surely sloping away from the others
        const double rise = (std::fabs(gy) + gy_error) * h * (1 + 1e-9);
        const double bound = delta_hat(row, X) + (2 * e + margin + rise) * (1 + 1e-9) + 1e-290;
        return std::isfinite(bound) && bound < 0;
    };
    // Where to look: the centre row's roots (or its vertex), as silhouette.hpp.
    const double a = rr - (yS * yS + zS * zS);
    const double c0 = row.ySy + row.zSz;
    const double k = row.yy + row.zz;
    const double b = 2 * xS * c0;
    const double c = c0 * c0 - k * m;
    double x1 = -b / (2 * a), x2 = x1;
    const double disc = b * b - 4 * a * c;
    if (disc > 0) {
        const double root = std::sqrt(disc);
        x1 = (-b + root) / (2 * a);
        x2 = (-b - root) / (2 * a);
    }
    if (!std::isfinite(x1) || !std::isfinite(x2)) return all;
    const auto column = [&](double x) {
        const double j = std::floor(((x + 1) * w - 1) / 2);
        return static_cast<int>(std::max(-1.0, std::min(static_cast<double>(w), j)));
    };
    RowSpan span = all;
    for (int step = 2; step <= 32; step *= 4) {
        const int J = std::min(column(x1) - step, w - 1);
        if (J < 0) break;
        if (proven(2.0 * (J + 1) / w - 1 + slack, 1)) {  // the right edge of column J
            span.lo = J + 1;
            break;
        }
    }
    for (int step = 2; step <= 32; step *= 4) {
        const int J = std::max(column(x2) + 1 + step, 0);
        if (J > w - 1) break;
        if (proven(2.0 * J / w - 1 - slack, -1)) {  // the left edge of column J
            span.hi = J;
            break;
        }
    }
    if (span.hi < span.lo) span.hi = span.lo;
    return span;
}

}  // namespace promyk
