// Quake PVS RLE (../shared/formats/quake-doom-hepvs.md §1.10): decoding rules from the spec,
// hand-made vectors, and the encoder's exact output form.
#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"

#include <gtest/gtest.h>

#include <random>

namespace pvs {
namespace {

std::vector<uint8_t> decode_to_bytes(const std::vector<uint8_t>& in, size_t bit_count, QuakeRleResult* result = nullptr)
{
    std::vector<uint64_t> words(bits::words_for(bit_count));
    const QuakeRleResult r = decode_quake_rle(in, bit_count, words);
    if (result)
        *result = r;
    std::vector<uint8_t> bytes(bits::bytes_for(bit_count));
    bits::to_bytes(words, bit_count, bytes);
    return bytes;
}

TEST(QuakeRle, NonZeroBytesAreCopiedAndZeroIsFollowedByAByteCount)
{
    // 0x0F, then a run of 3 zero bytes, then 0x80: 5 bytes, 40 bits.
    QuakeRleResult r;
    EXPECT_EQ(decode_to_bytes({0x0F, 0x00, 0x03, 0x80}, 40, &r), (std::vector<uint8_t>{0x0F, 0, 0, 0, 0x80}));
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.consumed, 4u);
}

TEST(QuakeRle, ZeroCountIsBytesNotBits)
{
    // A count of 2 must skip 16 bits: bit 16 is then the first bit of the 0x01 byte.
    std::vector<uint64_t> words(1);
    ASSERT_TRUE(decode_quake_rle(std::vector<uint8_t>{0x00, 0x02, 0x01}, 24, words).complete);
    EXPECT_EQ(words[0], uint64_t{1} << 16);
}

TEST(QuakeRle, RunPastTheRowIsClampedAndTheRestOfTheInputIsNotRead)
{
    QuakeRleResult r;
    EXPECT_EQ(decode_to_bytes({0x01, 0x00, 0xFF, 0x77}, 24, &r), (std::vector<uint8_t>{0x01, 0, 0}));
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.consumed, 3u);
}

TEST(QuakeRle, TruncatedInputIsReportedIncomplete)
{
    QuakeRleResult r;
    decode_to_bytes({0x01, 0x00}, 24, &r); // zero with no count byte
    EXPECT_FALSE(r.complete);
    decode_to_bytes({0x01}, 24, &r); // ends before the row is full
    EXPECT_FALSE(r.complete);
    decode_to_bytes({}, 8, &r);
    EXPECT_FALSE(r.complete);
}

TEST(QuakeRle, PaddingBitsPastTheRowAreDropped)
{
    std::vector<uint64_t> words(1);
    ASSERT_TRUE(decode_quake_rle(std::vector<uint8_t>{0xFF, 0xFF}, 11, words).complete);
    EXPECT_EQ(words[0], 0x7FFu);
}

TEST(QuakeRle, EncoderSplitsZeroRunsAt255AndNeverRunsPastTheRow)
{
    // 600 zero bytes then one 0x02 byte: runs of 255, 255, 90, then the byte.
    const size_t bit_count = 601 * 8;
    std::vector<uint64_t> row(bits::words_for(bit_count), 0);
    bits::set(row, 600 * 8 + 1);
    std::vector<uint8_t> out;
    encode_quake_rle(row, bit_count, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{0x00, 255, 0x00, 255, 0x00, 90, 0x02}));
    std::vector<uint8_t> tail;
    std::vector<uint64_t> zeros(1, 0);
    encode_quake_rle(zeros, 20, tail);
    EXPECT_EQ(tail, (std::vector<uint8_t>{0x00, 3}));
    EXPECT_LE(out.size(), quake_rle_bound(bit_count));
}

// One bit read in place is the bit the whole decode gives, for every bit of random rows (sparse
// ones have zero runs, some past 255 bytes), of rows cut short, and of a run clamped at the row.
TEST(QuakeRle, OneBitReadInPlaceIsTheDecodedBit)
{
    std::mt19937 rng(3);
    const size_t n = 4100;
    for (double density : {0.0005, 0.02, 0.5}) {
        std::vector<uint64_t> row(bits::words_for(n), 0);
        std::bernoulli_distribution pick(density);
        for (size_t i = 0; i < n; ++i)
            if (pick(rng))
                bits::set(row, i);
        std::vector<uint8_t> encoded;
        encode_quake_rle(row, n, encoded);
        const std::vector<uint8_t> clamped{0x81, 0x00, 0xff, 0x00, 0xff, 0x00, 0xff, 0x44};
        for (const std::vector<uint8_t>& input :
             {encoded, std::vector<uint8_t>(encoded.begin(), encoded.begin() + long(encoded.size() / 2)), clamped}) {
            std::vector<uint64_t> decoded(bits::words_for(n));
            decode_quake_rle(input, n, decoded);
            for (size_t bit = 0; bit < n; ++bit)
                ASSERT_EQ(quake_rle_test(input, n, bit), bits::test(decoded, bit)) << density << " bit " << bit;
            EXPECT_FALSE(quake_rle_test(input, n, n)); // past the row
        }
    }
}

} // namespace
} // namespace pvs
