// The general tracer for any scene, the article's too: for `bench effects`,
// which times the article's scene through it beside the article's kernel
// (issue 18: a scene pays only for the stages it uses). Rendering never
// calls this; make_kernel (render/kernel.hpp) picks the article's kernel for
// the article's scene.
#pragma once

#include <memory>

#include "render/kernel.hpp"

namespace promyk {

// make_kernel's kernel with the article's kernel ruled out: the stages the
// scene calls for (render/stages.hpp) with `article` false.
std::unique_ptr<Kernel> make_general_kernel(const Scene& scene, RealType real = RealType::double_,
                                            Formula formula = Formula::article, int spp = 1);

}  // namespace promyk
