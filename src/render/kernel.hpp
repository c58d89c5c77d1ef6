// A scene compiled for the engine, with the row kernel chosen for it once,
// before any pixel: the article's kernel for the article's world, else the
// general tracer instantiated with exactly the stages the scene calls for
// (render/stages.hpp). The renderer and the tracing of single pixels both go
// through it, so an image and its traces always come from the same code.
#pragma once

#include <cstdint>
#include <memory>

#include "geometry/formula.hpp"
#include "math/real.hpp"
#include "render/notes.hpp"
#include "render/stages.hpp"
#include "scene/scene.hpp"
#include "trace/keys.hpp"
#include "trace/trace.hpp"

namespace promyk {

// One row's pixels per branch, its first non-finite pixel's column, and the
// work done (rays and intersection tests).
struct RowCounts {
    int branches[branch_count] = {};  // by the pixel's branch (its centre sample's)
    int disagreeing = 0;              // pixels whose samples took different branches
    int first_non_finite_j = -1;
    long long shadow_rays = 0;
    long long sphere_tests = 0;
    long long plane_tests = 0;
    int skipped = 0;  // pixels drawn as background without a test (render/silhouette.hpp)
};

class Kernel {
public:
    virtual ~Kernel() = default;
    // 1 for a grey image, 3 for RGB.
    virtual int channels() const = 0;
    // Renders row i of the w x w pane into out[0 .. w * channels()).
    virtual RowCounts row(int w, int i, std::uint8_t* out) const = 0;
    // Pixel (i, j)'s intensity as rendering computes it (no recorder): the
    // grey level in all three channels, or r, g, b; and its branch. For
    // tests and benchmarks: traced and untraced must agree bit for bit.
    virtual Vec3d intensity(int w, int i, int j, Branch* branch = nullptr) const = 0;
    // The same intensity converted exactly to quad (every real type's values
    // are quads), for comparisons finer than a double's ulp (render --map error).
    virtual Vec3<quad> exact_intensity(int w, int i, int j, Branch* branch = nullptr) const = 0;
    // Traces pixel (i, j) of the header's pane (header.w).
    virtual PixelTrace trace(const TraceHeader& header, int i, int j) const = 0;
    // The most digits any step of pixel (i, j) loses to cancellation (the
    // largest of the trace's digits_lost (of all its samples), unrounded; 0 when no step has an
    // estimate), computed without building a trace: for a map of digits lost.
    // `branch`, when given, gets the pixel's branch from the same computation.
    virtual double digits_lost(int w, int i, int j, Branch* branch = nullptr) const = 0;
    // Pixel (i, j)'s branch (as intensity gives it) and its notes, tangent
    // and behind the eye (render/notes.hpp: the centre sample's when spp > 1).
    virtual PixelNotes notes(int w, int i, int j) const = 0;
    const Stages& stages() const { return stages_; }
    // Samples per pixel (render/samples.hpp): 1 is the pixel's centre.
    int spp() const { return spp_; }
    // Whether row() counts every pixel's branch (RowCounts::branches), or
    // only the non-finite ones (the rest left 0): the rows drawn in lanes
    // then skip their per-vector counting (its cost: docs/bench.md). On by
    // default; render --stats needs it.
    bool counts_branches() const { return count_branches_; }
    void set_branch_counting(bool on) { count_branches_ = on; }

protected:
    Kernel(const Stages& stages, int spp) : stages_(stages), spp_(spp) {}

private:
    Stages stages_;
    int spp_;
    bool count_branches_ = true;
};

// The kernel for the scene, computing in `real` (PRODUCT.md: --real) with
// `formula` for the eye's rays against spheres (--formula), with spp samples
// per pixel (--spp; throws UsageError unless valid_spp(spp)).
std::unique_ptr<Kernel> make_kernel(const Scene& scene, RealType real = RealType::double_,
                                    Formula formula = Formula::article, int spp = 1);

}  // namespace promyk
