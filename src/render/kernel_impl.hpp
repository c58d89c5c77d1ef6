// The kernels as templates over the real type, instantiated once per type in
// kernel_<type>.cpp (one translation unit each, so they compile in parallel).
// Internal to render/: use make_kernel (render/kernel.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <type_traits>

#include "math/real.hpp"
#include "render/general_tracer.hpp"
#include "render/kernel.hpp"
#include "render/pane.hpp"
#include "render/quantize.hpp"
#include "render/renderer.hpp"
#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"

namespace promyk::kernels {

template <class Real>
Vec3d to_double(const Vec3<Real>& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}


template <class Real>
class ArticleKernel final : public Kernel {
public:
    ArticleKernel(const Stages& stages, const ArticleWorld<double>& world)
        : Kernel(stages),
          world_{Real(world.z_E), to_real<Real>(world.S), Real(world.r), to_real<Real>(world.L), Real(world.I),
                 Real(world.background)} {}
    int channels() const override { return 1; }
    RowCounts row(int w, int i, std::uint8_t* out) const override {
        if constexpr (std::is_same_v<Real, double>) {
            return render_row(world_, w, i, out);  // the tuned loop of the article's program
        } else {
            NullRecorder none;
            RowCounts counts;
            counts.sphere_tests = w;
            for (int j = 0; j < w; ++j) {
                const PixelResult<Real> pixel = trace_pixel_ray(world_, w, i, j, none);
                ++counts.branches[static_cast<int>(pixel.branch)];
                if (pixel.branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
                out[j] = to_byte(static_cast<double>(pixel.I_P));
            }
            return counts;
        }
    }
    Vec3d intensity(int w, int i, int j, Branch* branch) const override {
        NullRecorder none;
        const PixelResult<Real> pixel = trace_pixel_ray(world_, w, i, j, none);
        if (branch) *branch = pixel.branch;
        const double I_P = static_cast<double>(pixel.I_P);
        return {I_P, I_P, I_P};
    }
    PixelTrace trace(const TraceHeader& header, int i, int j) const override {
        if constexpr (std::is_same_v<Real, double>) {
            return trace_pixel(world_, header, i, j);
        } else {
            PixelTrace trace;
            trace.header = header;
            trace.header.i = i;
            trace.header.j = j;
            trace.header.real = std::string(real_type_name(RealTraits<Real>::type));
            RecordingRecorder recorder;
            const PixelResult<Real> pixel = trace_pixel_ray(world_, header.w, i, j, recorder);
            trace.steps = recorder.take_steps();
            trace.branch = pixel.branch;
            trace.result = static_cast<double>(pixel.I_P);
            trace.result_real_text = {real_text(pixel.I_P)};
            trace.grey = to_byte(trace.result);
            trace.first_non_finite = first_non_finite_step(trace.steps);
            return trace;
        }
    }

private:
    ArticleWorld<Real> world_;
};

template <class Sw, bool Rgb, class Real>
class GeneralKernel final : public Kernel {
public:
    GeneralKernel(const Stages& stages, const Scene& scene)
        : Kernel(stages), world_(compile_world<Real, Rgb>(scene)) {}

    int channels() const override { return Rgb ? 3 : 1; }

