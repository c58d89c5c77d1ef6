#include "render/kernel.hpp"

#include <algorithm>
#include <array>

#include "render/general_tracer.hpp"
#include "render/pane.hpp"
#include "render/quantize.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"

namespace promyk {

namespace {

class ArticleKernel final : public Kernel {
public:
    ArticleKernel(const Stages& stages, const ArticleWorld<double>& world) : Kernel(stages), world_(world) {}
    int channels() const override { return 1; }
    RowCounts row(int w, int i, std::uint8_t* out) const override { return render_row(world_, w, i, out); }
    Vec3d intensity(int w, int i, int j, Branch* branch) const override {
        NullRecorder none;
        const PixelResult<double> pixel = trace_pixel_ray(world_, w, i, j, none);
        if (branch) *branch = pixel.branch;
        return {pixel.I_P, pixel.I_P, pixel.I_P};
    }
    PixelTrace trace(const TraceHeader& header, int i, int j) const override {
        return trace_pixel(world_, header, i, j);
    }

private:
    ArticleWorld<double> world_;
};

template <class Sw, bool Rgb>
class GeneralKernel final : public Kernel {
public:
    GeneralKernel(const Stages& stages, const Scene& scene)
        : Kernel(stages), world_(compile_world<double, Rgb>(scene)) {}

    int channels() const override { return Rgb ? 3 : 1; }

    RowCounts row(int w, int i, std::uint8_t* out) const override {
        const double y_E = pane_y<double>(i, w);
        NullRecorder none;
        WorkCounts work;
        RowCounts counts;
        for (int j = 0; j < w; ++j) {
            const auto pixel = trace_general<Sw>(world_, Vec3d{pane_x<double>(j, w), y_E, world_.z_E}, work, none);
            ++counts.branches[static_cast<int>(pixel.branch)];
            if (pixel.branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
            if constexpr (Rgb) {
                out[3 * j] = to_byte(pixel.I_P.x);
                out[3 * j + 1] = to_byte(pixel.I_P.y);
                out[3 * j + 2] = to_byte(pixel.I_P.z);
            } else {
                out[j] = to_byte(pixel.I_P);
            }
        }
        counts.shadow_rays = work.shadow_rays;
        counts.sphere_tests = work.sphere_tests;
        counts.plane_tests = work.plane_tests;
        return counts;
    }

    Vec3d intensity(int w, int i, int j, Branch* branch) const override {
        NullRecorder none;
        WorkCounts work;
        const auto pixel = trace_general<Sw>(world_, pane_point(i, j, w, world_.z_E), work, none);
        if (branch) *branch = pixel.branch;
        if constexpr (Rgb)
            return pixel.I_P;
        else
            return {pixel.I_P, pixel.I_P, pixel.I_P};
    }

    PixelTrace trace(const TraceHeader& header, int i, int j) const override {
        PixelTrace trace;
        trace.header = header;
        trace.header.i = i;
        trace.header.j = j;
        RecordingRecorder recorder;
        WorkCounts work;
        const auto pixel =
            trace_general<Sw>(world_, pane_point(i, j, header.w, world_.z_E), work, recorder);
        trace.steps = recorder.take_steps();
        trace.groups = recorder.take_groups();
        trace.branch = pixel.branch;
        if (pixel.hit_kind != 0) trace.hit_object = object_name(pixel.hit_kind, pixel.hit_index);
        if constexpr (Rgb) {
            trace.result_rgb = pixel.I_P;
            trace.result = pixel.I_P.x;
            trace.rgb = {to_byte(pixel.I_P.x), to_byte(pixel.I_P.y), to_byte(pixel.I_P.z)};
            trace.grey = trace.rgb[0];
        } else {
            trace.result = pixel.I_P;
            trace.grey = to_byte(pixel.I_P);
        }
        trace.first_non_finite = first_non_finite_step(trace.steps);
        return trace;
    }

private:
    World<double, Rgb> world_;
};

template <bool Rgb, bool Shadows, bool Phong, bool Ambient, bool Many>
std::unique_ptr<Kernel> general(const Stages& stages, const Scene& scene) {
    return std::make_unique<GeneralKernel<Switches<Shadows, Phong, Ambient, Many>, Rgb>>(stages, scene);
}

// The 16 combinations of shadows, Phong, ambient and several objects, for
// one channel count: each an instantiation with only its own stages.
template <bool Rgb>
std::unique_ptr<Kernel> general(const Stages& s, const Scene& scene) {
    using Make = std::unique_ptr<Kernel> (*)(const Stages&, const Scene&);
    static constexpr std::array<Make, 16> table = {
        general<Rgb, false, false, false, false>, general<Rgb, false, false, false, true>,
        general<Rgb, false, false, true, false>,  general<Rgb, false, false, true, true>,
        general<Rgb, false, true, false, false>,  general<Rgb, false, true, false, true>,
        general<Rgb, false, true, true, false>,   general<Rgb, false, true, true, true>,
        general<Rgb, true, false, false, false>,  general<Rgb, true, false, false, true>,
        general<Rgb, true, false, true, false>,   general<Rgb, true, false, true, true>,
        general<Rgb, true, true, false, false>,   general<Rgb, true, true, false, true>,
        general<Rgb, true, true, true, false>,    general<Rgb, true, true, true, true>,
    };
    return table[(s.shadows ? 8 : 0) + (s.phong ? 4 : 0) + (s.ambient ? 2 : 0) + (s.objects ? 1 : 0)](s, scene);
}

}  // namespace

std::unique_ptr<Kernel> make_kernel(const Scene& scene) {
    const Stages stages = plan_stages(scene);
    if (stages.article) return std::make_unique<ArticleKernel>(stages, article_world(scene));
    return stages.colour ? general<true>(stages, scene) : general<false>(stages, scene);
}

}  // namespace promyk
