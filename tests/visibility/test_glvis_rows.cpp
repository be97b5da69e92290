// glVIS GL_PVS rows (../shared/formats/quake-doom-hepvs.md §4.5): uncompressed rows of
// (n + 7) / 8 bytes, LSB first; an empty lump means everything is visible. Hand-made lumps.
#include "visibility/bit_row.h"
#include "visibility/codec/glvis_rows.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

std::vector<size_t> positions(std::span<const uint64_t> words)
{
    std::vector<size_t> out;
    bits::for_each_set(words, [&](size_t i) { out.push_back(i); });
    return out;
}

TEST(GlvisRows, RowSizeIsRoundedUpToWholeBytes)
{
    EXPECT_EQ(glvis_row_bytes(0), 0u);
    EXPECT_EQ(glvis_row_bytes(1), 1u);
    EXPECT_EQ(glvis_row_bytes(8), 1u);
    EXPECT_EQ(glvis_row_bytes(9), 2u);
    EXPECT_EQ(glvis_lump_size(10), 20u);
}

TEST(GlvisRows, RowsAreUncompressedAndLeastSignificantBitFirst)
{
    // 10 subsectors, 2 bytes per row; row 0 = {0, 1, 9}, row 1 = {1, 8}, row 2 = {2}, ...
    std::vector<uint8_t> lump(glvis_lump_size(10), 0);
    lump[0] = 0x03;
    lump[1] = 0x02;
    lump[2] = 0x02;
    lump[3] = 0x01;
    lump[4] = 0x04;
    std::vector<uint64_t> row(1, ~uint64_t{0});
    EXPECT_EQ(decode_glvis_row(lump, 10, 0, row), GlvisRowStatus::decoded);
    EXPECT_EQ(positions(row), (std::vector<size_t>{0, 1, 9}));
    EXPECT_EQ(decode_glvis_row(lump, 10, 1, row), GlvisRowStatus::decoded);
    EXPECT_EQ(positions(row), (std::vector<size_t>{1, 8}));
    EXPECT_EQ(decode_glvis_row(lump, 10, 2, row), GlvisRowStatus::decoded);
    EXPECT_EQ(positions(row), (std::vector<size_t>{2}));
    EXPECT_EQ(decode_glvis_row(lump, 10, 9, row), GlvisRowStatus::decoded);
    EXPECT_TRUE(positions(row).empty());
}

TEST(GlvisRows, PaddingBitsInTheLastByteAreIgnored)
{
    // 3 subsectors, one byte per row, every byte 0xFF: only bits 0..2 count.
    const std::vector<uint8_t> lump(3, 0xFF);
    std::vector<uint64_t> row(1);
    EXPECT_EQ(decode_glvis_row(lump, 3, 1, row), GlvisRowStatus::decoded);
    EXPECT_EQ(row[0], 0x7u);
}

TEST(GlvisRows, EmptyLumpMeansEverythingVisible)
{
    std::vector<uint64_t> row(bits::words_for(70), 0);
    EXPECT_EQ(decode_glvis_row({}, 70, 5, row), GlvisRowStatus::empty_lump);
    EXPECT_EQ(bits::count(row), 70u);
    EXPECT_EQ(row[1], (uint64_t{1} << 6) - 1) << "padding stays clear";
}

TEST(GlvisRows, ShortLumpIsReportedAndTheRowIsAllVisible)
{
    // 10 subsectors need 20 bytes; this lump holds rows 0..2 and half of row 3.
    const std::vector<uint8_t> lump = {0x01, 0x00, 0x02, 0x00, 0x04, 0x00, 0x08};
    std::vector<uint64_t> row(1);
    EXPECT_EQ(decode_glvis_row(lump, 10, 2, row), GlvisRowStatus::decoded);
    EXPECT_EQ(positions(row), (std::vector<size_t>{2}));
    EXPECT_EQ(decode_glvis_row(lump, 10, 3, row), GlvisRowStatus::short_lump);
    EXPECT_EQ(row[0], 0x3FFu);
    EXPECT_EQ(decode_glvis_row(lump, 10, 9, row), GlvisRowStatus::short_lump);
    // A row number past the subsector count is never read, even from a long lump.
    const std::vector<uint8_t> long_lump(100, 0);
    EXPECT_EQ(decode_glvis_row(long_lump, 10, 10, row), GlvisRowStatus::short_lump);
    EXPECT_EQ(decode_glvis_row(long_lump, 10, SIZE_MAX, row), GlvisRowStatus::short_lump);
}

TEST(GlvisRows, ExtraBytesAfterTheLastRowAreNotRead)
{
    std::vector<uint8_t> lump = {0x05, 0x02, 0xEE, 0xEE};
    std::vector<uint64_t> row(1);
    EXPECT_EQ(decode_glvis_row(lump, 2, 1, row), GlvisRowStatus::decoded);
    EXPECT_EQ(positions(row), (std::vector<size_t>{1}));
}

TEST(GlvisRows, EncoderWritesTheWholeLumpAndClearsPadding)
{
    // 3 subsectors, each sees itself; row 0 also has garbage past bit 2.
    std::vector<uint64_t> rows = {0x1 | 0xF0, 0x2, 0x4 | 0x1};
    std::vector<uint8_t> lump = {0x99}; // appended after existing content
    encode_glvis_rows(rows, 3, lump);
    EXPECT_EQ(lump, (std::vector<uint8_t>{0x99, 0x01, 0x02, 0x05}));

    // 9 subsectors: two bytes per row, rows spread over two words' worth of bytes.
    std::vector<uint64_t> nine(9, 0);
    for (size_t i = 0; i < 9; ++i)
        nine[i] = (uint64_t{1} << i) | (uint64_t{1} << 8);
    std::vector<uint8_t> out;
    encode_glvis_rows(nine, 9, out);
    ASSERT_EQ(out.size(), glvis_lump_size(9));
    EXPECT_EQ(out[0], 0x01);
    EXPECT_EQ(out[1], 0x01);
    EXPECT_EQ(out[16], 0x00);
    EXPECT_EQ(out[17], 0x01);
    for (size_t i = 0; i < 9; ++i) {
        std::vector<uint64_t> row(1);
        ASSERT_EQ(decode_glvis_row(out, 9, i, row), GlvisRowStatus::decoded);
        EXPECT_EQ(row[0], nine[i]);
    }
}

TEST(GlvisRows, ZeroSubsectors)
{
    std::vector<uint8_t> out;
    encode_glvis_rows({}, 0, out);
    EXPECT_TRUE(out.empty());
    std::vector<uint64_t> row;
    EXPECT_EQ(decode_glvis_row({}, 0, 0, row), GlvisRowStatus::empty_lump);
}

} // namespace
} // namespace pvs
