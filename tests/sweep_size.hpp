#pragma once
// A sweep's size in this build. Our rules keep sweeps to the release pass;
// the sanitizer pass (PROMYK_SANITIZE, about ten times slower) still runs a
// sweep's first cases, which is where it finds memory and undefined-behaviour
// faults, and leaves the rest of the sweep to the release pass.

#ifdef PROMYK_SANITIZED
constexpr bool sanitized_build = true;
#else
constexpr bool sanitized_build = false;
#endif

// `release` cases in the release pass, `sanitized` (fewer) under the sanitizers.
constexpr int sweep_size(int release, int sanitized) { return sanitized_build ? sanitized : release; }
