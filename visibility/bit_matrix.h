// Square bit matrices stored as rows of 64-bit words (bit_row.h's layout: row r, column c is bit
// c % 64 of word r * words_per_row + c / 64).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace pvs::bits {

// Keeps bit (r, c) only where (c, r) is set too: M = M AND transpose(M), in place, for an n x n
// matrix of `words_per_row` words a row (>= words_for(n); padding bits are left clear if they
// were). A PVS made of one-sided tests ("A cannot see B" proven from A's side) becomes
// symmetric and keeps a pair only when neither side ruled it out. 64 x 64 blocks at a time.
void and_with_transpose(std::span<uint64_t> matrix, size_t n, size_t words_per_row);

// Transposes one 64 x 64 block given as 64 words (word i = row i). Exposed for tests.
void transpose_64(uint64_t block[64]);

} // namespace pvs::bits
