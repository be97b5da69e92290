// Ambient sound levels (wld/quake/ambient_sounds.h) against the bytes other tools' vis wrote:
// ericw-tools' (../shared/data/modern-quake: each map after `vis -threads 2 -nostate`) and WVis's
// (the id maps in ../shared/data/quake). From each file's own PVS, every leaf's four levels must
// come out byte for byte, and each -noambient* switch must clear exactly what its class fed.
#include "tests/support/test_data.h"
#include "visibility/file_error.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

namespace pvs::quake {
namespace {

class VisAmbient : public testing::TestWithParam<const char*> {};

size_t leaves_with(const std::vector<AmbientLevels>& levels, uint32_t channel)
{
    size_t n = 0;
    for (const AmbientLevels& l : levels)
        n += l[channel] != 0;
    return n;
}

TEST_P(VisAmbient, EveryLeafMatchesFromEricwsOwnPvs)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    const Zone zone = load_zone(path);
    ASSERT_TRUE(zone.baked_pvs.has_value());
    const std::vector<AmbientLevels> want = read_ambient_levels(bytes, path);
    const std::vector<AmbientLevels> got = compute_ambient_levels(bytes, *zone.baked_pvs, AmbientOptions{}, path);
    ASSERT_EQ(got.size(), want.size());
    size_t differ = 0, any = 0;
    for (size_t r = 0; r < got.size(); ++r) {
        differ += got[r] != want[r];
        any += want[r] != AmbientLevels{0, 0, 0, 0};
        if (got[r] != want[r] && differ <= 5)
            ADD_FAILURE() << "leaf " << r + 1 << ": got " << int(got[r][0]) << "," << int(got[r][1]) << ","
                          << int(got[r][2]) << "," << int(got[r][3]) << " ericw " << int(want[r][0]) << ","
                          << int(want[r][1]) << "," << int(want[r][2]) << "," << int(want[r][3]);
    }
    EXPECT_EQ(differ, 0u) << "of " << got.size() << " leaves";
    EXPECT_GT(any, got.size() / 3) << "ericw set levels on many leaves of this map";

    // Each switch clears its class: sky alone, or the water channel when water and slime are off.
    AmbientOptions no_sky;
    no_sky.sky = false;
    const std::vector<AmbientLevels> quiet_sky = compute_ambient_levels(bytes, *zone.baked_pvs, no_sky, path);
    EXPECT_EQ(leaves_with(quiet_sky, kAmbientSky), 0u);
    EXPECT_EQ(leaves_with(quiet_sky, kAmbientWater), leaves_with(want, kAmbientWater));
    AmbientOptions no_liquid;
    no_liquid.water = no_liquid.slime = false;
    const std::vector<AmbientLevels> quiet_water = compute_ambient_levels(bytes, *zone.baked_pvs, no_liquid, path);
    EXPECT_EQ(leaves_with(quiet_water, kAmbientWater), 0u);
    EXPECT_EQ(leaves_with(quiet_water, kAmbientSky), leaves_with(want, kAmbientSky));
    for (const AmbientLevels& l : compute_ambient_levels(bytes, *zone.baked_pvs, AmbientOptions::none(), path))
        ASSERT_EQ(l, (AmbientLevels{0, 0, 0, 0}));
    EXPECT_EQ(leaves_with(want, kAmbientSlime), 0u) << "vis sends slime to the water channel";
}

INSTANTIATE_TEST_SUITE_P(SharedMaps, VisAmbient,
                         testing::Values("modern-quake/q1/lqdm2.ericw-vis.bsp", "modern-quake/q1/lqdm5.ericw-vis.bsp",
                                         "quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp",
                                         "quake/start.bsp", "quake/end.bsp"),
                         [](const testing::TestParamInfo<const char*>& p) {
                             return test::param_name(p.param); // "lqdm2.ericw-vis.bsp" -> "lqdm2_ericw_vis"
                         });

// The shared README's sums: lqdm2 452 leaves with a level, sky 115 260 in all; lqdm5 444 975
// water and 457 980 sky.
TEST(VisAmbient, KnownSumsOfTheSharedFiles)
{
    SHARED_DATA_OR_SKIP(lqdm2, "modern-quake/q1/lqdm2.ericw-vis.bsp");
    SHARED_DATA_OR_SKIP(lqdm5, "modern-quake/q1/lqdm5.ericw-vis.bsp");
    const auto sums = [](const std::string& path, size_t& leaves) {
        std::array<uint64_t, 4> s{};
        leaves = 0;
        for (const AmbientLevels& l : read_ambient_levels(test::read_bytes(path), path)) {
            for (int c = 0; c < 4; ++c)
                s[size_t(c)] += l[size_t(c)];
            leaves += l != AmbientLevels{0, 0, 0, 0};
        }
        return s;
    };
    size_t leaves = 0;
    const auto s2 = sums(lqdm2, leaves);
    EXPECT_EQ(leaves, 452u);
    EXPECT_EQ(s2[kAmbientWater], 0u);
    EXPECT_EQ(s2[kAmbientSky], 115260u);
    const auto s5 = sums(lqdm5, leaves);
    EXPECT_EQ(s5[kAmbientWater], 444975u);
    EXPECT_EQ(s5[kAmbientSky], 457980u);
}

TEST(VisAmbient, BadInputIsAFileError)
{
    const std::vector<uint8_t> ibsp = {'I', 'B', 'S', 'P', 38, 0, 0, 0};
    try {
        read_ambient_levels(ibsp, "q2.bsp");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("Quake 2 IBSP version 38"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_ambient_levels(std::vector<uint8_t>{29, 0}, "short.bsp"), FileError);
}

} // namespace
} // namespace pvs::quake
