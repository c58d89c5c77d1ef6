// The general tracer's sampled rows in avx512 (render/general_sample_set.inc),
// its vector eight doubles wide.
#define PROMYK_SAMPLE_VECTOR Double8
#include "render/general_sample_set.inc"
