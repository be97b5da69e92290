// PVS storage: dense and compressed storage decode to the same rows, missing rows read as all
// visible, identical rows are stored once, the automatic choice follows the documented rule,
// and the row cursor returns the current region's row.
#include "visibility/bit_row.h"
#include "visibility/pvs.h"

#include <gtest/gtest.h>

#include <random>

namespace pvs {
namespace {

// A reproducible PVS: row r sees r, its neighbours, and a few random regions; every 7th row is missing.
std::vector<BitSet> random_rows(uint32_t n, double density, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::bernoulli_distribution pick(density);
    std::vector<BitSet> rows(n, BitSet(n));
    for (uint32_t r = 0; r < n; ++r) {
        rows[r].set(r);
        if (r + 1 < n)
            rows[r].set(r + 1);
        for (uint32_t c = 0; c < n; ++c)
            if (pick(rng))
                rows[r].set(c);
    }
    return rows;
}

Pvs build(const std::vector<BitSet>& rows, Pvs::StoragePolicy policy, bool with_missing)
{
    const auto n = static_cast<uint32_t>(rows.size());
    return Pvs::build(n, [&](uint32_t r, std::span<uint64_t> out) {
        if (with_missing && r % 7 == 3)
            return false;
        std::copy(rows[r].words().begin(), rows[r].words().end(), out.begin());
        return true;
    }, policy);
}

TEST(PvsStorage, DenseAndCompressedDecodeTheSameRows)
{
    const auto rows = random_rows(300, 0.05, 1);
    const Pvs dense = build(rows, Pvs::StoragePolicy::Dense, true);
    const Pvs compressed = build(rows, Pvs::StoragePolicy::Compressed, true);
    ASSERT_EQ(dense.storage(), Pvs::Storage::Dense);
    ASSERT_EQ(compressed.storage(), Pvs::Storage::Compressed);
    EXPECT_EQ(dense.missing_row_count(), compressed.missing_row_count());
    std::vector<uint64_t> a(dense.words_per_row()), b(compressed.words_per_row());
    for (uint32_t r = 0; r < 300; ++r) {
        dense.decode_row(r, a);
        compressed.decode_row(r, b);
        ASSERT_EQ(a, b) << r;
        if (r % 7 == 3) {
            EXPECT_TRUE(dense.row_missing(r));
            EXPECT_EQ(bits::count(a), 300u); // missing = all visible
        } else {
            ASSERT_TRUE(std::equal(a.begin(), a.end(), rows[r].words().begin()));
        }
    }
}

// visible(from, to) reads one bit of a compressed row in place: it must be the decoded row's bit,
// in both codecs (sparse rows take Quake RLE, dense runs bit runs) and for missing rows.
TEST(PvsStorage, OneBitIsTheDecodedRowsBitInEitherStorage)
{
    std::vector<BitSet> rows = random_rows(300, 0.03, 4);
    for (uint32_t r = 0; r < 100; ++r) // dense rows in long runs
        for (uint32_t c = r; c < 300; c += (c % 50 == 49) ? 30 : 1)
            rows[r].set(c);
    for (const Pvs::StoragePolicy policy : {Pvs::StoragePolicy::Dense, Pvs::StoragePolicy::Compressed}) {
        const Pvs pvs = build(rows, policy, true);
        std::vector<uint64_t> row(pvs.words_per_row());
        for (uint32_t r = 0; r < 300; ++r) {
            pvs.decode_row(r, row);
            for (uint32_t c = 0; c < 300; ++c)
                ASSERT_EQ(pvs.visible(r, c), bits::test(row, c)) << r << " " << c;
            EXPECT_FALSE(pvs.visible(r, 300)); // past the last region
        }
    }
}

TEST(PvsStorage, IdenticalRowsAreStoredOnce)
{
    std::vector<BitSet> same(4000, BitSet(4000));
    for (BitSet& row : same)
        row.set(17);
    std::vector<BitSet> distinct = same;
    for (uint32_t r = 0; r < 4000; ++r)
        distinct[r].set(r);
    const Pvs shared = build(same, Pvs::StoragePolicy::Compressed, false);
    const Pvs unshared = build(distinct, Pvs::StoragePolicy::Compressed, false);
    EXPECT_LT(shared.memory_bytes() + 4000 * 5, unshared.memory_bytes());
    EXPECT_TRUE(shared.visible(3999, 17));
    EXPECT_FALSE(shared.visible(3999, 3999));
}

TEST(PvsStorage, AutoChoosesDenseForSmallAndCompressedForLargeSparseSets)
{
    EXPECT_EQ(build(random_rows(200, 0.1, 2), Pvs::StoragePolicy::Auto, false).storage(), Pvs::Storage::Dense);
    // 6000 regions: a dense matrix is 4.5 MB; sparse rows compress to a few bytes each.
    const Pvs large = build(random_rows(6000, 0.0005, 3), Pvs::StoragePolicy::Auto, false);
    EXPECT_EQ(large.storage(), Pvs::Storage::Compressed);
    EXPECT_LT(large.memory_bytes(), 6000u * 6000u / 8u / 4u);
}

// A dense PVS holds its matrix and nothing of the compressed rows it was chosen from (it once
// kept their capacity: a 33 626-region zone took 261 MiB for a 135 MiB matrix).
TEST(PvsStorage, ADensePvsHoldsOnlyItsMatrix)
{
    const uint32_t n = 3000;
    const Pvs dense = build(random_rows(n, 0.7, 4), Pvs::StoragePolicy::Auto, false);
    ASSERT_EQ(dense.storage(), Pvs::Storage::Dense);
    const size_t matrix = size_t(n) * dense.words_per_row() * sizeof(uint64_t);
    EXPECT_GE(dense.memory_bytes(), matrix);
    EXPECT_LT(dense.memory_bytes(), matrix + 4096);
}

TEST(PvsStorage, CursorReturnsTheRowOfTheRegionAskedFor)
{
    const auto rows = random_rows(500, 0.02, 4);
    for (auto policy : {Pvs::StoragePolicy::Dense, Pvs::StoragePolicy::Compressed}) {
        const Pvs pvs = build(rows, policy, false);
        PvsRowCursor cursor(pvs);
        for (uint32_t r : {5u, 5u, 499u, 0u, 5u}) {
            const std::span<const uint64_t> row = cursor.row(r);
            ASSERT_TRUE(std::equal(row.begin(), row.end(), rows[r].words().begin())) << r;
        }
    }
}

TEST(PvsStorage, EmptyPvsHasNoRows)
{
    const Pvs pvs = Pvs::build(0, [](uint32_t, std::span<uint64_t>) { return true; });
    EXPECT_EQ(pvs.region_count(), 0u);
    EXPECT_EQ(pvs.words_per_row(), 0u);
}

} // namespace
} // namespace pvs
