// The float rows in avx512: compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx512, so every template here is
// promyk::lanes::avx512::..., apart from the baseline's copies.
// The wrappers are the same in every wider set: render/float_row_wide.inc.
#include "render/float_row_wide.inc"
