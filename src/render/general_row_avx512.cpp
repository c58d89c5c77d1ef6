// The general tracer's rows of one sample a pixel in avx512 (its sampled
// rows: render/general_sample_avx512.cpp): compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx512, so every template here is
// promyk::lanes::avx512::..., apart from the baseline's copies.
// The wrappers are the same in every wider set: render/general_row_wide.inc.
#include "render/general_row_wide.inc"
