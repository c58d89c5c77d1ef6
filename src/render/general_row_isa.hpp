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
namespace avx2 {
#include "render/general_row_isa.inc"
}
namespace avx512 {
#include "render/general_row_isa.inc"
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace promyk::lanes
