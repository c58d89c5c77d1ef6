// "Digits lost": how many significant digits a sum or difference cancels.
// For c = a - b (or a + b with a and b of opposite signs) the relative error
// the operands carry reaches c multiplied by max(|a|, |b|) / |c|, so
//
//   digits_lost = log10(max(|a|, |b|) / |c|), clamped to 0 ... full digits,
//
// where the full digits are the type's p·log10(2) for a p-bit significand
// (float 7.2, double 16.0, long double 19.3, quad 34.0). When c is exactly 0
// and an operand is not, every digit is lost: the full digits. When both
// operands are 0, nothing is lost (0). A non-finite operand or result gives
// no estimate (NaN here; no `digits_lost` in the trace).
//
// A vector difference (N = P - S, K = L - P) takes the largest component of
// its operands against the result's largest (max-norms); a dot
// product x_P x_Q + y_P y_Q + z_P z_Q takes its largest term as the operand
// (max |term| / |sum|). Everything is computed from the values of the actual
// type: each magnitude's log10 from its own type's exponent and significand
// (a quad's magnitude may lie beyond the range of a double), then the
// difference of the logs as a double; the log10 is math/portable_log10.hpp,
// so that the CLI and the web page (wasm) give the same estimates.
//
// Only a recorder that asks for estimates (Recorder::estimates) computes
// them: rendering never does (trace/recorder.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/portable_log10.hpp"
#include "math/real.hpp"
#include "math/vec3.hpp"

namespace promyk {

// The significand's bits of each real type.
template <class Real>
constexpr int significand_bits() {
    if constexpr (std::is_same_v<Real, quad>)
        return 113;
    else
        return std::numeric_limits<Real>::digits;
}

// The type's full decimal digits, p·log10(2): every digit, the estimate when
// a subtraction cancels completely.
template <class Real>
double full_digits() {
    return significand_bits<Real>() * 0.30102999566398119521;  // log10(2)
}

// A step is marked in the text trace when it loses at least this many
// digits (its estimate rounded to one decimal, as the trace shows it).
inline constexpr double many_digits_lost = 3.0;

// The estimate as traces show it: rounded to one decimal.
inline double rounded_digits(double digits) { return std::round(digits * 10) / 10; }

inline bool loses_many_digits(double digits) { return rounded_digits(digits) >= many_digits_lost; }

namespace digits_detail {

template <class Real>
bool finite(Real x) {
    return x * Real(0) == Real(0);
}

}  // namespace digits_detail

// The digits lost by a result whose largest operand has magnitude
// `largest` (NaN: no estimate).
template <class Real>
double digits_lost(Real largest, Real result) {
    using namespace digits_detail;
    if (!finite(largest) || !finite(result)) return std::numeric_limits<double>::quiet_NaN();
    largest = magnitude(largest);
    if (largest == 0) return 0;
    if (result == 0) return full_digits<Real>();
    const double digits = log10_magnitude(largest) - log10_magnitude(result);
    return std::clamp(digits, 0.0, full_digits<Real>());
}

// c = a - b or a + b.
template <class Real>
double sum_digits_lost(Real a, Real b, Real c) {
    using namespace digits_detail;
    if (!finite(a) || !finite(b)) return std::numeric_limits<double>::quiet_NaN();
    return digits_lost(std::max(magnitude(a), magnitude(b)), c);
}

// C = A - B or A + B, component by component: the vector's error, about
// the operands' largest component times the type's epsilon, against the
// result's largest component (max-norms). Not the worst component: one that
// cancels to nothing in a vector that is long in another direction costs
// the vector no digits (NaN when a component is not finite).
template <class Real>
double sum_digits_lost(const Vec3<Real>& A, const Vec3<Real>& B, const Vec3<Real>& C) {
    using namespace digits_detail;
    Real largest = 0, result = 0;
    for (const Real x : {A.x, A.y, A.z, B.x, B.y, B.z}) {
        if (!finite(x)) return std::numeric_limits<double>::quiet_NaN();
        largest = std::max(largest, magnitude(x));
    }
    for (const Real x : {C.x, C.y, C.z}) result = std::max(result, magnitude(x));
    return digits_lost(largest, result);
}

// sum = P.Q: the largest term against the sum.
template <class Real>
double dot_digits_lost(const Vec3<Real>& P, const Vec3<Real>& Q, Real sum) {
    using namespace digits_detail;
    const Real terms[3] = {P.x * Q.x, P.y * Q.y, P.z * Q.z};
    Real largest = 0;
    for (const Real term : terms) {
        if (!finite(term)) return std::numeric_limits<double>::quiet_NaN();
        largest = std::max(largest, magnitude(term));
    }
    return digits_lost(largest, sum);
}

}  // namespace promyk
