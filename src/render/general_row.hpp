// Rows of the general tracer (render/general_tracer.hpp) computed lanes at a
// time (render/general_lanes.hpp), one sample a pixel or several
// (render/general_sample_lanes.hpp), in double with the article's formula for
// the eye's rays, for every stage: one or several spheres and planes,
// several lights, ambient, shadows, Phong, grey or colour. The
// path is render/isa.hpp's; where there are no lanes (the wasm) these say
// so, and the kernel draws the row one pixel at a time.
#pragma once

#include <cstdint>

#include "math/vec3.hpp"
#include "render/kernel.hpp"
#include "render/world.hpp"

namespace promyk {

// The general tracer's stages that change a pixel's steps in lanes.
struct GeneralLaneStages {
    bool shadows = false;
    bool ambient = false;
    bool many = false;  // several objects (Stages::objects)
    bool phong = false;
};

// Row i of a w-pixel pane into out[0 .. w * channels): each byte to_byte
// of trace_general's intensity, the row's counts (branches, first
// non-finite column, rays and tests) as GeneralKernel counts them;
// count_branches false: of the branches, only the non-finite pixels. False,
// with nothing drawn, where this build has no lanes or the world no object.
bool general_row_in_lanes(const World<double, false>& world, GeneralLaneStages stages, int w, int i, std::uint8_t* out,
                          RowCounts& counts, bool count_branches = true);
bool general_row_in_lanes(const World<double, true>& world, GeneralLaneStages stages, int w, int i, std::uint8_t* out,
                          RowCounts& counts, bool count_branches = true);

// Row i drawn from spp > 1 samples a pixel (render/general_sample_lanes.hpp):
// each byte to_byte of sample_pixel over trace_general's mean, the row's
// counts (branches, disagreeing pixels, first non-finite column, rays and
// tests) as GeneralKernel counts them; count_branches false: of the
// branches, only the non-finite pixels. False, with nothing drawn, where
// this build has no lanes or the world no object.
bool general_sampled_row_in_lanes(const World<double, false>& world, GeneralLaneStages stages, int w, int i, int spp,
                                  std::uint8_t* out, RowCounts& counts, bool count_branches = true);
bool general_sampled_row_in_lanes(const World<double, true>& world, GeneralLaneStages stages, int w, int i, int spp,
                                  std::uint8_t* out, RowCounts& counts, bool count_branches = true);

// For the tests: the same sampled row, with its pixels' means and branches.
bool general_sampled_row_intensities(const World<double, false>& world, GeneralLaneStages stages, int w, int i,
                                     int spp, std::uint8_t* out, RowCounts& counts, double* I_P,
                                     std::uint8_t* branches);
bool general_sampled_row_intensities(const World<double, true>& world, GeneralLaneStages stages, int w, int i,
                                     int spp, std::uint8_t* out, RowCounts& counts, Vec3d* I_P,
                                     std::uint8_t* branches);

// For the tests: the same row's intensities and each pixel's Branch (as a
// byte), every column computed. False where there are no lanes.
bool general_row_intensities(const World<double, false>& world, GeneralLaneStages stages, int w, int i,
                             double* I_P, std::uint8_t* branches);
bool general_row_intensities(const World<double, true>& world, GeneralLaneStages stages, int w, int i, Vec3d* I_P,
                             std::uint8_t* branches);

}  // namespace promyk
