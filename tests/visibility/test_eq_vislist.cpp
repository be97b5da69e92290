// EverQuest VISLIST codec (../shared/formats/eq-s3d-wld.md §4.4 byte form, §4.5 word form):
// all 23 known-answer vectors of §8.1, the §8.2 encoder example, the §4.7 region known answer,
// and the encoder's exact output at the code-size boundaries.
#include "visibility/bit_row.h"
#include "visibility/codec/eq_vislist.h"
#include "visibility/codec/quake_rle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>

namespace pvs {
namespace {

std::vector<size_t> positions(std::span<const uint64_t> words)
{
    std::vector<size_t> out;
    bits::for_each_set(words, [&](size_t i) { out.push_back(i); });
    return out;
}

BitSet row_of(size_t region_count, const std::vector<size_t>& set)
{
    BitSet row(region_count);
    for (size_t i : set)
        row.set(i);
    return row;
}

struct Run {
    size_t first;
    size_t last; // inclusive, as the spec's "a..b"
};

struct Vector {
    int number;
    const char* name;
    std::vector<uint8_t> bytes;
    size_t region_count;
    std::vector<Run> expected;
    size_t expected_count;
    bool well_formed = true;
    size_t consumed = SIZE_MAX; // SIZE_MAX: the whole input
    bool word_form = false;
};

void PrintTo(const Vector& v, std::ostream* os) { *os << "#" << v.number << " " << v.name; }

// §8.1, byte arrays and expected positions exactly as the table gives them.
const std::vector<Vector>& vectors()
{
    static const std::vector<Vector> table = {
        {1, "empty list (range_count = 0)", {}, 10, {}, 0},
        {2, "single include", {0xC1}, 4, {{0, 0}}, 1},
        {3, "skip then include", {0x02, 0xC3}, 10, {{2, 4}}, 3},
        {4, "0x3F with u16 LE (0x012C = 300)", {0x3F, 0x2C, 0x01, 0xC2}, 400, {{300, 301}}, 2},
        {5, "endianness probe (LE 0x0100 = 256)", {0x3F, 0x00, 0x01, 0xC1}, 300, {{256, 256}}, 1},
        {6, "0xFF with u16 LE (0x0040 = 64)", {0xFF, 0x40, 0x00}, 64, {{0, 63}}, 64},
        {7, "skip then 0xFF (0x0104 = 260)", {0x05, 0xFF, 0x04, 0x01}, 300, {{5, 264}}, 260},
        {8, "0x40 class: skip 3, include 2", {0x5A}, 8, {{3, 4}}, 2},
        {9, "0x80 class: include 3, skip 2; then include 1", {0x9A, 0xC1}, 8, {{0, 2}, {5, 5}}, 4},
        {10, "all six classes", {0x01, 0xC2, 0x4B, 0x91, 0x3F, 0x0A, 0x00, 0xFF, 0x03, 0x00}, 30,
         {{1, 2}, {4, 8}, {20, 22}}, 10},
        {11, "zero-sized codes are no-ops", {0x00, 0xC0, 0x40, 0x80, 0x3F, 0x00, 0x00, 0xFF, 0x00, 0x00, 0xC1}, 4,
         {{0, 0}}, 1},
        {12, "include run exceeds N", {0xC5}, 3, {{0, 2}}, 3},
        {13, "0xFF run exceeds N (256 requested)", {0x02, 0xFF, 0x00, 0x01}, 10, {{2, 9}}, 8},
        {14, "skip beyond N", {0x3F, 0xFF, 0xFF, 0xC1}, 10, {}, 0},
        {15, "truncated 0x3F (malformed, stop)", {0xC1, 0x3F, 0x05}, 10, {{0, 0}}, 1, false, 1},
        {16, "truncated 0xFF (malformed, stop)", {0x01, 0xFF, 0x05}, 10, {}, 0, false, 1},
        {17, "largest 0x40 form: skip 7, include 7", {0x7F}, 20, {{7, 13}}, 7},
        {18, "largest 0x80 form: include 7, skip 7; include 1", {0xBF, 0xC1}, 20, {{0, 6}, {14, 14}}, 8},
        {19, "largest 0xC0 form (62)", {0xFE}, 100, {{0, 61}}, 62},
        {20, "largest short skip (62)", {0x3E, 0xC1}, 100, {{62, 62}}, 1},
        {21, "LQ fixture (real-looking data)",
         {0xFE, 0xF2, 0x18, 0xCA, 0x56, 0x51, 0x27, 0xDA, 0x57, 0x3F, 0x2C, 0x0A, 0x13, 0xD8}, 2905,
         {{0, 111}, {136, 145}, {148, 153}, {156, 156}, {196, 221}, {224, 230}, {2854, 2877}}, 186},
        {22, "LQ fixture 2 (trailing skip)", {0xC8, 0x32}, 100, {{0, 7}}, 8},
        {23, "word form (bit 7 clear), QL interpretation", {0x05, 0x00, 0x01, 0x01}, 300, {{5, 5}, {257, 257}}, 2,
         true, SIZE_MAX, true},
    };
    return table;
}

std::vector<size_t> expand(const std::vector<Run>& runs)
{
    std::vector<size_t> out;
    for (const Run& run : runs)
        for (size_t i = run.first; i <= run.last; ++i)
            out.push_back(i);
    return out;
}

EqVislistResult decode(const Vector& v, std::span<uint64_t> words)
{
    return v.word_form ? decode_eq_vislist_words(v.bytes, v.region_count, words)
                       : decode_eq_vislist_bytes(v.bytes, v.region_count, words);
}

class EqVislistKnownAnswer : public ::testing::TestWithParam<Vector> {};

TEST_P(EqVislistKnownAnswer, DecodesToTheSpecPositions)
{
    const Vector& v = GetParam();
    const std::vector<size_t> expected = expand(v.expected);
    ASSERT_EQ(expected.size(), v.expected_count) << "table transcription";

    // Pre-fill with garbage: the decoder must overwrite every word.
    std::vector<uint64_t> words(bits::words_for(v.region_count), ~uint64_t{0});
    const EqVislistResult r = decode(v, words);
    EXPECT_EQ(positions(words), expected);
    EXPECT_EQ(bits::count(words), v.expected_count);
    EXPECT_EQ(r.well_formed, v.well_formed);
    EXPECT_EQ(r.consumed, v.consumed == SIZE_MAX ? v.bytes.size() : v.consumed);
}

TEST_P(EqVislistKnownAnswer, ReencodingDecodesToTheSameRow)
{
    const Vector& v = GetParam();
    std::vector<uint64_t> words(bits::words_for(v.region_count));
    decode(v, words);
    std::vector<uint64_t> again(words.size(), ~uint64_t{0});
    if (v.word_form) {
        std::vector<uint8_t> bytes;
        ASSERT_TRUE(encode_eq_vislist_words(words, v.region_count, bytes));
        EXPECT_TRUE(decode_eq_vislist_words(bytes, v.region_count, again).well_formed);
        EXPECT_EQ(again, words);
        return;
    }
    for (bool packed : {false, true}) {
        std::vector<uint8_t> bytes;
        encode_eq_vislist_bytes(words, v.region_count, bytes, packed);
        EXPECT_EQ(bytes.size(), eq_vislist_bytes_size(words, v.region_count, packed));
        EXPECT_TRUE(decode_eq_vislist_bytes(bytes, v.region_count, again).well_formed);
        EXPECT_EQ(again, words) << "packed=" << packed;
    }
}

INSTANTIATE_TEST_SUITE_P(Spec8_1, EqVislistKnownAnswer, ::testing::ValuesIn(vectors()),
                         [](const ::testing::TestParamInfo<Vector>& param_info) {
                             return "Vector" + std::to_string(param_info.param.number);
                         });

TEST(EqVislist, TableHasAll23Vectors)
{
    ASSERT_EQ(vectors().size(), 23u);
    for (size_t i = 0; i < vectors().size(); ++i)
        EXPECT_EQ(vectors()[i].number, static_cast<int>(i + 1));
}

TEST(EqVislist, Spec8_2ExampleEncodesPlainAndPackedByteExact)
{
    const BitSet row = row_of(8, {0, 1, 2, 5});
    std::vector<uint8_t> plain;
    std::vector<uint8_t> packed;
    encode_eq_vislist_bytes(row.words(), 8, plain, false);
    encode_eq_vislist_bytes(row.words(), 8, packed); // packed is the default
    EXPECT_EQ(plain, (std::vector<uint8_t>{0xC3, 0x02, 0xC1}));
    EXPECT_EQ(packed, (std::vector<uint8_t>{0x9A, 0xC1}));
    EXPECT_EQ(eq_vislist_bytes_size(row.words(), 8, false), 3u);
    EXPECT_EQ(eq_vislist_bytes_size(row.words(), 8), 2u);
}

TEST(EqVislist, Spec4_7RegionKnownAnswerListIsRegions0125)
{
    // The 0x22 fragment of §4.7 (8-byte header + 100-byte body); its VisList sits at 0x50.
    const std::vector<uint8_t> fragment = {
        0x64, 0x00, 0x00, 0x00, 0x22, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0x81, 0x01, 0x00, 0x00, //
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, //
        0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
        0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
        0x02, 0x00, 0x9a, 0xc1, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, //
        0x00, 0x00, 0xc8, 0x42, 0x00, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00,
    };
    ASSERT_EQ(fragment.size(), 8u + 100u);
    ASSERT_TRUE(fragment[0x0C] & 0x80) << "flags bit 7: byte form";
    const size_t range_count = size_t{fragment[0x50]} | (size_t{fragment[0x51]} << 8);
    ASSERT_EQ(range_count, 2u);
    const auto list = std::span<const uint8_t>(fragment).subspan(0x52, range_count);

    BitSet row(8);
    const EqVislistResult r = decode_eq_vislist_bytes(list, 8, row.words());
    EXPECT_TRUE(r.well_formed);
    EXPECT_EQ(r.consumed, 2u);
    EXPECT_EQ(positions(row.words()), (std::vector<size_t>{0, 1, 2, 5}));

    // And the writer produces exactly those list bytes back.
    std::vector<uint8_t> encoded;
    encode_eq_vislist_bytes(row.words(), 8, encoded);
    EXPECT_TRUE(std::equal(encoded.begin(), encoded.end(), list.begin(), list.end()));
}

TEST(EqVislist, ByteIsARunCodeNotABitmask)
{
    // 0x02 means "skip two regions", not "bit 1 of a mask" as in Quake's rows.
    BitSet eq(10);
    ASSERT_TRUE(decode_eq_vislist_bytes(std::vector<uint8_t>{0x02, 0xC3}, 10, eq.words()).well_formed);
    EXPECT_EQ(positions(eq.words()), (std::vector<size_t>{2, 3, 4}));
    BitSet quake(10);
    ASSERT_TRUE(decode_quake_rle(std::vector<uint8_t>{0x02, 0xC3}, 10, quake.words()).complete);
    EXPECT_EQ(positions(quake.words()), (std::vector<size_t>{1, 8, 9}));

    // With a zero byte: EQ reads 00 as a no-op, Quake as "a run of 2 zero BYTES" (16 leaves).
    BitSet eq2(24);
    ASSERT_TRUE(decode_eq_vislist_bytes(std::vector<uint8_t>{0x00, 0x02, 0xC3}, 24, eq2.words()).well_formed);
    EXPECT_EQ(positions(eq2.words()), (std::vector<size_t>{2, 3, 4}));
    BitSet quake2(24);
    ASSERT_TRUE(decode_quake_rle(std::vector<uint8_t>{0x00, 0x02, 0xC3}, 24, quake2.words()).complete);
    EXPECT_EQ(positions(quake2.words()), (std::vector<size_t>{16, 17, 22, 23}));
}

TEST(EqVislist, ShortCodesEndAt62AndU16CodesStartAt63)
{
    auto encode = [](size_t region_count, const std::vector<size_t>& set) {
        std::vector<uint8_t> out;
        encode_eq_vislist_bytes(row_of(region_count, set).words(), region_count, out, false);
        return out;
    };
    EXPECT_EQ(encode(100, {62}), (std::vector<uint8_t>{0x3E, 0xC1}));
    EXPECT_EQ(encode(100, {63}), (std::vector<uint8_t>{0x3F, 0x3F, 0x00, 0xC1}));
    std::vector<size_t> first62(62);
    for (size_t i = 0; i < 62; ++i)
        first62[i] = i;
    EXPECT_EQ(encode(100, first62), (std::vector<uint8_t>{0xFE}));
    first62.push_back(62);
    EXPECT_EQ(encode(100, first62), (std::vector<uint8_t>{0xFF, 0x3F, 0x00}));
}

TEST(EqVislist, RunsLongerThan65535AreSplit)
{
    // Skip 70000 = 65535 + 4465 (0x1171), then include 1.
    std::vector<uint8_t> out;
    encode_eq_vislist_bytes(row_of(70001, {70000}).words(), 70001, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{0x3F, 0xFF, 0xFF, 0x3F, 0x71, 0x11, 0xC1}));

