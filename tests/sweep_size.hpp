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

// Whether case k of a sweep runs in this build: all of them in the release
// pass, one in `every` under the sanitizers. Give k the case's index plus
// the indices of the loops around it (path, formula), so that each case
// still meets one of them there.
constexpr bool in_sweep(long long k, int every) { return !sanitized_build || k % every == 0; }
