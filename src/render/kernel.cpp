#include "render/kernel.hpp"

namespace promyk {

namespace kernels {

// Defined in render/kernel_impl.hpp and instantiated for each real type and
// formula in its own generated translation unit (render/kernel_instance.cpp.in).
template <class Real, Formula F>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages);

template <class Real>
std::unique_ptr<Kernel> make_kernel_in(const Scene& scene, const Stages& stages, Formula formula) {
    switch (formula) {
        case Formula::stable:
            return make_kernel_in<Real, Formula::stable>(scene, stages);
        case Formula::fma:
            return make_kernel_in<Real, Formula::fma>(scene, stages);
        case Formula::geometric:
            return make_kernel_in<Real, Formula::geometric>(scene, stages);
        case Formula::article:
            break;
    }
    return make_kernel_in<Real, Formula::article>(scene, stages);
}

}  // namespace kernels

std::unique_ptr<Kernel> make_kernel(const Scene& scene, RealType real, Formula formula) {
    const Stages stages = plan_stages(scene);
    switch (real) {
        case RealType::float_:
            return kernels::make_kernel_in<float>(scene, stages, formula);
        case RealType::long_double:
            return kernels::make_kernel_in<long double>(scene, stages, formula);
        case RealType::quad_:
            return kernels::make_kernel_in<quad>(scene, stages, formula);
        case RealType::double_:
            break;
    }
    return kernels::make_kernel_in<double>(scene, stages, formula);
}

}  // namespace promyk
