#include "render/kernel.hpp"

#include "render/kernel_impl.hpp"

namespace promyk {

std::unique_ptr<Kernel> make_kernel(const Scene& scene, RealType real) {
    const Stages stages = plan_stages(scene);
    switch (real) {
        case RealType::float_:
            return kernels::make_kernel_in<float>(scene, stages);
        case RealType::long_double:
            return kernels::make_kernel_in<long double>(scene, stages);
        case RealType::quad_:
            return kernels::make_kernel_in<quad>(scene, stages);
        case RealType::double_:
            break;
    }
    return kernels::make_kernel_in<double>(scene, stages);
}

}  // namespace promyk
