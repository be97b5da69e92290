#include "visibility/bit_matrix.h"

#include <algorithm>

namespace pvs::bits {

void transpose_64(uint64_t a[64])
{
    // Swap ever smaller off-diagonal sub-blocks: 32 x 32, then 16 x 16 inside each, ... 1 x 1.
    uint64_t mask = 0x00000000FFFFFFFFull;
    for (unsigned width = 32; width != 0; width >>= 1, mask ^= mask << width) {
        for (unsigned row = 0; row < 64; row = (row + width + 1) & ~width) {
            const uint64_t t = ((a[row] >> width) ^ a[row + width]) & mask;
            a[row] ^= t << width;
            a[row + width] ^= t;
        }
    }
}

void and_with_transpose(std::span<uint64_t> matrix, size_t n, size_t words_per_row)
{
    const size_t blocks = (n + 63) / 64;
    uint64_t upper[64], lower[64];
    for (size_t bi = 0; bi < blocks; ++bi)
        for (size_t bj = bi; bj < blocks; ++bj) {
            // upper: rows of block bi, word bj; lower: rows of block bj, word bi.
            const size_t rows_i = std::min<size_t>(64, n - bi * 64), rows_j = std::min<size_t>(64, n - bj * 64);
            for (size_t r = 0; r < 64; ++r) {
                upper[r] = r < rows_i ? matrix[(bi * 64 + r) * words_per_row + bj] : 0;
                lower[r] = r < rows_j ? matrix[(bj * 64 + r) * words_per_row + bi] : 0;
            }
            transpose_64(lower);
            for (size_t r = 0; r < 64; ++r)
                upper[r] &= lower[r];
            for (size_t r = 0; r < rows_i; ++r)
                matrix[(bi * 64 + r) * words_per_row + bj] = upper[r];
            transpose_64(upper);
            for (size_t r = 0; r < rows_j; ++r)
                matrix[(bj * 64 + r) * words_per_row + bi] = upper[r];
        }
}

} // namespace pvs::bits
