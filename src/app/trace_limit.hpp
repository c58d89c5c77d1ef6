// The bound on a trace's size (issue 19): a pixel's trace is estimated from
// the scene's counts (render/trace_size.hpp) before anything is traced, and
// refused (exit 2) above the limit, 250 MB unless --max-trace-size. The
// same limit bounds render's --traces file and what diff reads, so that
// promyk's own traces stay diffable.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "math/real.hpp"
#include "scene/scene.hpp"

namespace promyk::app {

// --max-trace-size SIZE on `cmd`: bytes, or with a unit (500MB, 2GB, 1.5e10).
CLI::Option* add_max_trace_size_option(CLI::App& cmd, std::string& size);

// The limit in bytes: the option's value, or default_max_trace_size when empty.
double trace_size_limit(const std::string& size);

// What one trace costs: a pixel of the scene in `traces` settings (trace
// --compare traces several), `text` for the text layout.
struct TraceCost {
    const Scene* scene = nullptr;
    RealType real = RealType::double_;
    int spp = 1;
    int traces = 1;
    bool text = false;
};

// The estimate of the trace(s) in bytes.
double trace_cost_bytes(const TraceCost& cost);

// UsageError (exit 2) when the estimate is above the limit: names the
// estimate, what it is made of, the limit and --max-trace-size to go past it.
void require_trace_size(const TraceCost& cost, const std::string& size_option);

}  // namespace promyk::app
