// The general tracer's sampled rows in avx2 (render/general_sample_set.inc),
// its vector four doubles wide.
#define PROMYK_SAMPLE_VECTOR Double4
#include "render/general_sample_set.inc"
