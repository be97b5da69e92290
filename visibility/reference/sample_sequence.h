// The random numbers of the sampled reference, as pure functions of (seed, stream, index), so
// that any thread can draw any sample and the result never depends on who drew it first.
//
//  - hash_unit(key, k): SplitMix64's finaliser on a key (a counter-based generator; the same
//    numbers on every platform), mapped to [0, 1) with 53 bits.
//  - stratified_direction(index, shift): point `index` of the (0,2)-sequence formed by Sobol's
//    first two dimensions (the bit reversal and v_k = v_{k-1} xor v_{k-1}/2), digitally shifted
//    by the 64 bits of `shift` (which keeps it a (0,2)-sequence), through the equal-area map
//    z = 1 - 2u, phi = 2 pi v: the first 2^k directions of a stream put one direction in every
//    elementary box of area 2^-k of the (u, v) square, so each doubling refines the last.
//  - stratified_unit(index, shift): the first of those dimensions alone, in [0, 1).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

namespace pvs::sampling {

constexpr uint64_t kGolden = 0x9e3779b97f4a7c15ull;

constexpr uint64_t mix64(uint64_t z)
{
    z += kGolden;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// A key for sample `index` of stream (seed, a, b): distinct inputs give unrelated keys.
constexpr uint64_t sample_key(uint64_t seed, uint64_t a, uint64_t b, uint64_t index)
{
    return mix64(mix64(mix64(mix64(seed) ^ (a * kGolden)) ^ (b * 0xd6e8feb86659fd93ull)) ^ index);
}

// The k-th uniform number in [0, 1) of a key.
constexpr double hash_unit(uint64_t key, uint64_t k) { return double(mix64(key + (k + 1) * kGolden) >> 11) * 0x1.0p-53; }

// Point `index` (< 2^32) of the van der Corput sequence in base 2 (the bit reversal), digitally
// shifted by `shift`: the first 2^k points of a stream put one point in every interval of 2^-k.
double stratified_unit(uint32_t index, uint32_t shift);

// The unit direction of point `index` (< 2^32) of a shifted (0,2)-sequence (see above).
glm::dvec3 stratified_direction(uint32_t index, uint64_t shift);

} // namespace pvs::sampling
