// Vec3: a point or vector of three reals, with exactly the operations the
// article uses. Every operation is written out component by component in the
// article's order, so Vec3 code rounds exactly like the article's program.
#pragma once

namespace promyk {

template <class Real>
struct Vec3 {
    Real x{}, y{}, z{};
};

using Vec3d = Vec3<double>;

// P - Q = [x_P - x_Q, y_P - y_Q, z_P - z_Q]
template <class Real>
constexpr Vec3<Real> operator-(const Vec3<Real>& P, const Vec3<Real>& Q) {
    return {P.x - Q.x, P.y - Q.y, P.z - Q.z};
}

// E / t = (x_E / t, y_E / t, z_E / t): used for unit vectors, N / r.
template <class Real>
constexpr Vec3<Real> operator/(const Vec3<Real>& E, Real t) {
    return {E.x / t, E.y / t, E.z / t};
}

// -P: the opposite vector (exact: only the signs change).
template <class Real>
constexpr Vec3<Real> operator-(const Vec3<Real>& P) {
    return {-P.x, -P.y, -P.z};
}

// a ⊙ b: channel by channel, for colours.
template <class Real>
constexpr Vec3<Real> operator*(const Vec3<Real>& a, const Vec3<Real>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}

template <class Real>
constexpr Vec3<Real> operator+(const Vec3<Real>& P, const Vec3<Real>& Q) {
    return {P.x + Q.x, P.y + Q.y, P.z + Q.z};
}

// tE = (t x_E, t y_E, t z_E)
template <class Real>
constexpr Vec3<Real> operator*(Real t, const Vec3<Real>& E) {
    return {t * E.x, t * E.y, t * E.z};
}

// P.Q = x_P x_Q + y_P y_Q + z_P z_Q, summed left to right as the article writes it.
template <class Real>
constexpr Real dot(const Vec3<Real>& P, const Vec3<Real>& Q) {
    return P.x * Q.x + P.y * Q.y + P.z * Q.z;
}

// |P|^2 = x_P^2 + y_P^2 + z_P^2
template <class Real>
constexpr Real length_squared(const Vec3<Real>& P) {
    return dot(P, P);
}

template <class Real>
constexpr bool operator==(const Vec3<Real>& P, const Vec3<Real>& Q) {
    return P.x == Q.x && P.y == Q.y && P.z == Q.z;
}

// True when a number, or every component, finite (x * 0 is 0 only for a finite x).
template <class Real>
bool finite_value(Real x) {
    return x * Real(0) == Real(0);
}
template <class Real>
bool finite_value(const Vec3<Real>& v) {
    return finite_value(v.x) && finite_value(v.y) && finite_value(v.z);
}

}  // namespace promyk
