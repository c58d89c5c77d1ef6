// The general tracer's sampled rows on the baseline (render/general_sample_set.inc),
// its vector two doubles wide. The wasm has no lanes (PROMYK_ISA_KERNELS
// unset): there this file is empty, and its rows are traced a pixel at a time.
#if defined(PROMYK_ISA_KERNELS)
#define PROMYK_SAMPLE_VECTOR Double2
#include "render/general_sample_set.inc"
#endif
