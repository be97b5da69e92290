// Property tests for every PVS row codec: Quake RLE (quake-doom-hepvs.md §1.10), EverQuest
// VISLIST byte and word forms (eq-s3d-wld.md §4.4, §4.5, §8.2) and glVIS GL_PVS rows
// (quake-doom-hepvs.md §4.5). Seeded std::mt19937_64, so every failure reproduces.
//
// * Round trip: encode then decode gives the row back exactly, for empty, full, sparse, dense,
//   run-structured and single-bit rows, at sizes that are and are not multiples of 8 and 64,
//   and (EQ byte form) with skip and include runs longer than 65535.
// * Sizes: the size helpers are exact, the documented bounds hold, packed <= plain.
// * Hostile input: random bytes never crash a decoder (ASan/UBSan builds) and never set a bit
//   at or past the row size; the EQ byte decoder matches a naive reference decoder.
#include "visibility/bit_row.h"
#include "visibility/codec/eq_vislist.h"
#include "visibility/codec/glvis_rows.h"
#include "visibility/codec/quake_rle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace pvs {
namespace {

using Rng = std::mt19937_64;

size_t uniform(Rng& rng, size_t lo, size_t hi) // inclusive
{
    return std::uniform_int_distribution<size_t>(lo, hi)(rng);
}

// Row shapes the properties run over.
enum class Shape { empty, full, sparse, dense, runs, long_runs, first_bit, last_bit, first_and_last };

const char* shape_name(Shape s)
{
    switch (s) {
    case Shape::empty: return "empty";
    case Shape::full: return "full";
    case Shape::sparse: return "sparse";
    case Shape::dense: return "dense";
    case Shape::runs: return "runs";
    case Shape::long_runs: return "long_runs";
    case Shape::first_bit: return "first_bit";
    case Shape::last_bit: return "last_bit";
    case Shape::first_and_last: return "first_and_last";
    }
    return "?";
}

constexpr Shape all_shapes[] = {Shape::empty,  Shape::full,      Shape::sparse,
                                Shape::dense,  Shape::runs,      Shape::long_runs,
                                Shape::first_bit, Shape::last_bit, Shape::first_and_last};

// Alternating clear/set runs with lengths drawn from [1, max_run]; starts clear or set at random.
void fill_runs(BitSet& row, Rng& rng, size_t max_run)
{
    bool on = uniform(rng, 0, 1) == 1;
    for (size_t i = 0; i < row.size();) {
        const size_t len = std::min(row.size() - i, uniform(rng, 1, max_run));
        if (on)
            for (size_t j = i; j < i + len; ++j)
                row.set(j);
        i += len;
        on = !on;
    }
}

BitSet make_row(size_t n, Shape shape, Rng& rng)
{
    BitSet row(n);
    auto with_probability = [&](double p) {
        std::bernoulli_distribution bit(p);
        for (size_t i = 0; i < n; ++i)
            if (bit(rng))
                row.set(i);
    };
    switch (shape) {
    case Shape::empty: break;
    case Shape::full: bits::fill(row.words(), n); break;
    case Shape::sparse: with_probability(0.01); break;
    case Shape::dense: with_probability(0.90); break;
    case Shape::runs: fill_runs(row, rng, 20); break;           // lots of 1-7 runs: packing
    case Shape::long_runs: fill_runs(row, rng, 100000); break;  // u16 codes and splits
    case Shape::first_bit:
        if (n > 0)
            row.set(0);
        break;
    case Shape::last_bit:
        if (n > 0)
            row.set(n - 1);
        break;
    case Shape::first_and_last:
        if (n > 0) {
            row.set(0);
            row.set(n - 1);
        }
        break;
    }
    return row;
}

// Sizes: tiny, byte and word edges, and not multiples of 8 or 64.
const std::vector<size_t>& sizes()
{
    static const std::vector<size_t> s = {0, 1, 2, 7, 8, 9, 63, 64, 65, 100, 127, 128, 129, 1000, 1001, 4097, 2905};
    return s;
}

bool padding_is_clear(std::span<const uint64_t> words, size_t n)
{
    if (words.size() != bits::words_for(n))
        return false;
    return n % 64 == 0 || (words.back() >> (n % 64)) == 0;
}

// A copy of `row` with every padding bit set: encoders must not look at them.
std::vector<uint64_t> with_dirty_padding(const BitSet& row)
{
    std::vector<uint64_t> words(row.words().begin(), row.words().end());
    if (row.size() % 64 != 0)
        words.back() |= ~uint64_t{0} << (row.size() % 64);
    return words;
}

// ---- EverQuest byte form -------------------------------------------------------------------

void check_eq_bytes_round_trip(const BitSet& row, const std::string& what)
{
    SCOPED_TRACE(what);
    const size_t n = row.size();
    std::vector<uint8_t> plain;
    std::vector<uint8_t> packed;
    encode_eq_vislist_bytes(row.words(), n, plain, false);
    encode_eq_vislist_bytes(row.words(), n, packed, true);
    EXPECT_EQ(plain.size(), eq_vislist_bytes_size(row.words(), n, false));
    EXPECT_EQ(packed.size(), eq_vislist_bytes_size(row.words(), n, true));
    EXPECT_LE(packed.size(), plain.size());
    EXPECT_LE(plain.size(), eq_vislist_bytes_bound(n));
    if (row.count() == 0) {
        EXPECT_TRUE(plain.empty());
    }

    const std::vector<uint64_t> dirty = with_dirty_padding(row);
    std::vector<uint8_t> from_dirty;
    encode_eq_vislist_bytes(dirty, n, from_dirty);
    EXPECT_EQ(from_dirty, packed);

    for (const auto* bytes : {&plain, &packed}) {
        BitSet back(n);
        bits::fill(back.words(), n); // garbage the decoder must overwrite
        const EqVislistResult r = decode_eq_vislist_bytes(*bytes, n, back.words());
        EXPECT_TRUE(r.well_formed);
        EXPECT_EQ(r.consumed, bytes->size());
        EXPECT_EQ(back, row) << (bytes == &plain ? "plain" : "packed");
    }
}

TEST(CodecProperties, EqBytesRoundTripsEveryShapeAndSize)
{
    Rng rng(0x5eed0001);
    for (size_t n : sizes())
        for (Shape shape : all_shapes)
            for (int rep = 0; rep < 3; ++rep)
                check_eq_bytes_round_trip(make_row(n, shape, rng),
                                          "n=" + std::to_string(n) + " " + shape_name(shape) + " #" + std::to_string(rep));
}

TEST(CodecProperties, EqBytesRoundTripsRandomSizes)
{
    Rng rng(0x5eed0002);
    for (int rep = 0; rep < 300; ++rep) {
        const size_t n = uniform(rng, 0, 3000);
        const Shape shape = all_shapes[uniform(rng, 0, std::size(all_shapes) - 1)];
        check_eq_bytes_round_trip(make_row(n, shape, rng), "n=" + std::to_string(n) + " " + shape_name(shape));
    }
}

TEST(CodecProperties, EqBytesRoundTripsRunsLongerThan65535)
{
    Rng rng(0x5eed0003);
    for (int rep = 0; rep < 6; ++rep) {
        const size_t n = uniform(rng, 195000, 205000);
        // Skip > 65535, include > 65535, a short gap, another include > 65535, sparse tail.
        BitSet row(n);
        const size_t skip = uniform(rng, 65536, 70000);
        const size_t include = uniform(rng, 65536, 66000);
        const size_t gap = uniform(rng, 1, 10);
        const size_t include2 = uniform(rng, 65536 + 62, 65536 + 70);
        size_t i = skip;
        for (size_t j = 0; j < include; ++j)
            row.set(i++);
        i += gap;
        for (size_t j = 0; j < include2 && i < n; ++j)
            row.set(i++);
        for (; i < n; i += uniform(rng, 1, 5000))
            row.set(i);
        check_eq_bytes_round_trip(row, "long runs, n=" + std::to_string(n));

        // The complement: include > 65535 first, skips > 65535 inside.
        BitSet flipped(n);
        for (size_t k = 0; k < n; ++k)
            if (!row.test(k))
                flipped.set(k);
        check_eq_bytes_round_trip(flipped, "complement, n=" + std::to_string(n));
    }
    for (Shape shape : {Shape::full, Shape::long_runs, Shape::first_and_last, Shape::sparse, Shape::empty})
        check_eq_bytes_round_trip(make_row(200000, shape, rng), std::string("n=200000 ") + shape_name(shape));
}

// ---- EverQuest word form -------------------------------------------------------------------

void check_eq_words_round_trip(const BitSet& row, const std::string& what)
{
    SCOPED_TRACE(what);
    const size_t n = row.size();
    std::vector<uint8_t> bytes;
    ASSERT_TRUE(encode_eq_vislist_words(with_dirty_padding(row), n, bytes));
    EXPECT_EQ(bytes.size(), 2 * row.count());
    EXPECT_EQ(bytes.size(), eq_vislist_words_size(row.words(), n));
    BitSet back(n);
    bits::fill(back.words(), n);
    const EqVislistResult r = decode_eq_vislist_words(bytes, n, back.words());
    EXPECT_TRUE(r.well_formed);
    EXPECT_EQ(r.consumed, bytes.size());
    EXPECT_EQ(back, row);
}

TEST(CodecProperties, EqWordsRoundTripsEveryShapeAndSize)
{
    Rng rng(0x5eed0004);
    for (size_t n : sizes())
        for (Shape shape : all_shapes)
            for (int rep = 0; rep < 2; ++rep)
                check_eq_words_round_trip(make_row(n, shape, rng), "n=" + std::to_string(n) + " " + shape_name(shape));
    // The largest size whose every region a u16 can name.
    for (Shape shape : {Shape::sparse, Shape::last_bit, Shape::full})
        check_eq_words_round_trip(make_row(65536, shape, rng), std::string("n=65536 ") + shape_name(shape));
}

TEST(CodecProperties, EqWordsRefusesRegionsAbove65535)
{
    Rng rng(0x5eed0005);
    for (int rep = 0; rep < 20; ++rep) {
        const size_t n = uniform(rng, 65537, 100000);
        BitSet row = make_row(n, Shape::sparse, rng);
        row.set(uniform(rng, 65536, n - 1));
        std::vector<uint8_t> bytes;
        EXPECT_FALSE(encode_eq_vislist_words(row.words(), n, bytes));
        EXPECT_TRUE(bytes.empty());
    }
}

// ---- glVIS rows ----------------------------------------------------------------------------

TEST(CodecProperties, GlvisLumpRoundTripsEveryRow)
{
    Rng rng(0x5eed0006);
    for (size_t n : {size_t{0}, size_t{1}, size_t{7}, size_t{8}, size_t{9}, size_t{63}, size_t{64}, size_t{65},
                     size_t{100}, size_t{129}, size_t{300}}) {
        const size_t row_words = bits::words_for(n);
        std::vector<BitSet> rows;
        std::vector<uint64_t> flat;
        for (size_t i = 0; i < n; ++i) {
            rows.push_back(make_row(n, all_shapes[uniform(rng, 0, std::size(all_shapes) - 1)], rng));
            const std::vector<uint64_t> dirty = with_dirty_padding(rows.back());
            flat.insert(flat.end(), dirty.begin(), dirty.end());
        }
        ASSERT_EQ(flat.size(), n * row_words);
        std::vector<uint8_t> lump;
        encode_glvis_rows(flat, n, lump);
        ASSERT_EQ(lump.size(), glvis_lump_size(n));
        for (size_t i = 0; i < n; ++i) {
            BitSet back(n);
            bits::fill(back.words(), n);
            const GlvisRowStatus status = decode_glvis_row(lump, n, i, back.words());
            ASSERT_EQ(status, GlvisRowStatus::decoded) << "n=" << n << " row " << i;
            EXPECT_EQ(back, rows[i]) << "n=" << n << " row " << i;
        }
    }
}

// ---- Quake RLE -----------------------------------------------------------------------------

void check_quake_round_trip(const BitSet& row, const std::string& what)
{
    SCOPED_TRACE(what);
    const size_t n = row.size();
    std::vector<uint8_t> bytes;
    encode_quake_rle(with_dirty_padding(row), n, bytes);
    EXPECT_LE(bytes.size(), quake_rle_bound(n));
    BitSet back(n);
    bits::fill(back.words(), n);
    const QuakeRleResult r = decode_quake_rle(bytes, n, back.words());
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.consumed, bytes.size());
    EXPECT_EQ(back, row);
}

