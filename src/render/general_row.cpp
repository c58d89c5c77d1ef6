// The general tracer's rows in lanes (render/general_row.hpp): the
// baseline's two doubles here, the wider sets in their own translation
// units (render/general_row_isa.hpp), chosen by render/isa.hpp. Compiled
// with -fno-math-errno (src/CMakeLists.txt): a square root that need not set
// errno is one sqrtpd for its lanes, with the same bits. The wasm compiles
// this file without lanes (PROMYK_ISA_KERNELS unset): its rows stay one pixel
// at a time.
#include "render/general_row.hpp"

#include <vector>

#if defined(PROMYK_ISA_KERNELS)
#include "render/general_row_isa.hpp"
#include "render/general_row_lanes.hpp"
#include "render/general_sample_lanes.hpp"
#include "render/isa.hpp"
#include "render/pane.hpp"
#include "render/pane_columns.hpp"
#endif

namespace promyk {

#if defined(PROMYK_ISA_KERNELS)
namespace {

template <bool Rgb>
bool has_object(const lanes::GeneralRow<Rgb>& row) {
    return row.sphere_count + row.plane_count > 0;
}

// This thread's row, refilled for each row drawn.
template <bool Rgb>
const lanes::GeneralRow<Rgb>& row_of(const World<double, Rgb>& world, int w, int i) {
    thread_local lanes::GeneralRow<Rgb> row;
    row.set(world, pane_y<double>(i, w));
    return row;
}

template <bool Rgb>
bool draw(const World<double, Rgb>& world, GeneralLaneStages stages, int w, int i, std::uint8_t* out, RowCounts& counts,
          bool count_branches) {
    const lanes::GeneralRow<Rgb>& row = row_of(world, w, i);
    if (!has_object(row)) return false;
    const double* x_E = pane_columns(w);
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_general_row(row, stages, x_E, w, out, count_branches);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_general_row(row, stages, x_E, w, out, count_branches);
            break;
        default:
            counts = lanes::draw_general_row<lanes::Double2>(row, stages, x_E, w, out, count_branches);
    }
    return true;
}

template <bool Rgb, class Intensity>
bool intensities(const World<double, Rgb>& world, GeneralLaneStages stages, int w, int i, Intensity* I_P,
                 std::uint8_t* branches) {
    const lanes::GeneralRow<Rgb>& row = row_of(world, w, i);
    if (!has_object(row)) return false;
    const double* x_E = pane_columns(w);
    switch (article_isa()) {
        case Isa::avx512:
            lanes::avx512::general_row_intensities(row, stages, x_E, w, I_P, branches);
            break;
        case Isa::avx2:
            lanes::avx2::general_row_intensities(row, stages, x_E, w, I_P, branches);
            break;
        default:
            lanes::general_row_intensities<lanes::Double2>(row, stages, x_E, w, I_P, branches);
    }
    return true;
}

// Row i from spp samples a pixel; I_P and branches for the tests, else null.
template <bool Rgb, class Intensity>
bool draw_sampled(const World<double, Rgb>& world, GeneralLaneStages stages, int w, int i, int spp, std::uint8_t* out,
                  RowCounts& counts, Intensity* I_P, std::uint8_t* branches, bool count_branches = true) {
    if (spp <= 1) return false;
    const lanes::GeneralRow<Rgb>& row = row_of(world, w, i);  // its heights unused: each sample's own
    if (!has_object(row)) return false;
    switch (article_isa()) {
        case Isa::avx512:
            counts = lanes::avx512::draw_sampled_general_row(row, stages, w, i, spp, out, I_P, branches, count_branches);
            break;
        case Isa::avx2:
            counts = lanes::avx2::draw_sampled_general_row(row, stages, w, i, spp, out, I_P, branches, count_branches);
            break;
        default:
            counts = lanes::draw_sampled_general_row<lanes::Double2>(row, stages, w, i, spp, out, I_P, branches,
                                                                     count_branches);
    }
    return true;
}

}  // namespace

bool general_sampled_row_in_lanes(const World<double, false>& world, GeneralLaneStages stages, int w, int i, int spp,
                                  std::uint8_t* out, RowCounts& counts, bool count_branches) {
    return draw_sampled(world, stages, w, i, spp, out, counts, static_cast<double*>(nullptr), nullptr, count_branches);
}
bool general_sampled_row_in_lanes(const World<double, true>& world, GeneralLaneStages stages, int w, int i, int spp,
                                  std::uint8_t* out, RowCounts& counts, bool count_branches) {
    return draw_sampled(world, stages, w, i, spp, out, counts, static_cast<Vec3d*>(nullptr), nullptr, count_branches);
}
bool general_sampled_row_intensities(const World<double, false>& world, GeneralLaneStages stages, int w, int i,
                                     int spp, std::uint8_t* out, RowCounts& counts, double* I_P,
                                     std::uint8_t* branches) {
    return draw_sampled(world, stages, w, i, spp, out, counts, I_P, branches);
}
bool general_sampled_row_intensities(const World<double, true>& world, GeneralLaneStages stages, int w, int i,
                                     int spp, std::uint8_t* out, RowCounts& counts, Vec3d* I_P,
                                     std::uint8_t* branches) {
    return draw_sampled(world, stages, w, i, spp, out, counts, I_P, branches);
}

bool general_row_in_lanes(const World<double, false>& world, GeneralLaneStages stages, int w, int i, std::uint8_t* out,
                          RowCounts& counts, bool count_branches) {
    return draw(world, stages, w, i, out, counts, count_branches);
}
bool general_row_in_lanes(const World<double, true>& world, GeneralLaneStages stages, int w, int i, std::uint8_t* out,
                          RowCounts& counts, bool count_branches) {
    return draw(world, stages, w, i, out, counts, count_branches);
}
bool general_row_intensities(const World<double, false>& world, GeneralLaneStages stages, int w, int i,
                             double* I_P, std::uint8_t* branches) {
    return intensities(world, stages, w, i, I_P, branches);
}
bool general_row_intensities(const World<double, true>& world, GeneralLaneStages stages, int w, int i, Vec3d* I_P,
                             std::uint8_t* branches) {
    return intensities(world, stages, w, i, I_P, branches);
}

#else  // no lanes in this build

bool general_sampled_row_in_lanes(const World<double, false>&, GeneralLaneStages, int, int, int, std::uint8_t*,
                                  RowCounts&, bool) {
    return false;
}
bool general_sampled_row_in_lanes(const World<double, true>&, GeneralLaneStages, int, int, int, std::uint8_t*,
                                  RowCounts&, bool) {
    return false;
}
bool general_sampled_row_intensities(const World<double, false>&, GeneralLaneStages, int, int, int, std::uint8_t*,
                                     RowCounts&, double*, std::uint8_t*) {
    return false;
}
bool general_sampled_row_intensities(const World<double, true>&, GeneralLaneStages, int, int, int, std::uint8_t*,
                                     RowCounts&, Vec3d*, std::uint8_t*) {
    return false;
}

bool general_row_in_lanes(const World<double, false>&, GeneralLaneStages, int, int, std::uint8_t*, RowCounts&, bool) {
    return false;
}
bool general_row_in_lanes(const World<double, true>&, GeneralLaneStages, int, int, std::uint8_t*, RowCounts&, bool) {
    return false;
}
bool general_row_intensities(const World<double, false>&, GeneralLaneStages, int, int, double*, std::uint8_t*) {
    return false;
}
bool general_row_intensities(const World<double, true>&, GeneralLaneStages, int, int, Vec3d*, std::uint8_t*) {
    return false;
}

#endif

}  // namespace promyk
