// The article's drawn rows in avx2: compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx2, so every template here is
// promyk::lanes::avx2::..., apart from the baseline's copies.
// The wrappers are the same in every wider set: render/article_row_wide.inc.
#include "render/article_row_wide.inc"
