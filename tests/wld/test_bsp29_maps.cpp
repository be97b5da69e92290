// Every Quake level in ../shared/data loads, and every PVS row in it decodes to exactly
// (visleafs+7)/8 bytes. The row check parses the lumps itself and decodes with the spec's
// pseudo-code (no clamping), independently of the loader, then compares with the loaded PVS.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/zone_stats.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <cstring>

namespace pvs {
namespace {

template <class T>
T get(const std::vector<uint8_t>& d, size_t at)
{
    T v;
    std::memcpy(&v, d.data() + at, sizeof v);
    return v;
}

// The spec's decoder (§1.10), counting what it produces without clamping a run to the row.
std::vector<uint8_t> spec_decode(const std::vector<uint8_t>& d, size_t at, size_t end, size_t row_bytes)
{
    std::vector<uint8_t> out;
    while (out.size() < row_bytes && at < end) {
        const uint8_t b = d[at++];
        if (b != 0)
            out.push_back(b);
        else if (at < end)
            out.insert(out.end(), d[at++], uint8_t{0});
    }
    return out;
}

struct MapCase {
    const char* file;
    uint32_t visleafs;
    uint32_t leaves;
};

class QuakeMap : public ::testing::TestWithParam<MapCase> {};

TEST_P(QuakeMap, LoadsAndEveryPvsRowDecodesToExactlyTheRowSize)
{
    SHARED_DATA_OR_SKIP(path, GetParam().file);
    const std::vector<uint8_t> d = test::read_bytes(path);
    const Zone zone = quake::load_bsp29(d, path);
    ASSERT_EQ(zone.region_count(), GetParam().visleafs);
    ASSERT_TRUE(zone.baked_pvs.has_value());

    const size_t vis_ofs = get<int32_t>(d, 4 + 8 * 4), vis_len = get<int32_t>(d, 4 + 8 * 4 + 4);
    const size_t leaf_ofs = get<int32_t>(d, 4 + 8 * 10), leaf_len = get<int32_t>(d, 4 + 8 * 10 + 4);
    ASSERT_EQ(leaf_len / 28, GetParam().leaves);
    const size_t row_bytes = (GetParam().visleafs + 7) / 8;
    std::vector<uint64_t> loaded(bits::words_for(GetParam().visleafs));
    for (uint32_t leaf = 1; leaf <= GetParam().visleafs; ++leaf) {
        const int32_t visofs = get<int32_t>(d, leaf_ofs + 28 * leaf + 4);
        ASSERT_GE(visofs, 0) << "leaf " << leaf;
        const std::vector<uint8_t> row = spec_decode(d, vis_ofs + size_t(visofs), vis_ofs + vis_len, row_bytes);
        ASSERT_EQ(row.size(), row_bytes) << "leaf " << leaf;
        zone.baked_pvs->decode_row(leaf - 1, loaded);
        std::vector<uint8_t> loaded_bytes(row_bytes);
        bits::to_bytes(loaded, GetParam().visleafs, loaded_bytes);
        std::vector<uint8_t> expected = row;
        if (GetParam().visleafs % 8)
            expected.back() &= uint8_t((1u << (GetParam().visleafs % 8)) - 1);
        ASSERT_EQ(loaded_bytes, expected) << "leaf " << leaf;
    }
}

// Counts from ../shared/data/README.md.
INSTANTIATE_TEST_SUITE_P(SharedData, QuakeMap,
                         ::testing::Values(MapCase{"quake/e1m1.bsp", 1206, 1593}, MapCase{"quake/e1m2.bsp", 1149, 1548},
                                           MapCase{"quake/e2m1.bsp", 1110, 1621}, MapCase{"quake/dm2.bsp", 984, 1210},
                                           MapCase{"quake/start.bsp", 1172, 1612}, MapCase{"quake/end.bsp", 337, 674},
                                           MapCase{"visdemo/example.bsp", 11, 12}),
                         [](const ::testing::TestParamInfo<MapCase>& param) { return test::param_name(param.param.file); });

TEST(QuakeMaps, EndHas61LavaLeaves)
{
    SHARED_DATA_OR_SKIP(path, "quake/end.bsp");
    const Zone zone = quake::load_bsp29(test::read_bytes(path), path);
    uint64_t lava = 0;
    for (const auto& [key, value] : zone.source.counts)
        if (key == "leaves.lava")
            lava = value;
    EXPECT_EQ(lava, 61u);
    uint32_t lava_regions = 0;
    for (const Region& r : zone.regions)
        lava_regions += (r.flags & kRegionLava) != 0;
    EXPECT_GT(lava_regions, 0u);
}

TEST(QuakeMaps, VisdemoHasElevenLeavesThatAllSeeThemselves)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone zone = quake::load_bsp29(test::read_bytes(path), path);
    ASSERT_EQ(zone.region_count(), 11u);
    for (uint32_t r = 0; r < 11; ++r)
        EXPECT_TRUE(zone.baked_pvs->visible(r, r)) << r;
}

} // namespace
} // namespace pvs

namespace pvs {
namespace {

TEST(QuakeMaps, VisdemoPicksUpItsPortalFile)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
    const Zone zone = load_zone(path);
    EXPECT_EQ(zone.region_count(), 11u);
    ASSERT_TRUE(zone.portals.has_value());
    EXPECT_EQ(zone.portals->portals.size(), 12u);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    // Every portal joins two regions, so each side's region is in the other's PVS.
    for (const Portal& p : zone.portals->portals) {
        EXPECT_TRUE(zone.baked_pvs->visible(uint32_t(p.regions[0]), uint32_t(p.regions[1])));
        EXPECT_TRUE(zone.baked_pvs->visible(uint32_t(p.regions[1]), uint32_t(p.regions[0])));
    }
}

} // namespace
} // namespace pvs
