// The general tracer's rows compiled for each wider instruction set
// (render/general_row_lanes.hpp in render/general_row_avx2.cpp and
// ..._avx512.cpp; render/general_sample_lanes.hpp in
// render/general_sample_avx2.cpp and ..._avx512.cpp); render/general_row.cpp
// calls the one render/isa.hpp chose. Declared in each set's own namespace
// (see render/article_row_isa.hpp).
#pragma once

#include <cstdint>

#include "math/vec3.hpp"
#include "render/general_row.hpp"
#include "render/kernel.hpp"

namespace promyk::lanes {

template <bool Rgb>
struct GeneralRow;

#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Winline-namespace-reopened-noninline"
#endif
// Row `row` (x_E[j] = pane_x(j, w)) drawn, and its intensities and branches
// for the tests; row i drawn from spp samples a pixel (I_P and branches
// for the tests, else null).
namespace avx2 {
RowCounts draw_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out);
RowCounts draw_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out);
void general_row_intensities(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                             double* I_P, std::uint8_t* branches);
void general_row_intensities(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                             Vec3d* I_P, std::uint8_t* branches);
RowCounts draw_sampled_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, double* I_P, std::uint8_t* branches, bool count_branches);
RowCounts draw_sampled_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, Vec3d* I_P, std::uint8_t* branches, bool count_branches);
}
namespace avx512 {
RowCounts draw_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out);
RowCounts draw_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                           std::uint8_t* out);
void general_row_intensities(const GeneralRow<false>& row, GeneralLaneStages stages, const double* x_E, int w,
                             double* I_P, std::uint8_t* branches);
void general_row_intensities(const GeneralRow<true>& row, GeneralLaneStages stages, const double* x_E, int w,
                             Vec3d* I_P, std::uint8_t* branches);
RowCounts draw_sampled_general_row(const GeneralRow<false>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, double* I_P, std::uint8_t* branches, bool count_branches);
RowCounts draw_sampled_general_row(const GeneralRow<true>& row, GeneralLaneStages stages, int w, int i, int spp,
                                   std::uint8_t* out, Vec3d* I_P, std::uint8_t* branches, bool count_branches);
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace promyk::lanes
