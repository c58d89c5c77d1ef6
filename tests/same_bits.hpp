// Bit identity, the tests' measure of "the same number" (== would take -0
// for 0 and never a NaN for itself), and a long double with all the digits
// that tell two apart: one definition for every test file.
#pragma once

#include <cstring>
#include <sstream>
#include <string>

#include "math/vec3.hpp"

namespace promyk::testing {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool same_bits(const Vec3d& a, const Vec3d& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

// 21 significant digits: enough to tell any two long doubles apart.
inline std::string show_digits(long double v) {
    std::ostringstream out;
    out.precision(21);
    out << v;
    return out.str();
}

}  // namespace promyk::testing
