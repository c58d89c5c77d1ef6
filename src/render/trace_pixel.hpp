// Tracing one pixel: the tracer run with a recording recorder, packed with
// the header that says what was computed.
#pragma once

#include "geometry/formula.hpp"
#include "math/real.hpp"
#include "render/tracer.hpp"
#include "scene/scene.hpp"
#include "trace/trace.hpp"

namespace promyk {

// Header fields shared by every pixel of one scene at one size.
TraceHeader trace_header(const Scene& scene, int w);

// Traces pixel (i, j) of the header's w x w pane.
PixelTrace trace_pixel(const ArticleWorld<double>& world, const TraceHeader& header, int i, int j);

// Traces pixel (i, j) of a w x w pane of the scene.
PixelTrace trace_pixel(const Scene& scene, int w, int i, int j, RealType real = RealType::double_,
                       Formula formula = Formula::article, int spp = 1);

}  // namespace promyk