    RowCounts row(int w, int i, std::uint8_t* out) const override {
        const Real y_E = pane_y<Real>(i, w);
        NullRecorder none;
        WorkCounts work;
        RowCounts counts;
        for (int j = 0; j < w; ++j) {
            const auto pixel = trace_general<Sw>(world_, Vec3<Real>{pane_x<Real>(j, w), y_E, world_.z_E}, work, none);
            ++counts.branches[static_cast<int>(pixel.branch)];
            if (pixel.branch == Branch::non_finite && counts.first_non_finite_j < 0) counts.first_non_finite_j = j;
            if constexpr (Rgb) {
                out[3 * j] = to_byte(static_cast<double>(pixel.I_P.x));
                out[3 * j + 1] = to_byte(static_cast<double>(pixel.I_P.y));
                out[3 * j + 2] = to_byte(static_cast<double>(pixel.I_P.z));
            } else {
                out[j] = to_byte(static_cast<double>(pixel.I_P));
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
        if constexpr (Rgb) {
            return to_double(pixel.I_P);
        } else {
            const double I_P = static_cast<double>(pixel.I_P);
            return {I_P, I_P, I_P};
        }
    }

    PixelTrace trace(const TraceHeader& header, int i, int j) const override {
        PixelTrace trace;
        trace.header = header;
        trace.header.i = i;
        trace.header.j = j;
        trace.header.real = std::string(real_type_name(RealTraits<Real>::type));
        RecordingRecorder recorder;
        WorkCounts work;
        const auto pixel =
            trace_general<Sw>(world_, pane_point(i, j, header.w, world_.z_E), work, recorder);
        trace.steps = recorder.take_steps();
        trace.groups = recorder.take_groups();
        trace.branch = pixel.branch;
        if (pixel.hit_kind != 0) trace.hit_object = object_name(pixel.hit_kind, pixel.hit_index);
        if constexpr (Rgb) {
            const Vec3d I_P = to_double(pixel.I_P);
            trace.result_rgb = I_P;
            trace.result = I_P.x;
            trace.rgb = {to_byte(I_P.x), to_byte(I_P.y), to_byte(I_P.z)};
            trace.grey = trace.rgb[0];
            if constexpr (!std::is_same_v<Real, double>)
                trace.result_real_text = {real_text(pixel.I_P.x), real_text(pixel.I_P.y), real_text(pixel.I_P.z)};
        } else {
            trace.result = static_cast<double>(pixel.I_P);
            trace.grey = to_byte(trace.result);
            if constexpr (!std::is_same_v<Real, double>) trace.result_real_text = {real_text(pixel.I_P)};
        }
        trace.first_non_finite = first_non_finite_step(trace.steps);
        return trace;
    }

private:
    World<Real, Rgb> world_;
};

template <class Real, bool Rgb, bool Shadows, bool Phong, bool Ambient, bool Many>
std::unique_ptr<Kernel> general(const Stages& stages, const Scene& scene) {
    return std::make_unique<GeneralKernel<Switches<Shadows, Phong, Ambient, Many>, Rgb, Real>>(stages, scene);
}

// The 16 combinations of shadows, Phong, ambient and several objects, for
// one channel count: each an instantiation with only its own stages.
template <class Real, bool Rgb>
std::unique_ptr<Kernel> general(const Stages& s, const Scene& scene) {
    using Make = std::unique_ptr<Kernel> (*)(const Stages&, const Scene&);
    static constexpr std::array<Make, 16> table = {
        general<Real, Rgb, false, false, false, false>, general<Real, Rgb, false, false, false, true>,
        general<Real, Rgb, false, false, true, false>,  general<Real, Rgb, false, false, true, true>,
        general<Real, Rgb, false, true, false, false>,  general<Real, Rgb, false, true, false, true>,
        general<Real, Rgb, false, true, true, false>,   general<Real, Rgb, false, true, true, true>,
        general<Real, Rgb, true, false, false, false>,  general<Real, Rgb, true, false, false, true>,
        general<Real, Rgb, true, false, true, false>,   general<Real, Rgb, true, false, true, true>,
        general<Real, Rgb, true, true, false, false>,   general<Real, Rgb, true, true, false, true>,
        general<Real, Rgb, true, true, true, false>,    general<Real, Rgb, true, true, true, true>,
    };
    return table[(s.shadows ? 8 : 0) + (s.phong ? 4 : 0) + (s.ambient ? 2 : 0) + (s.objects ? 1 : 0)](s, scene);
}

// The kernel for the scene in type Real: the article's when the stages say so.
template <class Real>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages) {
    if (stages.article) return std::make_unique<ArticleKernel<Real>>(stages, article_world(scene));
    return stages.colour ? general<Real, true>(stages, scene) : general<Real, false>(stages, scene);
}

extern template std::unique_ptr<Kernel> make_kernel_in<float>(const Scene&, const Stages&);
extern template std::unique_ptr<Kernel> make_kernel_in<double>(const Scene&, const Stages&);
extern template std::unique_ptr<Kernel> make_kernel_in<long double>(const Scene&, const Stages&);
extern template std::unique_ptr<Kernel> make_kernel_in<quad>(const Scene&, const Stages&);

}  // namespace promyk::kernels
