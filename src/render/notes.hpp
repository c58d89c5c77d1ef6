// A pixel's notes (PRODUCT.md section 9: "notes may add detail"), found by a
// recorder that watches only the eye ray's sphere tests: their discriminant
// and what they found. The branch atlas (render --map branch, render/maps.hpp)
// draws them.
//
// tangent: a sphere test's discriminant is within rounding of 0: its value is
//   at most a bound on the rounding error of its own computation, so whether
//   the ray hits or misses that sphere is decided by rounding (an exactly
//   tangent ray, delta = 0, is one; the article counts it a miss). The bound,
//   with eps the type's epsilon (2u):
//     delta, delta_fma = C^2 - |E|^2 (|S|^2 - r^2):  8 eps (C^2 + |E|^2 |S|^2)
//       (each of C^2 and |E|^2 c_0 carries a few roundings of its own size,
//       and c_0's error is one of |S|^2's; |C| <= |E| |S| bounds C's error);
//     delta_g = r^2 - |l|^2:  16 eps (|l|^2 + |delta_g| + |l| |S|)
//       (l = t_mid E - S carries absolute errors of a few eps |S|, and
//       r^2 = delta_g + |l|^2).
//   On the article's scene no pixel of a 512 x 512 pane is tangent, in
//   double or in float; a small sphere far away is tangent everywhere in
//   float with the article's formula, whose delta is all rounding there.
// behind: a sphere test found both roots at t <= 0: the sphere lies on the
//   ray's line behind the eye, where the article's program (which never
//   checks t > 0) would draw it.
//
// A note is about what the pixel shows: it applies when the noted sphere is
// the object hit, or when the pixel shows the background (a miss). With
// several samples the notes are the centre sample's, as the branch is.
#pragma once

#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>
#include <vector>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

struct PixelNotes {
    Branch branch = Branch::miss;  // the pixel's branch (as Kernel::intensity gives it)
    bool tangent = false;
    bool behind = false;
};

template <class Real>
Real epsilon_of() {
    if constexpr (std::is_same_v<Real, quad>)
        return quad_math::nextafter(quad(1), quad(2)) - quad(1);
    else
        return std::numeric_limits<Real>::epsilon();
}

// The recorder: `records` is true (the words "behind" are recorded only
// for a recording recorder), but it keeps only a few numbers of the sphere
// test in progress and the indices of the spheres it noted.
template <class Real>
class NotesRecorder {
public:
    static constexpr bool records = true;
    static constexpr bool estimates = false;  // no digits lost (trace/digits_lost.hpp)

    template <class A, class R>
    constexpr void lost(Key, const A&, const A&, const R&) const noexcept {}
    template <class V, class R>
    constexpr void lost_in_dot(Key, const V&, const V&, const R&) const noexcept {}

    template <class Value>
    void operator()(Key key, const Value& value) {
        if (!eye_sphere_test()) return;
        if constexpr (std::is_same_v<Value, Real>) {
            number(key, value);
        } else if constexpr (std::is_convertible_v<const Value&, std::string_view>) {
            if (key == Key::found && std::string_view(value) == "behind") behind_.push_back(sphere_);
        }
    }

    // Groups: a top-level "sphere" group is an eye-ray test (the article's
    // kernel has none: its one sphere is sphere 0); spheres inside a "light"
    // group are shadow tests and are not looked at.
    void begin_group(std::string_view kind, int index) {
        ++depth_;
        if (kind == "light" && light_depth_ < 0) light_depth_ = depth_;
        if (kind == "plane" && light_depth_ < 0) in_plane_ = true;
        if (kind == "sphere" && light_depth_ < 0) sphere_ = index;
    }
    void end_group() {
        if (depth_ == light_depth_) light_depth_ = -1;
        in_plane_ = false;
        --depth_;
    }

    // The pixel's notes, given its branch and what it shows: the index of the
    // sphere hit, or -1 for a plane, or `shows_background`.
    PixelNotes notes(Branch branch, bool shows_background, int hit_sphere) const {
        PixelNotes notes;
        notes.branch = branch;
        notes.tangent = applies(tangent_, shows_background, hit_sphere);
        notes.behind = applies(behind_, shows_background, hit_sphere);
        return notes;
    }

private:
    bool eye_sphere_test() const { return light_depth_ < 0 && !in_plane_; }

    static bool applies(const std::vector<int>& spheres, bool shows_background, int hit_sphere) {
        for (const int k : spheres)
            if (shows_background || k == hit_sphere) return true;
        return false;
    }

    void number(Key key, Real value) {
        const Real eps = epsilon_of<Real>();
        switch (key) {
            case Key::EE:
                EE_ = value;
                break;
            case Key::SS:
                SS_ = value;
                break;
            case Key::C:
                C_ = value;
                break;
            case Key::ll:
                ll_ = value;
                break;
            case Key::delta:
            case Key::delta_fma:
                if (magnitude(value) <= Real(8) * eps * (C_ * C_ + EE_ * SS_)) tangent_.push_back(sphere_);
                break;
            case Key::delta_g:
                if (magnitude(value) <= Real(16) * eps * (ll_ + magnitude(value) + square_root(ll_ * SS_)))
                    tangent_.push_back(sphere_);
                break;
            default:
                break;
        }
    }

    int depth_ = 0;
    int light_depth_ = -1;
    bool in_plane_ = false;
    int sphere_ = 0;
    Real EE_ = 0, SS_ = 0, C_ = 0, ll_ = 0;
    std::vector<int> tangent_, behind_;
};

}  // namespace promyk
