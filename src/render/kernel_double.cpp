// The kernels computing in double (see render/kernel_impl.hpp).
#include "render/kernel_impl.hpp"

namespace promyk::kernels {

template std::unique_ptr<Kernel> make_kernel_in<double>(const Scene&, const Stages&);

}  // namespace promyk::kernels
