#include "render/kernel.hpp"

#include <fmt/format.h>

#include "render/samples.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace kernels {

// Defined in render/kernel_impl.hpp and instantiated for each real type and
// formula in its own generated translation unit (render/kernel_instance.cpp.in).
template <class Real, Formula F>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages, int spp);

template <class Real>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages, Formula formula, int spp) {
    switch (formula) {
        case Formula::stable:
            return make_kernel_in<Real, Formula::stable>(scene, stages, spp);
        case Formula::fma:
            return make_kernel_in<Real, Formula::fma>(scene, stages, spp);
        case Formula::geometric:
            return make_kernel_in<Real, Formula::geometric>(scene, stages, spp);
        case Formula::article:
            break;
    }
    return make_kernel_in<Real, Formula::article>(scene, stages, spp);
}

}  // namespace kernels

std::unique_ptr<Kernel> make_kernel(const Scene& scene, RealType real, Formula formula, int spp) {
    if (!valid_spp(spp))
        throw UsageError(
            ui_message("kernel_spp_square", {{"max", std::to_string(max_spp)}, {"spp", std::to_string(spp)}}));
    const Stages stages = plan_stages(scene);
    switch (real) {
        case RealType::float_:
            return kernels::make_kernel_in<float>(scene, stages, formula, spp);
        case RealType::long_double:
#if PROMYK_HAS_X87_LONG_DOUBLE
            return kernels::make_kernel_in<long double>(scene, stages, formula, spp);
#else
            throw UsageError(ui_message("wasm_no_long_double"));
#endif
        case RealType::quad_:
            return kernels::make_kernel_in<quad>(scene, stages, formula, spp);
        case RealType::double_:
            break;
    }
    return kernels::make_kernel_in<double>(scene, stages, formula, spp);
}

}  // namespace promyk
