#include "render/general_kernel.hpp"

#include "render/samples.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"

namespace promyk {

namespace kernels {
// Defined in render/kernel_impl.hpp, instantiated per real type and formula.
template <class Real, Formula F>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages, int spp);
}  // namespace kernels

namespace {

template <class Real>
std::unique_ptr<Kernel> general_in(const Scene& scene, const Stages& stages, Formula formula, int spp) {
    switch (formula) {
        case Formula::stable:
            return kernels::make_kernel_in<Real, Formula::stable>(scene, stages, spp);
        case Formula::fma:
            return kernels::make_kernel_in<Real, Formula::fma>(scene, stages, spp);
        case Formula::geometric:
            return kernels::make_kernel_in<Real, Formula::geometric>(scene, stages, spp);
        case Formula::article:
            break;
    }
    return kernels::make_kernel_in<Real, Formula::article>(scene, stages, spp);
}

}  // namespace

std::unique_ptr<Kernel> make_general_kernel(const Scene& scene, RealType real, Formula formula, int spp) {
    if (!valid_spp(spp))
        throw UsageError(
            ui_message("kernel_spp_square", {{"max", std::to_string(max_spp)}, {"spp", std::to_string(spp)}}));
    Stages stages = plan_stages(scene);
    stages.article = false;  // the general tracer, whatever the scene
    switch (real) {
        case RealType::float_:
            return general_in<float>(scene, stages, formula, spp);
        case RealType::quad_:
            return general_in<quad>(scene, stages, formula, spp);
        case RealType::long_double:
#if PROMYK_HAS_X87_LONG_DOUBLE
            return general_in<long double>(scene, stages, formula, spp);
#else
            throw UsageError(ui_message("wasm_no_long_double"));
#endif
        case RealType::double_:
            break;
    }
    return general_in<double>(scene, stages, formula, spp);
}

}  // namespace promyk
