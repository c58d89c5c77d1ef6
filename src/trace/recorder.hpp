// Recorders: the policy through which the tracer reports its intermediates.
// The tracer takes a recorder as a template parameter. Rendering passes a
// NullRecorder, whose calls compile to nothing, so rendering pays nothing for
// tracing and traced and untraced results are identical bit for bit.
#pragma once

#include <variant>
#include <vector>

#include "math/vec3.hpp"
#include "trace/keys.hpp"

namespace promyk {

struct NullRecorder {
    // Stages that exist only to explain (never needed for the pixel's value)
    // are guarded by `if constexpr (Recorder::records)`.
    static constexpr bool records = false;

    template <class Value>
    constexpr void operator()(Key, const Value&) const noexcept {}
};

using StepValue = std::variant<double, Vec3d>;

struct Step {
    Key key;
    StepValue value;
};

class RecordingRecorder {
public:
    static constexpr bool records = true;

    void operator()(Key key, double value) { steps_.push_back({key, value}); }
    void operator()(Key key, const Vec3d& value) { steps_.push_back({key, value}); }

    std::vector<Step> take_steps() { return std::move(steps_); }

private:
    std::vector<Step> steps_;
};

}  // namespace promyk
