// The general tracer's rows of one sample a pixel in avx512 (its sampled
// rows: render/general_sample_avx512.cpp): compiled with its instruction set
// (src/CMakeLists.txt) and PROMYK_LANES_ISA=avx512, so every template here is
// promyk::lanes::avx512::..., apart from the baseline's copies.
// First: it opens the inline namespace the declarations below extend.
#include "render/general_row_lanes.hpp"
#include "render/general_row_isa.hpp"

namespace promyk::lanes {
inline namespace avx512 {  // inline, as lanes.hpp opened it in this file

RowCounts draw_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out) {
    return draw_general_row<Double8>(row, stages, x_E, w, out);
}
RowCounts draw_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out) {
    return draw_general_row<Double8>(row, stages, x_E, w, out);
}
void general_row_intensities(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                             double* I_P, std::uint8_t* branches) {
    general_row_intensities<Double8>(row, stages, x_E, w, I_P, branches);
}
void general_row_intensities(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                             Vec3d* I_P, std::uint8_t* branches) {
    general_row_intensities<Double8>(row, stages, x_E, w, I_P, branches);
}

}  // namespace avx512
}  // namespace promyk::lanes
