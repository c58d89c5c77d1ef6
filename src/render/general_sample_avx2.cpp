// The general tracer's sampled rows (spp > 1) in avx2: compiled with its
// instruction set (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx2, as
// render/general_row_avx2.cpp is. A file of their own: with the rows of one
// sample in the same file, clang's sanitizer build (-O0, every lane lambda
// always_inline) took 13 GB to compile it, and two such at once did not
// fit in 24 GiB.
// The wrappers are the same in every wider set: render/general_sample_wide.inc.
#include "render/general_sample_wide.inc"
