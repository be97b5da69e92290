// The gap between a PVS and a reference (visibility/eval/pvs_gap.h) on rows small enough to
// count by hand.
#include "visibility/eval/pvs_gap.h"

#include "visibility/bit_row.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace pvs {
namespace {

Pvs rows_from(const std::vector<std::vector<uint32_t>>& rows)
{
    return Pvs::build(uint32_t(rows.size()), [&](uint32_t r, std::span<uint64_t> row) {
        for (uint32_t c : rows[r])
            bits::set(row, c);
        return true;
    });
}

TEST(PvsGap, WorstExcessPairsAreTheCostliestBitsBeyondTheReference)
{
    const Pvs reference = rows_from({{0, 1}, {0, 1}, {2}});
    const Pvs all = rows_from({{0, 1, 2}, {0, 1, 2}, {0, 1, 2}});
    const std::vector<uint64_t> cost = {5, 1, 9};
    // Beyond the reference: (0,2) 9, (1,2) 9, (2,0) 5, (2,1) 1. The three costliest, the dearest
    // first, ties in row order:
    const std::vector<CostlyPair> worst = worst_excess_pairs(&all, reference, cost, 3);
    ASSERT_EQ(worst.size(), 3u);
    EXPECT_EQ(worst[0].row, 0u);
    EXPECT_EQ(worst[0].region, 2u);
    EXPECT_EQ(worst[0].cost, 9u);
    EXPECT_EQ(worst[1].row, 1u);
    EXPECT_EQ(worst[1].region, 2u);
    EXPECT_EQ(worst[2].row, 2u);
    EXPECT_EQ(worst[2].region, 0u);
    EXPECT_EQ(worst[2].cost, 5u);
    // A null PVS is every region: the same pairs.
    const std::vector<CostlyPair> none = worst_excess_pairs(nullptr, reference, cost, 3);
    ASSERT_EQ(none.size(), 3u);
    EXPECT_EQ(none[2].row, 2u);
    // More asked than there are: all four; the reference against itself: none.
    EXPECT_EQ(worst_excess_pairs(&all, reference, cost, 10).size(), 4u);
    EXPECT_TRUE(worst_excess_pairs(&reference, reference, cost, 10).empty());
    EXPECT_EQ(pvs_gap(&all, reference).excess_bits, 4u);
    EXPECT_THROW(worst_excess_pairs(&all, reference, std::vector<uint64_t>{1, 2}, 3), std::invalid_argument);
}

} // namespace
} // namespace pvs
