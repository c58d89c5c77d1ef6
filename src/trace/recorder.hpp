// Recorders: the policy through which the tracer reports its intermediates.
// The tracer takes a recorder as a template parameter. Rendering passes a
// NullRecorder, whose calls compile to nothing, so rendering pays nothing for
// tracing and traced and untraced results are identical bit for bit.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "math/real.hpp"
#include "math/vec3.hpp"
#include "trace/digits_lost.hpp"
#include "trace/keys.hpp"
#include "util/interrupt.hpp"

namespace promyk {

struct NullRecorder {
    // Stages that exist only to explain (never needed for the pixel's value)
    // are guarded by `if constexpr (Recorder::records)`.
    static constexpr bool records = false;
    // Estimates of the digits a step's subtraction loses
    // (trace/digits_lost.hpp) are computed only when this is true: the
    // calls that need operands recomputed are guarded by
    // `if constexpr (Recorder::estimates)`.
    static constexpr bool estimates = false;

    template <class Value>
    constexpr void operator()(Key, const Value&) const noexcept {}
    constexpr void begin_group(std::string_view, int) const noexcept {}
    constexpr void end_group() const noexcept {}
    // The digits lost by the step `key` just recorded: a sum or difference
    // of a and b (numbers or vectors), or a dot product of P and Q.
    template <class A, class R>
    constexpr void lost(Key, const A&, const A&, const R&) const noexcept {}
    template <class V, class R>
    constexpr void lost_in_dot(Key, const V&, const V&, const R&) const noexcept {}
};

// Only the largest estimate of digits lost over a pixel's computation, with
// no trace (for a map of digits lost: cheap, no step is stored). Stages
// that exist only to explain do not run (records is false).
struct DigitsRecorder {
    static constexpr bool records = false;
    static constexpr bool estimates = true;

    template <class Value>
    constexpr void operator()(Key, const Value&) const noexcept {}
    constexpr void begin_group(std::string_view, int) const noexcept {}
    constexpr void end_group() const noexcept {}
    template <class A, class R>
    void lost(Key, const A& a, const A& b, const R& result) {
        take(sum_digits_lost(a, b, result));
    }
    template <class V, class R>
    void lost_in_dot(Key, const V& P, const V& Q, const R& sum) {
        take(dot_digits_lost(P, Q, sum));
    }

    double max_digits_lost = 0;  // 0 when no step had an estimate

private:
    void take(double digits) {
        if (digits > max_digits_lost) max_digits_lost = digits;  // false for NaN
    }
};

// A step's value: a number, a point or vector (or an RGB colour), or a word
// (the nearest object, a blocker, what an object's test found).
using StepValue = std::variant<double, Vec3d, std::string>;

struct Step {
    Step() = default;
    Step(Key key_, StepValue value_, int group_ = -1, std::vector<std::string> real_text_ = {})
        : key(key_), value(std::move(value_)), group(group_), real_text(std::move(real_text_)) {}

    Key key = Key::E;
    StepValue value;  // for a non-double real type: the value rounded to double
    int group = -1;   // index into the trace's groups; -1: the top level
    // For a non-double real type, the value as its own type's shortest
    // round-trip text (one per component of a vector); empty for double.
    std::vector<std::string> real_text;
    // The significant digits the step's subtraction (or sum of terms of
    // opposite signs) cancels, trace/digits_lost.hpp; NaN for a step that
    // has no estimate (no such operation, or a non-finite operand).
    double digits_lost = std::numeric_limits<double>::quiet_NaN();
};

// A group of steps: one object tested, one light, one object a shadow ray is
// tested against (PRODUCT.md section 9: {"group": "sphere", "index": 0}).
struct TraceGroup {
    std::string kind;  // sphere, plane, light
    int index = 0;     // the object's or light's index in the scene
    int parent = -1;   // the enclosing group, -1 for the top level
};

// A real type other than double (float, long double, quad).
template <class Real>
inline constexpr bool is_other_real =
    (std::is_floating_point_v<Real> || std::is_same_v<Real, quad>) && !std::is_same_v<Real, double>;

class RecordingRecorder {
public:
    static constexpr bool records = true;
    static constexpr bool estimates = true;

    // Room for a one-sphere pixel's steps (about 25): growing the vector from
    // empty moved every step five times, about 930 instructions a traced pixel.
    RecordingRecorder() { steps_.reserve(32); }

    void operator()(Key key, double value) { add(key).value.emplace<double>(value); }
    void operator()(Key key, const Vec3d& value) { add(key).value.emplace<Vec3d>(value); }
    void operator()(Key key, std::string_view word) { add(key).value.emplace<std::string>(word); }
    void operator()(Key key, const char* word) { (*this)(key, std::string_view(word)); }
    void operator()(Key key, const std::string& word) { (*this)(key, std::string_view(word)); }

    // A value of another real type: kept as a double for the JSON's `value`,
    // and exactly, as text in its own type, beside it.
    template <class Real, class = std::enable_if_t<is_other_real<Real>>>
    void operator()(Key key, Real value) {
        Step& step = add(key);
        step.value.emplace<double>(static_cast<double>(value));
        step.real_text = {promyk::real_text(value)};
    }
    template <class Real, class = std::enable_if_t<is_other_real<Real>>>
    void operator()(Key key, const Vec3<Real>& v) {
        Step& step = add(key);
        step.value.emplace<Vec3d>(Vec3d{static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)});
        step.real_text = {promyk::real_text(v.x), promyk::real_text(v.y), promyk::real_text(v.z)};
    }

    // The digits lost by the step just recorded, which must be `key` in the
    // current group (else nothing is attached).
    template <class A, class R>
    void lost(Key key, const A& a, const A& b, const R& result) {
        attach(key, sum_digits_lost(a, b, result));
    }
    template <class V, class R>
    void lost_in_dot(Key key, const V& P, const V& Q, const R& sum) {
        attach(key, dot_digits_lost(P, Q, sum));
    }

    void begin_group(std::string_view kind, int index) {
        groups_.push_back({std::string(kind), index, current_});
        current_ = static_cast<int>(groups_.size()) - 1;
    }
    void end_group() { current_ = groups_.at(static_cast<std::size_t>(current_)).parent; }

    std::vector<Step> take_steps() { return std::move(steps_); }
    std::vector<TraceGroup> take_groups() { return std::move(groups_); }

private:
    void attach(Key key, double digits) {
        if (steps_.empty() || std::isnan(digits)) return;
        Step& step = steps_.back();
        if (step.key == key && step.group == current_) step.digits_lost = digits;
    }

    // A new step, its value set in place by the caller: GCC 12 warns (wrongly)
    // of an uninitialised string when a Step holding a number is moved into
    // the vector from a temporary.
    Step& add(Key key) {
        // A pixel of thousands of objects and lights takes seconds to trace:
        // a signal stops it here (Interrupted), as it stops the renderer's rows.
        if ((steps_.size() & 4095) == 0) throw_if_interrupted();
        Step& step = steps_.emplace_back();
        step.key = key;
        step.group = current_;
        return step;
    }

    std::vector<Step> steps_;
    std::vector<TraceGroup> groups_;
    int current_ = -1;
};

// A group's title as the text trace and messages write it: "sphere 1".
inline std::string group_title(const TraceGroup& group) { return group.kind + " " + std::to_string(group.index); }

}  // namespace promyk