TEST(CodecProperties, QuakeRleRoundTripsEveryShapeAndSize)
{
    Rng rng(0x5eed0007);
    for (size_t n : sizes())
        for (Shape shape : all_shapes)
            for (int rep = 0; rep < 3; ++rep)
                check_quake_round_trip(make_row(n, shape, rng), "n=" + std::to_string(n) + " " + shape_name(shape));
    for (int rep = 0; rep < 200; ++rep) {
        const size_t n = uniform(rng, 0, 5000);
        const Shape shape = all_shapes[uniform(rng, 0, std::size(all_shapes) - 1)];
        check_quake_round_trip(make_row(n, shape, rng), "n=" + std::to_string(n) + " " + shape_name(shape));
    }
}

// ---- Hostile input -------------------------------------------------------------------------

// Random bytes, biased toward the bytes that carry operands or runs in some codec.
std::vector<uint8_t> hostile_bytes(Rng& rng, size_t max_len)
{
    static constexpr uint8_t special[] = {0x00, 0x3F, 0xFF, 0xFE, 0xC0, 0x40, 0x80, 0x01};
    std::vector<uint8_t> out(uniform(rng, 0, max_len));
    for (auto& b : out)
        b = uniform(rng, 0, 3) == 0 ? special[uniform(rng, 0, std::size(special) - 1)]
                                    : static_cast<uint8_t>(uniform(rng, 0, 255));
    return out;
}

