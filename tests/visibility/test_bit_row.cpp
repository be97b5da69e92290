// Bit rows: LSB-first layout shared with Quake and glVIS byte rows, iteration order, padding.
#include "visibility/bit_row.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

TEST(BitRow, ByteRowsMapBitJToByteJOver8AtPositionJMod8)
{
    // Byte 1 = 0x05 sets bits 8 and 10; byte 8 (second word) = 0x80 sets bit 71.
    std::vector<uint8_t> bytes(9, 0);
    bytes[1] = 0x05;
    bytes[8] = 0x80;
    std::vector<uint64_t> words(bits::words_for(72));
    bits::from_bytes(bytes, 72, words);
    std::vector<size_t> seen;
    bits::for_each_set(words, [&](size_t i) { seen.push_back(i); });
    EXPECT_EQ(seen, (std::vector<size_t>{8, 10, 71}));
    std::vector<uint8_t> back(9);
    bits::to_bytes(words, 72, back);
    EXPECT_EQ(back, bytes);
}

TEST(BitRow, PaddingBitsPastTheCountAreDroppedBothWays)
{
    std::vector<uint8_t> bytes{0xFF, 0xFF};
    std::vector<uint64_t> words(1);
    bits::from_bytes(bytes, 12, words);
    EXPECT_EQ(words[0], 0xFFFu);
    words[0] = ~uint64_t{0};
    std::vector<uint8_t> out(2);
    bits::to_bytes(words, 12, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{0xFF, 0x0F}));
}

TEST(BitRow, FillSetsExactlyTheCount)
{
    for (size_t n : {0u, 1u, 63u, 64u, 65u, 130u}) {
        std::vector<uint64_t> words(bits::words_for(n) + 1, 0xAAAAu);
        bits::fill(words, n);
        EXPECT_EQ(bits::count(words), n) << n;
    }
}

TEST(BitSet, SetClearTestCount)
{
    BitSet set(200);
    set.set(0);
    set.set(199);
    set.set(64);
    EXPECT_EQ(set.count(), 3u);
    EXPECT_TRUE(set.test(199));
    set.clear(199);
    EXPECT_FALSE(set.test(199));
    EXPECT_EQ(set.count(), 2u);
}

} // namespace
} // namespace pvs
