#include "visibility/reference/sample_sequence.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pvs::sampling {

namespace {

// Sobol's second dimension: direction numbers v_0 = 1/2, v_k = v_{k-1} xor v_{k-1} / 2.
struct Sobol2 {
    uint32_t v[32];
    constexpr Sobol2() : v{}
    {
        v[0] = 1u << 31;
        for (int k = 1; k < 32; ++k)
            v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    }
    constexpr uint32_t operator()(uint32_t index) const
    {
        uint32_t y = 0;
        for (int k = 0; index != 0; ++k, index >>= 1)
            if (index & 1u)
                y ^= v[k];
        return y;
    }
};
constexpr Sobol2 kSobol2;

constexpr uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

} // namespace

double stratified_unit(uint32_t index, uint32_t shift)
{
    return (double(reverse_bits(index) ^ shift) + 0.5) * 0x1.0p-32;
}

glm::dvec3 stratified_direction(uint32_t index, uint64_t shift)
{
    const double u = (double(reverse_bits(index) ^ uint32_t(shift)) + 0.5) * 0x1.0p-32;
    const double v = (double(kSobol2(index) ^ uint32_t(shift >> 32)) + 0.5) * 0x1.0p-32;
    const double z = 1.0 - 2.0 * u;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * v;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

} // namespace pvs::sampling