size_t hostile_size(Rng& rng)
{
    switch (uniform(rng, 0, 3)) {
    case 0: return uniform(rng, 0, 16);
    case 1: return uniform(rng, 0, 300);
    case 2: return 64 * uniform(rng, 0, 8);
    default: return uniform(rng, 0, 70000);
    }
}

// Straightforward byte-form decoder: a 64-bit cursor, one position at a time (§4.4 table).
std::vector<size_t> reference_eq_bytes(const std::vector<uint8_t>& in, size_t n, bool& well_formed)
{
    std::vector<size_t> out;
    uint64_t r = 0;
    auto include = [&](uint64_t k) {
        const uint64_t end = r + k;
        for (; r < end && r < n; ++r)
            out.push_back(static_cast<size_t>(r));
        r = end;
    };
    well_formed = true;
    for (size_t pos = 0; pos < in.size();) {
        const unsigned b = in[pos++];
        if (b == 0x3F || b == 0xFF) {
            if (in.size() - pos < 2) {
                well_formed = false;
                break;
            }
            const uint64_t w = in[pos] | (uint64_t{in[pos + 1]} << 8);
            pos += 2;
            if (b == 0x3F)
                r += w;
            else
                include(w);
        } else if (b < 0x40) {
            r += b;
        } else if (b < 0x80) {
            r += (b >> 3) & 7;
            include(b & 7);
        } else if (b < 0xC0) {
            include((b >> 3) & 7);
            r += b & 7;
        } else {
            include(b - 0xC0);
        }
    }
    return out;
}

