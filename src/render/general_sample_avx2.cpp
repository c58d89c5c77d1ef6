// The general tracer's sampled rows (spp > 1) in avx2: compiled with its
// instruction set (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx2, as
// render/general_row_avx2.cpp is. A file of their own: with the rows of one
// sample in the same file, clang's sanitizer build (-O0, every lane lambda
// always_inline) took 13 GB to compile it, and two such at once did not
// fit in 24 GiB.
// First: it opens the inline namespace the declarations below extend.
#include "render/general_sample_lanes.hpp"
#include "render/general_row_isa.hpp"

namespace promyk::lanes {
inline namespace avx2 {  // inline, as lanes.hpp opened it in this file

RowCounts draw_sampled_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, double* I_P, std::uint8_t* branches, bool count_branches) {
    return draw_sampled_general_row<Double4>(row, stages, w, i, spp, out, I_P, branches, count_branches);
}
RowCounts draw_sampled_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, Vec3d* I_P, std::uint8_t* branches, bool count_branches) {
    return draw_sampled_general_row<Double4>(row, stages, w, i, spp, out, I_P, branches, count_branches);
}

}  // namespace avx2
}  // namespace promyk::lanes