    // Include 65536 = 65535 + 1, then include 65535 + 63: the remainder picks its own code.
    const std::vector<std::pair<size_t, std::vector<uint8_t>>> cases = {
        {65536, {0xFF, 0xFF, 0xFF, 0xC1}},
        {65598, {0xFF, 0xFF, 0xFF, 0xFF, 0x3F, 0x00}},
        {65535, {0xFF, 0xFF, 0xFF}},
    };
    for (const auto& [len, expected] : cases) {
        BitSet row(len + 10);
        bits::fill(row.words(), len);
        out.clear();
        encode_eq_vislist_bytes(row.words(), row.size(), out);
        EXPECT_EQ(out, expected) << len;
        BitSet back(row.size());
        ASSERT_TRUE(decode_eq_vislist_bytes(out, row.size(), back.words()).well_formed);
        EXPECT_EQ(back, row);
    }
}

TEST(EqVislist, PackingMergesOnlyRunsOf1To7AndNeverTheTrailingSkip)
{
    auto packed = [](size_t region_count, const std::vector<size_t>& set) {
        std::vector<uint8_t> out;
        encode_eq_vislist_bytes(row_of(region_count, set).words(), region_count, out);
        return out;
    };
    // Skip 7 + include 7 (vector 17's byte); include 7 + skip 7 + include 1 (vector 18).
    EXPECT_EQ(packed(20, {7, 8, 9, 10, 11, 12, 13}), (std::vector<uint8_t>{0x7F}));
    EXPECT_EQ(packed(20, {0, 1, 2, 3, 4, 5, 6, 14}), (std::vector<uint8_t>{0xBF, 0xC1}));
    // Skip 8 cannot pack: plain 08 then C1.
    EXPECT_EQ(packed(20, {8}), (std::vector<uint8_t>{0x08, 0xC1}));
    // Include 2 followed only by the trailing skip: no 0x80 form.
    EXPECT_EQ(packed(20, {0, 1}), (std::vector<uint8_t>{0xC2}));
    // Skip 1 + include 1, skip 1 + include 1: two 0x40 bytes.
    EXPECT_EQ(packed(20, {1, 3}), (std::vector<uint8_t>{0x49, 0x49}));
    // Include 1 + skip 1, then include 20 (too long to pair): 0x80 byte, then D4.
    std::vector<size_t> set = {0};
    for (size_t i = 2; i < 22; ++i)
        set.push_back(i);
    EXPECT_EQ(packed(30, set), (std::vector<uint8_t>{0x89, 0xD4}));
}

TEST(EqVislist, EmptyRowEncodesToNoBytes)
{
    BitSet row(50);
    std::vector<uint8_t> out;
    encode_eq_vislist_bytes(row.words(), 50, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(eq_vislist_bytes_size(row.words(), 50), 0u);
}

TEST(EqVislist, EncoderIgnoresPaddingBitsAndAppends)
{
    BitSet row(10);
    row.words()[0] = ~uint64_t{0}; // bits 10..63 are padding garbage
    std::vector<uint8_t> out = {0xAB};
    encode_eq_vislist_bytes(row.words(), 10, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{0xAB, 0xCA}));
    std::vector<uint8_t> words_out;
    ASSERT_TRUE(encode_eq_vislist_words(row.words(), 3, words_out));
    EXPECT_EQ(words_out, (std::vector<uint8_t>{0, 0, 1, 0, 2, 0}));
    EXPECT_EQ(eq_vislist_words_size(row.words(), 3), 6u);
}

TEST(EqVislist, ManyMaximalSkipsSaturateTheCursor)
{
    // 5000 x "skip 65535" then include 1: the cursor would pass 2^32; it must clamp at N.
    std::vector<uint8_t> in;
    for (int i = 0; i < 5000; ++i)
        in.insert(in.end(), {0x3F, 0xFF, 0xFF});
    in.push_back(0xC1);
    BitSet row(1000);
    const EqVislistResult r = decode_eq_vislist_bytes(in, 1000, row.words());
    EXPECT_TRUE(r.well_formed);
    EXPECT_EQ(r.consumed, in.size());
    EXPECT_EQ(row.count(), 0u);

    // The same with maximal includes: everything set, nothing past N.
    for (auto& b : in)
        if (b == 0x3F)
            b = 0xFF;
    ASSERT_TRUE(decode_eq_vislist_bytes(in, 1000, row.words()).well_formed);
    EXPECT_EQ(row.count(), 1000u);
}

TEST(EqVislistWords, DecodesExplicitRegionNumbersInAnyOrder)
{
    BitSet row(300);
    const EqVislistResult r =
        decode_eq_vislist_words(std::vector<uint8_t>{0x01, 0x01, 0x05, 0x00, 0x05, 0x00, 0x2C, 0x01}, 300, row.words());
    EXPECT_TRUE(r.well_formed);
    EXPECT_EQ(r.consumed, 8u);
    EXPECT_EQ(positions(row.words()), (std::vector<size_t>{5, 257})); // 300 (0x012C) >= N: dropped
}

TEST(EqVislistWords, OddTrailingByteIsMalformed)
{
    BitSet row(300);
    const EqVislistResult r = decode_eq_vislist_words(std::vector<uint8_t>{0x05, 0x00, 0x07}, 300, row.words());
    EXPECT_FALSE(r.well_formed);
    EXPECT_EQ(r.consumed, 2u);
    EXPECT_EQ(positions(row.words()), (std::vector<size_t>{5}));
}

TEST(EqVislistWords, EncoderWritesAscendingLittleEndianWords)
{
    std::vector<uint8_t> out;
    ASSERT_TRUE(encode_eq_vislist_words(row_of(300, {257, 5}).words(), 300, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{0x05, 0x00, 0x01, 0x01})); // vector 23's bytes
    EXPECT_EQ(eq_vislist_words_size(row_of(300, {257, 5}).words(), 300), 4u);
}

TEST(EqVislistWords, RegionsPast65535CannotBeWritten)
{
    std::vector<uint8_t> out = {0x11};
    EXPECT_TRUE(encode_eq_vislist_words(row_of(70000, {65535}).words(), 70000, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{0x11, 0xFF, 0xFF}));
    out = {0x11};
    EXPECT_FALSE(encode_eq_vislist_words(row_of(70000, {1, 65536}).words(), 70000, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{0x11})) << "nothing appended on failure";
}

} // namespace
} // namespace pvs
