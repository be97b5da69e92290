// Portal vis's finished rows as runs of nonzero words (visibility/portal/run_rows.h): every row
// the bake stores goes through encode_runs, and the flow reads them only through RunRow, so a
// row must come back bit for bit and its runs must keep the layout the flow relies on.
#include "visibility/portal/run_rows.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace pvs::portal_vis {
namespace {

RunRow encode_into(RowPool& pool, const std::vector<uint64_t>& dense)
{
    std::vector<uint64_t> encoded;
    encode_runs(dense, encoded);
    return pool.append(encoded);
}

// The row back (or_into), every bit through test(), and the layout: runs strictly increasing
// and disjoint, no run starting or ending on a zero word, gaps between runs of two zero words
// or more (one-word gaps are kept inside a run), every nonzero word inside a run.
void expect_round_trip(const std::vector<uint64_t>& dense, RowPool& pool)
{
    const RunRow row = encode_into(pool, dense);
    std::vector<uint64_t> back(dense.size(), 0);
    row.or_into(back.data());
    ASSERT_EQ(back, dense);
    for (uint32_t bit = 0; bit < uint32_t(dense.size() * 64); ++bit)
        ASSERT_EQ(row.test(bit), ((dense[bit >> 6] >> (bit & 63)) & 1u) != 0) << "bit " << bit;
    uint32_t covered = 0;
    for (uint32_t i = 0; i < row.runs(); ++i) {
        ASSERT_LT(row.start(i), row.end(i));
        ASSERT_LE(row.end(i), dense.size());
        EXPECT_NE(dense[row.start(i)], 0u);
        EXPECT_NE(dense[row.end(i) - 1], 0u);
        if (i > 0) {
            EXPECT_GE(row.start(i), row.end(i - 1) + 2) << "a one-word gap splits a run";
            EXPECT_EQ(row.first_run_after(row.end(i - 1)), i);
        }
        EXPECT_EQ(row.first_run_after(row.start(i)), i);
        covered += row.end(i) - row.start(i);
    }
    uint32_t nonzero = 0;
    for (uint64_t w : dense)
        nonzero += w != 0;
    EXPECT_GE(covered, nonzero);
    EXPECT_EQ(row.first_run_after(uint32_t(dense.size())), row.runs());
    EXPECT_EQ(row.size_words(), 2 + row.runs() + covered);
}

TEST(RunRows, EdgeCasesComeBackBitForBit)
{
    RowPool fresh; // nothing appended yet: no chunk to write into, nothing to return
    EXPECT_EQ(fresh.append_words({}), nullptr);
    EXPECT_EQ(fresh.bytes(), 0u);
    RowPool pool;
    expect_round_trip({}, pool);
    expect_round_trip(std::vector<uint64_t>(19, 0), pool);
    expect_round_trip(std::vector<uint64_t>(19, ~uint64_t{0}), pool);
    expect_round_trip({1}, pool);
    expect_round_trip({0, 0, uint64_t{1} << 63}, pool);
    expect_round_trip({5, 0, 7, 0, 0, 9, 0, 0, 0, 1}, pool); // a one-word gap, then two, then three
    const RunRow empty = encode_into(pool, std::vector<uint64_t>(4, 0));
    EXPECT_EQ(empty.runs(), 0u);
    EXPECT_EQ(empty.size_words(), 2u);
}

TEST(RunRows, RandomSparseAndDenseRowsComeBackBitForBit)
{
    std::mt19937_64 rng(17);
    RowPool pool;
    for (int trial = 0; trial < 300; ++trial) {
        const size_t words = 1 + rng() % 700;
        const unsigned density = unsigned(rng() % 4); // from nearly empty to mostly full
        std::vector<uint64_t> dense(words, 0);
        for (uint64_t& w : dense)
            if (rng() % 8 < density * 2)
                w = rng() & rng();
        expect_round_trip(dense, pool);
    }
}

TEST(RunRows, RowsNeverMoveAsThePoolGrows)
{
    RowPool pool;
    std::vector<std::vector<uint64_t>> dense;
    std::vector<RunRow> rows;
    std::mt19937_64 rng(5);
    for (int i = 0; i < 2000; ++i) { // well over one 512 KB chunk
        dense.emplace_back(64 + rng() % 64);
        for (uint64_t& w : dense.back())
            w = rng();
        rows.push_back(encode_into(pool, dense.back()));
    }
    EXPECT_GT(pool.bytes(), size_t{1} << 19);
    for (size_t i = 0; i < rows.size(); ++i) {
        std::vector<uint64_t> back(dense[i].size(), 0);
        rows[i].or_into(back.data());
        ASSERT_EQ(back, dense[i]) << "row " << i;
    }
}

} // namespace
} // namespace pvs::portal_vis
