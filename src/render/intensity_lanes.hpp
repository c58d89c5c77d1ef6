// Intensities in lanes: a grey level (one vector of lanes) or r, g, b
// (three), and the arithmetic both kernels' lanes do on them, written out
// here rather than by Vec3's operators, so that every function these
// templates call is this instruction set's own copy (render/lanes.hpp).
// Shared by the general tracer's lanes (render/general_lanes.hpp) and the
// sampled rows (render/sample_lanes.hpp).
#pragma once

#include <limits>
#include <type_traits>

#include "math/vec3.hpp"
#include "render/lanes.hpp"

namespace promyk::lanes {
inline namespace PROMYK_LANES_ISA {

// An intensity in lanes: one grey level, or r, g, b.
template <class Lane, bool Rgb>
using LaneIntensity = std::conditional_t<Rgb, Vec3<Lane>, Lane>;

template <class Lane, class Real>
PROMYK_LANES_INLINE Lane splat_of(Real x) {
    return splat<Lane>(x);
}
template <class Lane, class Real>
PROMYK_LANES_INLINE Vec3<Lane> splat_of(const Vec3<Real>& v) {
    return {splat<Lane>(v.x), splat<Lane>(v.y), splat<Lane>(v.z)};
}
template <class Lane>
PROMYK_LANES_INLINE Lane pick(MaskOf<Lane> m, Lane a, Lane b) {
    return select(m, a, b);
}
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> pick(MaskOf<Lane> m, const Vec3<Lane>& a, const Vec3<Lane>& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
template <class Lane>
PROMYK_LANES_INLINE Lane times(Lane a, Lane b) {
    return a * b;
}
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> times(Lane a, const Vec3<Lane>& b) {  // a b: a number times a colour
    return {a * b.x, a * b.y, a * b.z};
}
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> times(const Vec3<Lane>& a, const Vec3<Lane>& b) {  // channel by channel
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class Lane>
PROMYK_LANES_INLINE Lane plus(Lane a, Lane b) {
    return a + b;
}
template <class Lane>
PROMYK_LANES_INLINE Vec3<Lane> plus(const Vec3<Lane>& a, const Vec3<Lane>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
// Every channel of an intensity: 0, or NaN (a non-finite pixel's).
template <class Lane, bool Rgb>
PROMYK_LANES_INLINE LaneIntensity<Lane, Rgb> every_channel(double x) {
    if constexpr (Rgb)
        return {splat<Lane>(x), splat<Lane>(x), splat<Lane>(x)};
    else
        return splat<Lane>(x);
}
// A mask's a where m, else b.
template <class Mask>
PROMYK_LANES_INLINE Mask pick_mask(Mask m, Mask a, Mask b) {
    return either(both(m, a), both(lane_not(m), b));
}
// x * 0 is 0 only for a finite x.
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> finite_lanes(Lane x) {
    return x * 0.0 == 0.0;
}
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> below_max_lanes(Lane x) {
    return x <= std::numeric_limits<double>::max();
}
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> below_max_lanes(const Vec3<Lane>& v) {
    return both(both(below_max_lanes(v.x), below_max_lanes(v.y)), below_max_lanes(v.z));
}

// Each channel divided by d (a sampled pixel's mean: sum / spp).
template <class Div, class Lane>
PROMYK_LANES_INLINE Lane divided(const Div& d, Lane x) {
    return d.divide(x);
}
template <class Div, class Lane>
PROMYK_LANES_INLINE Vec3<Lane> divided(const Div& d, const Vec3<Lane>& x) {
    return {d.divide(x.x), d.divide(x.y), d.divide(x.z)};
}
// Where every channel is finite (math/vec3.hpp's finite_value).
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> finite_channels(Lane x) {
    using Real = typename LaneTraits<Lane>::Real;
    return x * Real(0) == Real(0);
}
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> finite_channels(const Vec3<Lane>& v) {
    return both(both(finite_channels(v.x), finite_channels(v.y)), finite_channels(v.z));
}
// Where every channel of a equals b's (as numbers: +0 equals -0).
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> equal_channels(Lane a, Lane b) {
    return a == b;
}
template <class Lane>
PROMYK_LANES_INLINE MaskOf<Lane> equal_channels(const Vec3<Lane>& a, const Vec3<Lane>& b) {
    return both(both(a.x == b.x, a.y == b.y), a.z == b.z);
}

}  // namespace PROMYK_LANES_ISA
}  // namespace promyk::lanes
