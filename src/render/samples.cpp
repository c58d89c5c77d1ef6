#include "render/samples.hpp"

#include <cmath>

namespace promyk {

namespace {

// A well-mixed 32-bit integer hash (the "lowbias32" of Chris Wellons's hash
// prospector): every input bit affects every output bit.
std::uint32_t mix(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace

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

std::uint32_t sample_hash(int i, int j, int s) {
    const auto u32 = [](int x) { return static_cast<std::uint32_t>(x); };
    // The constants keep (0, 0, 0) from hashing to 0 (mix(0) is 0).
    return mix(u32(i) * 0x9e3779b1U ^ mix(u32(j) * 0x85ebca6bU ^ mix(u32(s) + 0x632be5abU)));
}

SampleOffset sample_offset(int i, int j, int s, int spp) {
    if (spp <= 1) return {};  // the centre, exactly
    const int n = spp_side(spp);
    const std::uint32_t h = sample_hash(i, j, s);
    // 16 bits of jitter along each axis: exact binary fractions.
    const double jitter_u = static_cast<double>(h & 0xffffU) / 65536.0;
    const double jitter_v = static_cast<double>(h >> 16) / 65536.0;
    const int column = s % n, row = s / n;
    return {(column + jitter_u) / n - 0.5, (row + jitter_v) / n - 0.5};
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
