#include "render/samples.hpp"

#include <cmath>

namespace promyk {

bool valid_spp(int spp) {
    if (spp < 1 || spp > max_spp) return false;
    const int n = spp_side(spp);
    return n * n == spp;
}

int spp_side(int spp) {
    int n = 1;
    while ((n + 1) * (n + 1) <= spp) ++n;
    return n;
}

SampleOffset sample_offset(int i, int j, int s, int spp) {
    if (spp <= 1) return {};  // the centre, exactly
    return sample_offset_on(i, j, s, spp_side(spp));
}

int centre_sample(int i, int j, int spp) {
    int best = 0;
    double best_d = INFINITY;
    for (int s = 0; s < spp; ++s) {
        const SampleOffset o = sample_offset(i, j, s, spp);
        const double d = o.u * o.u + o.v * o.v;
        if (d < best_d) best = s, best_d = d;
    }
    return best;
}

}  // namespace promyk
