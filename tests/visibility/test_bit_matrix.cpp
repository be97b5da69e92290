// bits::transpose_64 and bits::and_with_transpose against the definition, bit by bit.
#include "visibility/bit_matrix.h"
#include "visibility/bit_row.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace pvs {
namespace {

TEST(BitMatrix, TransposeOfOneBlockMovesEveryBit)
{
    std::mt19937_64 rng(3);
    uint64_t block[64], original[64];
    for (int i = 0; i < 64; ++i)
        block[i] = original[i] = rng();
    bits::transpose_64(block);
    for (int r = 0; r < 64; ++r)
        for (int c = 0; c < 64; ++c)
            ASSERT_EQ((block[c] >> r) & 1, (original[r] >> c) & 1) << r << "," << c;
}

TEST(BitMatrix, AndWithTransposeKeepsAPairOnlyWhenBothSidesHoldIt)
{
    for (size_t n : {1u, 63u, 64u, 65u, 130u, 200u}) {
        const size_t words = bits::words_for(n);
        std::mt19937_64 rng(n);
        std::vector<uint64_t> m(n * words, 0), original;
        for (size_t r = 0; r < n; ++r)
            for (size_t c = 0; c < n; ++c)
                if (rng() % 3 != 0)
                    bits::set(std::span(m).subspan(r * words, words), c);
        original = m;
        bits::and_with_transpose(m, n, words);
        for (size_t r = 0; r < n; ++r)
            for (size_t c = 0; c < n; ++c) {
                const bool rc = bits::test(std::span<const uint64_t>(original).subspan(r * words, words), c);
                const bool cr = bits::test(std::span<const uint64_t>(original).subspan(c * words, words), r);
                ASSERT_EQ(bits::test(std::span<const uint64_t>(m).subspan(r * words, words), c), rc && cr)
                    << n << ": " << r << "," << c;
            }
        for (size_t r = 0; r < n; ++r) // padding stays clear
            ASSERT_EQ(bits::count(std::span<const uint64_t>(m).subspan(r * words, words)),
                      [&] {
                          size_t k = 0;
                          for (size_t c = 0; c < n; ++c)
                              k += bits::test(std::span<const uint64_t>(m).subspan(r * words, words), c);
                          return k;
                      }());
    }
}

} // namespace
} // namespace pvs