std::vector<size_t> positions(std::span<const uint64_t> words)
{
    std::vector<size_t> out;
    bits::for_each_set(words, [&](size_t i) { out.push_back(i); });
    return out;
}

TEST(CodecProperties, HostileBytesNeverCrashAnyDecoderNorSetBitsPastTheRow)
{
    Rng rng(0x5eed0008);
    for (int rep = 0; rep < 3000; ++rep) {
        const size_t n = hostile_size(rng);
        const std::vector<uint8_t> in = hostile_bytes(rng, rep % 10 == 0 ? 2000 : 40);
        SCOPED_TRACE("rep " + std::to_string(rep) + " n=" + std::to_string(n) + " len=" + std::to_string(in.size()));
        // Exactly words_for(n) words, so ASan sees any write past the row; pre-filled with garbage.
        std::vector<uint64_t> out(bits::words_for(n), ~uint64_t{0});

        const EqVislistResult eq = decode_eq_vislist_bytes(in, n, out);
        EXPECT_LE(eq.consumed, in.size());
        EXPECT_EQ(eq.well_formed, eq.consumed == in.size());
        EXPECT_TRUE(padding_is_clear(out, n));
        bool ref_well_formed = false;
        EXPECT_EQ(positions(out), reference_eq_bytes(in, n, ref_well_formed));
        EXPECT_EQ(eq.well_formed, ref_well_formed);

        std::fill(out.begin(), out.end(), ~uint64_t{0});
        const EqVislistResult words = decode_eq_vislist_words(in, n, out);
        EXPECT_EQ(words.consumed, in.size() & ~size_t{1});
        EXPECT_EQ(words.well_formed, in.size() % 2 == 0);
        EXPECT_TRUE(padding_is_clear(out, n));
        EXPECT_LE(bits::count(out), in.size() / 2);

        std::fill(out.begin(), out.end(), ~uint64_t{0});
        const QuakeRleResult quake = decode_quake_rle(in, n, out);
        EXPECT_LE(quake.consumed, in.size());
        EXPECT_TRUE(padding_is_clear(out, n));

        std::fill(out.begin(), out.end(), ~uint64_t{0});
        const size_t row = uniform(rng, 0, n + 2);
        const GlvisRowStatus gl = decode_glvis_row(in, n, row, out);
        EXPECT_TRUE(padding_is_clear(out, n));
        if (gl != GlvisRowStatus::decoded) {
            EXPECT_EQ(bits::count(out), n) << "missing rows read as all visible";
        } else {
            EXPECT_LE((row + 1) * glvis_row_bytes(n), in.size());
        }
    }
}

TEST(CodecProperties, HostileMaximalCodesKeepTheEqCursorInRange)
{
    // Long streams of FF FF FF / 3F FF FF codes: the cursor reaches 2^32 and beyond.
    Rng rng(0x5eed0009);
    for (int rep = 0; rep < 20; ++rep) {
        std::vector<uint8_t> in;
        const size_t codes = uniform(rng, 1000, 70000);
        for (size_t i = 0; i < codes; ++i) {
            in.push_back(uniform(rng, 0, 1) != 0 ? uint8_t{0x3F} : uint8_t{0xFF});
            in.push_back(0xFF);
            in.push_back(0xFF);
        }
        in.push_back(static_cast<uint8_t>(uniform(rng, 0, 255)));
        const size_t n = hostile_size(rng);
        std::vector<uint64_t> out(bits::words_for(n), ~uint64_t{0});
        decode_eq_vislist_bytes(in, n, out);
        EXPECT_TRUE(padding_is_clear(out, n));
    }
}

} // namespace
} // namespace pvs
