// Rows as alternating runs of clear and set bits: the in-memory codec of PVS rows that are dense
// and come in long runs (open zones, where a region sees most of the zone in stretches of region
// ids), where Quake's RLE, which only shortens runs of zero bytes, saves nothing.
//
// Form: run lengths in bits, LEB128 varints (7 bits a byte, low first, high bit = more), first a
// run of clear bits (possibly 0), then set, clear, ... until bit_count bits are described.
// Not a file format: Pvs (pvs.h) picks it per row when it is the shorter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

// Appends the runs of a row of bit_count bits to `out`.
void encode_bit_runs(std::span<const uint64_t> row, size_t bit_count, std::vector<uint8_t>& out);

// Decodes a row of bit_count bits into `out` (words_for(bit_count) words, overwritten; padding
// cleared). Returns false when `in` ends early or describes more than bit_count bits (the row is
// then filled as far as it went and the rest cleared).
bool decode_bit_runs(std::span<const uint8_t> in, size_t bit_count, std::span<uint64_t> out);

// Bit `bit` (< bit_count) of the row decode_bit_runs would give, read without decoding the rest:
// the walk stops at the run that holds it.
bool bit_runs_test(std::span<const uint8_t> in, size_t bit_count, size_t bit);

} // namespace pvs
