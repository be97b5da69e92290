// The bit-runs row codec (visibility/codec/bit_runs.h): rows come back bit for bit for every
// shape (empty, one bit, word edges, all set, random runs, random noise), truncated or
// overlong input is refused without reading past it, and a PVS of dense rows in long runs (an
// open zone's) is stored compressed at a fraction of its matrix.
#include "visibility/bit_row.h"
#include "visibility/codec/bit_runs.h"
#include "visibility/pvs.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace pvs {
namespace {

std::vector<uint64_t> runs_row(size_t n, std::mt19937& rng, size_t mean_run)
{
    std::vector<uint64_t> row(bits::words_for(n), 0);
    std::geometric_distribution<size_t> run(1.0 / double(mean_run));
    bool value = rng() % 2;
    for (size_t at = 0; at < n; value = !value) {
        const size_t end = std::min(n, at + 1 + run(rng));
        for (; at < end; ++at)
            if (value)
                bits::set(row, at);
    }
    return row;
}

TEST(BitRuns, EveryRowComesBackBitForBit)
{
    std::mt19937 rng(8);
    for (size_t n : {0u, 1u, 63u, 64u, 65u, 127u, 128u, 1000u, 33626u})
        for (int shape = 0; shape < 5; ++shape) {
            std::vector<uint64_t> row(bits::words_for(n), 0);
            if (shape == 1) {
                bits::fill(row, n);
            } else if (shape == 2) {
                row = runs_row(n, rng, 40);
            } else if (shape == 3) {
                for (size_t i = 0; i < n; ++i)
                    if (rng() % 2)
                        bits::set(row, i);
            } else if (shape == 4 && n) {
                bits::set(row, n - 1);
            }
            std::vector<uint8_t> encoded;
            encode_bit_runs(row, n, encoded);
            std::vector<uint64_t> back(bits::words_for(n) + 1, ~uint64_t{0});
            ASSERT_TRUE(decode_bit_runs(encoded, n, back)) << n << " shape " << shape;
            back.resize(bits::words_for(n));
            ASSERT_EQ(back, row) << n << " shape " << shape;
        }
}

TEST(BitRuns, TruncatedAndOverlongInputIsRefused)
{
    std::mt19937 rng(2);
    const size_t n = 5000;
    const std::vector<uint64_t> row = runs_row(n, rng, 300);
    std::vector<uint8_t> encoded;
    encode_bit_runs(row, n, encoded);
    std::vector<uint64_t> out(bits::words_for(n));
    for (size_t cut = 0; cut < encoded.size(); ++cut)
        EXPECT_FALSE(decode_bit_runs(std::span(encoded).first(cut), n, out)) << cut;
    const std::vector<uint8_t> too_long{0x80, 0x80, 0x01}; // 16 384 clear bits in a 5 000-bit row
    EXPECT_FALSE(decode_bit_runs(too_long, n, out));
    const std::vector<uint8_t> endless(20, 0xff); // a varint that never ends
    EXPECT_FALSE(decode_bit_runs(endless, n, out));
}

// One bit read in place is the bit the whole decode gives, for every bit of every shape, and for
// input cut short or running past the row (decode_bit_runs' partial row is the known answer).
TEST(BitRuns, OneBitReadInPlaceIsTheDecodedBit)
{
    std::mt19937 rng(5);
    const size_t n = 3000;
    for (int shape = 0; shape < 3; ++shape) {
        std::vector<uint64_t> row = runs_row(n, rng, shape == 0 ? 5 : 200);
        if (shape == 2)
            bits::fill(row, n);
        std::vector<uint8_t> encoded;
        encode_bit_runs(row, n, encoded);
        encoded.push_back(0x7f); // an overlong last run: the decoder sets or clears the rest
        for (size_t cut : {encoded.size() - 1, encoded.size() / 2, encoded.size(), size_t{1}}) {
            const std::span<const uint8_t> in = std::span(encoded).first(cut);
            std::vector<uint64_t> decoded(bits::words_for(n));
            decode_bit_runs(in, n, decoded);
            for (size_t bit = 0; bit < n; ++bit)
                ASSERT_EQ(bit_runs_test(in, n, bit), bits::test(decoded, bit))
                    << shape << " cut " << cut << " bit " << bit;
            EXPECT_FALSE(bit_runs_test(in, n, n)); // past the row
        }
    }
}

TEST(BitRuns, DenseRowsInLongRunsAreStoredCompressedAndSmall)
{
    const uint32_t n = 6000;
    std::mt19937 rng(4);
    std::vector<std::vector<uint64_t>> rows;
    for (uint32_t r = 0; r < n; ++r)
        rows.push_back(runs_row(n, rng, 400)); // about half set, in runs of hundreds
    const Pvs pvs = Pvs::build(n, [&](uint32_t r, std::span<uint64_t> out) {
        std::copy(rows[r].begin(), rows[r].end(), out.begin());
        return true;
    });
    EXPECT_EQ(pvs.storage(), Pvs::Storage::Compressed);
    EXPECT_LT(pvs.memory_bytes(), size_t(n) * pvs.words_per_row() * 8 / 10);
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t r = 0; r < n; r += 97) {
        pvs.decode_row(r, row);
        ASSERT_EQ(row, rows[r]) << r;
    }
}

} // namespace
} // namespace pvs
