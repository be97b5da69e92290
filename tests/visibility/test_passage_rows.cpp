// Passage rows (visibility/portal/passages.h): every pair's row is stored by
// encode_passage_row and read by the flow only through PassageRow, narrow rows (a mask of
// their nonzero words) and wide rows (every word of their span) alike. So a row must come
// back bit for bit, through every reader: or_into(), and present()/stored_from() over
// any sub-range, which the flow spreads into a dense array.
#include "visibility/portal/passages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace pvs::portal_vis {
namespace {

// The row's words [from, to) spread out as the flow does, from present() and stored_from().
std::vector<uint64_t> spread(const PassageRow& row, uint32_t from, uint32_t to)
{
    if (row.wide)
        return std::vector<uint64_t>(row.words + (from - row.lo), row.words + (to - row.lo));
    std::vector<uint64_t> out(to - from, 0);
    const uint64_t* stored = row.stored_from(from);
    for (uint32_t i = 0; i < to - from; ++i)
        if ((row.present(from, to) >> i) & 1u)
            out[i] = *stored++;
    return out;
}

void expect_round_trip(const std::vector<uint64_t>& dense, bool expect_wide)
{
    std::vector<uint64_t> encoded = {0xdeadbeefu}; // rows follow one another in a block
    encode_passage_row(dense, encoded);
    const PassageRow row = PassageRow::decode(encoded.data() + 1);
    EXPECT_EQ(row.wide, expect_wide);
    uint32_t lo = 0, hi = uint32_t(dense.size());
    while (lo < hi && dense[lo] == 0)
        ++lo;
    while (hi > lo && dense[hi - 1] == 0)
        --hi;
    EXPECT_EQ(row.empty(), lo == hi);
    if (lo < hi) {
        EXPECT_EQ(row.lo, lo);
        EXPECT_EQ(row.hi, hi);
    }
    std::vector<uint64_t> back(dense.size(), 0);
    row.or_into(back.data());
    ASSERT_EQ(back, dense);
    for (uint32_t from = row.lo; from < row.hi; ++from)
        for (uint32_t to = from + 1; to <= row.hi; ++to)
            ASSERT_EQ(spread(row, from, to), std::vector<uint64_t>(dense.begin() + from, dense.begin() + to))
                << "words [" << from << ", " << to << ")";
    // Narrow rows store only their nonzero words.
    if (!row.wide) {
        size_t nonzero = 0;
        for (uint64_t w : dense)
            nonzero += w != 0;
        EXPECT_EQ(encoded.size(), 2 + nonzero);
    }
}

TEST(PassageRows, EmptyRowIsNarrowAndHoldsNothing) { expect_round_trip(std::vector<uint64_t>(19, 0), false); }

TEST(PassageRows, NarrowRowsKeepOnlyTheirNonzeroWords)
{
    std::vector<uint64_t> dense(19, 0);
    dense[3] = 1;
    expect_round_trip(dense, false);
    dense[7] = ~uint64_t{0};
    dense[5] = uint64_t{1} << 63;
    expect_round_trip(dense, false);
    std::vector<uint64_t> full(39, 0x8000000000000001u); // the widest narrow span, every word set
    expect_round_trip(full, false);
}

TEST(PassageRows, SpansPastTheMaskAreWide)
{
    std::vector<uint64_t> dense(200, 0);
    dense[10] = 5;
    dense[10 + kPassageMaskSpan] = 9; // a span of 40 words
    expect_round_trip(dense, true);
}

TEST(PassageRows, RowsFarIntoALargeZoneAreWideWhenTheirStartDoesNotFitTheHeader)
{
    std::vector<uint64_t> dense((size_t{1} << 24) + 4, 0); // 16 M words: lo needs 25 bits
    dense[(size_t{1} << 24) + 1] = 3;
    std::vector<uint64_t> encoded;
    encode_passage_row(dense, encoded);
    const PassageRow row = PassageRow::decode(encoded.data());
    EXPECT_TRUE(row.wide);
    EXPECT_EQ(row.lo, (uint32_t{1} << 24) + 1);
    EXPECT_EQ(row.hi, row.lo + 1);
    EXPECT_EQ(row.words[0], 3u);
}

TEST(PassageRows, RandomRowsComeBackThroughEveryReader)
{
    std::mt19937_64 rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<uint64_t> dense(1 + rng() % 80, 0);
        const size_t first = rng() % dense.size(), span = 1 + rng() % 50;
        for (size_t w = first; w < std::min(dense.size(), first + span); ++w)
            if (rng() % 2)
                dense[w] = rng() & rng();
        uint32_t lo = 0, hi = uint32_t(dense.size());
        while (lo < hi && dense[lo] == 0)
            ++lo;
        while (hi > lo && dense[hi - 1] == 0)
            --hi;
        expect_round_trip(dense, hi - lo > kPassageMaskSpan);
    }
}

} // namespace
} // namespace pvs::portal_vis
