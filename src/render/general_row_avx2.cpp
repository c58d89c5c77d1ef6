// The general tracer's rows of one sample a pixel in avx2 (its sampled
// rows: render/general_sample_avx2.cpp): compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx2, so every template here is
// promyk::lanes::avx2::..., apart from the baseline's copies.
// The wrappers are the same in every wider set: render/general_row_wide.inc.
#include "render/general_row_wide.inc"
