// Quake 2 maps (wld/quake2/): the IBSP 38 reader's clusters and visibility rows on maps compiled
// by ericw-tools (qbsp -q2bsp, then vis, in the project's test data), and the PHS made from the
// PVS. Known answers from the tools: the cluster count of each map's .prt; ericw vis's own PHS
// rows, which the EricwTools rule must rebuild byte for byte from its own PVS rows; the Quake2
// rule against a plain triple loop written here. Bad files: clear errors, never a crash.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"
#include "visibility/file_error.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/phs.h"


#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace pvs::quake2 {
namespace {

const char* const kMaps[] = {"q2_areaportals", "q2_liquids", "q2_tjunc_matrix"};

uint32_t prt_cluster_count(const std::string& path)
{
    std::ifstream in(path);
    std::string tag;
    uint32_t clusters = 0;
    in >> tag >> clusters;
    EXPECT_EQ(tag, "PRT1");
    return clusters;
}

class Ibsp38Map : public ::testing::TestWithParam<const char*> {};

TEST_P(Ibsp38Map, ClustersAreThePortalFilesAndEveryRowSeesItself)
{
    const std::string stem = std::string("modern-quake/q2/") + GetParam();
    SHARED_DATA_OR_SKIP(vised, stem + ".ericw-vis.bsp");
    SHARED_DATA_OR_SKIP(unvised, stem + ".bsp");
    SHARED_DATA_OR_SKIP(prt, stem + ".prt");
    const Ibsp38File f = read_ibsp38(test::read_bytes(vised), vised);
    EXPECT_EQ(f.clusters, prt_cluster_count(prt));
    int32_t max_cluster = -1;
    for (const Q2Leaf& leaf : f.leaves)
        max_cluster = std::max<int32_t>(max_cluster, leaf.cluster);
    EXPECT_EQ(uint32_t(max_cluster + 1), f.clusters);
    const size_t words = bits::words_for(f.clusters);
    for (uint32_t c = 0; c < f.clusters; ++c)
        EXPECT_TRUE(bits::test(std::span<const uint64_t>(f.pvs_rows.data() + c * words, words), c)) << c;
    const Ibsp38File before = read_ibsp38(test::read_bytes(unvised), unvised);
    EXPECT_EQ(before.clusters, 0u) << "qbsp leaves the visibility lump empty";
    EXPECT_EQ(before.leaves.size(), f.leaves.size());
}

TEST_P(Ibsp38Map, EricwRuleRebuildsTheFilesPhsByteForByte)
{
    const std::string stem = std::string("modern-quake/q2/") + GetParam();
    SHARED_DATA_OR_SKIP(vised, stem + ".ericw-vis.bsp");
    const std::vector<uint8_t> bytes = test::read_bytes(vised);
    const Ibsp38File f = read_ibsp38(bytes, vised);
    ASSERT_GT(f.clusters, 0u);
    const auto stored = [&](uint32_t offset, uint32_t length) {
        const auto at = bytes.begin() + std::ptrdiff_t(f.lumps[kQ2LumpVisibility].offset + offset);
        return std::vector<uint8_t>(at, at + length);
    };
    const std::vector<uint64_t> phs = compute_phs(f.pvs_rows, f.clusters, PhsRule::EricwTools);
    const size_t words = bits::words_for(f.clusters);
    std::vector<uint8_t> encoded;
    for (uint32_t c = 0; c < f.clusters; ++c) {
        encoded.clear();
        encode_quake_rle(std::span<const uint64_t>(phs.data() + c * words, words), f.clusters, encoded);
        EXPECT_EQ(encoded, stored(f.phs_offsets[c], f.phs_lengths[c])) << GetParam() << " cluster " << c;
        encoded.clear();
        encode_quake_rle(std::span<const uint64_t>(f.pvs_rows.data() + c * words, words), f.clusters, encoded);
        EXPECT_EQ(encoded, stored(f.pvs_offsets[c], f.pvs_lengths[c])) << "the PVS rows re-encode to their own bytes";
    }
}

// The Quake2 rule against the definition, bit by bit: c hears h when some s in PVS(c) sees h.
TEST_P(Ibsp38Map, Quake2RuleIsTheUnionOfTheSeenClustersRowsAndHoldsEricws)
{
    const std::string stem = std::string("modern-quake/q2/") + GetParam();
    SHARED_DATA_OR_SKIP(vised, stem + ".ericw-vis.bsp");
    const Ibsp38File f = read_ibsp38(test::read_bytes(vised), vised);
    const size_t n = f.clusters, words = bits::words_for(f.clusters);
    auto sees = [&](size_t a, size_t b) { return (f.pvs_rows[a * words + b / 64] >> (b % 64)) & 1u; };
    const std::vector<uint64_t> phs = compute_phs(f.pvs_rows, f.clusters, PhsRule::Quake2);
    size_t beyond_ericw = 0;
    for (size_t c = 0; c < n; ++c)
        for (size_t h = 0; h < n; ++h) {
            bool hears = false;
            for (size_t s = 0; s < n && !hears; ++s)
                hears = sees(c, s) && sees(s, h);
            const bool got = (phs[c * words + h / 64] >> (h % 64)) & 1u;
            ASSERT_EQ(got, hears) << "cluster " << c << " hearing " << h;
            const bool ericw = (f.phs_rows[c * words + h / 64] >> (h % 64)) & 1u;
            ASSERT_TRUE(got || !ericw) << "ericw's PHS is within Quake 2's";
            beyond_ericw += got && !ericw ? 1 : 0;
            if (got && !ericw) {
                EXPECT_GE(h, (((n + 7) / 8) / 8) * 64) << "ericw only drops bits of the last, partial word";
            }
        }
    if (std::string(GetParam()) == "q2_tjunc_matrix") {
        EXPECT_GT(beyond_ericw, 0u) << "96 clusters: ericw leaves out bits 64..95 of the seen rows";
    }
}

INSTANTIATE_TEST_SUITE_P(SharedData, Ibsp38Map, ::testing::ValuesIn(kMaps));

// ---- Bad input ----

void expect_error(const std::vector<uint8_t>& bytes, uint64_t offset, const std::string& text)
{
    try {
        (void)read_ibsp38(bytes, "x.bsp");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_EQ(e.offset(), offset) << e.what();
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

TEST(Ibsp38BadInput, HeadersThatAreNotQuake2AreNamed)
{
    std::vector<uint8_t> q3(8 + 8 * 19, 0);
    std::memcpy(q3.data(), "IBSP", 4);
    q3[4] = 46;
    expect_error(q3, 4, "a Quake 3 IBSP (version 46)");
    EXPECT_FALSE(looks_like_ibsp38(q3));
    q3[4] = 38;
    EXPECT_TRUE(looks_like_ibsp38(q3));
    std::vector<uint8_t> bsp29(200, 0);
    bsp29[0] = 29;
    expect_error(bsp29, 0, "not an IBSP file");
    expect_error(std::vector<uint8_t>(10, 0), 0, "runs past the end");
}

TEST(Ibsp38BadInput, LumpsClusterCountsAndOffsetsOutsideTheirRoomAreRefused)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_areaportals.ericw-vis.bsp");
    const std::vector<uint8_t> good = test::read_bytes(path);
    uint32_t vis_offset;
    std::memcpy(&vis_offset, good.data() + 8 + 8 * kQ2LumpVisibility, 4);

    std::vector<uint8_t> bad = good;
    const uint32_t huge = 0x7fffffff;
    std::memcpy(bad.data() + 8 + 8 * kQ2LumpLeafs + 4, &huge, 4);
    expect_error(bad, 8 + 8 * kQ2LumpLeafs, "the leafs lump");

    bad = good;
    const int32_t too_many = 1000;
    std::memcpy(bad.data() + vis_offset, &too_many, 4);
    expect_error(bad, vis_offset, "does not fit the visibility lump");

    bad = good;
    std::memcpy(bad.data() + vis_offset + 4, &huge, 4); // cluster 0's PVS offset
    expect_error(bad, vis_offset + 4, "lies outside the visibility lump");

    bad = good;
    const int32_t fewer = 2; // leaves still name clusters up to 7
    std::memcpy(bad.data() + vis_offset, &fewer, 4);
    EXPECT_THROW((void)read_ibsp38(bad, "x.bsp"), FileError);
}

// Every prefix and every single-byte change of a real map: an answer or a FileError.
TEST(Ibsp38BadInput, TruncationsAndFlipsFailCleanly)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_liquids.ericw-vis.bsp");
    const std::vector<uint8_t> good = test::read_bytes(path);
    size_t errors = 0;
    for (size_t cut = 0; cut < good.size(); cut += 97) {
        try {
            (void)read_ibsp38(std::span<const uint8_t>(good.data(), cut), "cut.bsp");
        } catch (const FileError&) {
            ++errors;
        }
    }
    EXPECT_GT(errors, 0u);
    std::vector<uint8_t> flipped = good;
    for (size_t i = 0; i < good.size(); i += 13) {
        flipped[i] ^= 0xA5;
        try {
            (void)read_ibsp38(flipped, "flip.bsp");
        } catch (const FileError&) {
        }
        flipped[i] = good[i];
    }
}

} // namespace
} // namespace pvs::quake2
