// Quake 2 maps as zones (wld/quake2/ibsp38_zone.h), on ericw-tools' files (qbsp -q2bsp, vis):
//  - the regions are the leaves with a cluster that are not solid, counted here from the file's
//    own bytes; every region's row is its cluster's row in the file, expanded to leaves;
//  - points on a split plane go to the front child, as Quake 2's CM_PointLeafnum;
//  - Quake 2's content rule: every portal built from the tree joins two leaves of one cluster or
//    two clusters qbsp's own portal file joins (plain water, lava, slime and glass without
//    translucency block sight: qbsp writes no portal there), and ericw's PVS misses no bit of
//    the sampled reference;
//  - unvised maps load without a PVS; names of the file's surfaces and contents reach the zone.
// Bad input (truncation, byte flips) is in test_bad_input.cpp, with the other BSP readers.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "visibility/portal/portalize.h"
#include "visibility/reference/reference_vis.h"
#include "visibility/region_lookup.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/quake2_vis.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <stdexcept>
#include <utility>

namespace pvs {
namespace {

const char* const kMaps[] = {"q2_areaportals", "q2_liquids", "q2_tjunc_matrix"};

template <class T>
T at(const std::vector<uint8_t>& bytes, size_t offset)
{
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

// The leaves straight from the bytes: (contents, cluster) per leaf, 28-byte records of lump 8.
std::vector<std::pair<int32_t, int16_t>> raw_leaves(const std::vector<uint8_t>& bytes)
{
    const int32_t offset = at<int32_t>(bytes, 8 + 8 * 8), length = at<int32_t>(bytes, 8 + 8 * 8 + 4);
    std::vector<std::pair<int32_t, int16_t>> leaves;
    for (int32_t i = 0; i < length / 28; ++i)
        leaves.emplace_back(at<int32_t>(bytes, size_t(offset + 28 * i)), at<int16_t>(bytes, size_t(offset + 28 * i + 4)));
    return leaves;
}

// The file's PVS bit "cluster a sees cluster b", decoded here from the visibility lump.
bool file_sees(const std::vector<uint8_t>& bytes, uint32_t a, uint32_t b)
{
    const int32_t lump = at<int32_t>(bytes, 8 + 8 * 3);
    size_t p = size_t(lump) + size_t(at<int32_t>(bytes, size_t(lump) + 4 + 8 * size_t(a)));
    uint32_t bit = 0; // Quake RLE: a zero byte then a count of zero bytes
    for (;;) {
        const uint8_t byte = bytes[p++];
        if (byte == 0) {
            bit += 8 * uint32_t(bytes[p++]);
            if (bit > b)
                return false;
            continue;
        }
        if (b < bit + 8)
            return (byte >> (b - bit)) & 1;
        bit += 8;
    }
}

class Quake2Zone : public ::testing::TestWithParam<const char*> {};

TEST_P(Quake2Zone, RegionsAreTheOpenLeavesWithAClusterAndTakeTheirClustersRows)
{
    SHARED_DATA_OR_SKIP(path, std::string("modern-quake/q2/") + GetParam() + ".ericw-vis.bsp");
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    const Zone zone = load_zone(path);
    EXPECT_EQ(zone.source.format, "Quake 2 BSP");
    EXPECT_EQ(zone.tree.tie_rule, TieRule::OnPlaneGoesFront);
    const auto leaves = raw_leaves(bytes);
    ASSERT_EQ(zone.tree.leaf_region.size(), leaves.size());
    std::vector<uint32_t> cluster_of_region;
    for (size_t i = 0; i < leaves.size(); ++i) {
        const bool region = leaves[i].second >= 0 && !(leaves[i].first & 1);
        EXPECT_EQ(zone.tree.leaf_region[i] >= 0, region) << "leaf " << i;
        if (region) {
            EXPECT_EQ(zone.tree.leaf_region[i], int32_t(cluster_of_region.size())) << "regions in leaf order";
            cluster_of_region.push_back(uint32_t(leaves[i].second));
        }
    }
    ASSERT_EQ(zone.region_count(), cluster_of_region.size());
    ASSERT_TRUE(zone.baked_pvs);
    std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        zone.baked_pvs->decode_row(r, row);
        for (uint32_t s = 0; s < zone.region_count(); ++s)
            ASSERT_EQ(bits::test(row, s), file_sees(bytes, cluster_of_region[r], cluster_of_region[s]))
                << r << " -> " << s;
    }
}

TEST_P(Quake2Zone, PortalsFromTheTreeJoinOnlyClustersQbspJoins)
{
    SHARED_DATA_OR_SKIP(path, std::string("modern-quake/q2/") + GetParam() + ".ericw-vis.bsp");
    SHARED_DATA_OR_SKIP(prt_path, std::string("modern-quake/q2/") + GetParam() + ".prt");
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    const Zone zone = load_zone(path);
    const auto leaves = raw_leaves(bytes);
    std::vector<uint32_t> cluster(zone.region_count());
    for (size_t i = 0; i < leaves.size(); ++i)
        if (zone.tree.leaf_region[i] >= 0)
            cluster[size_t(zone.tree.leaf_region[i])] = uint32_t(leaves[i].second);
    const quake::PrtFile prt = quake::load_prt(prt_path); // PRT1 over clusters
    std::set<std::pair<uint32_t, uint32_t>> joined;
    for (const Portal& p : prt.portals.portals)
        joined.insert(std::minmax(uint32_t(p.regions[0]), uint32_t(p.regions[1])));
    const PortalSet built = build_zone_portals(zone, PortalOptions{});
    ASSERT_FALSE(built.portals.empty());
    std::set<std::pair<uint32_t, uint32_t>> built_pairs;
    for (const Portal& p : built.portals) {
        const uint32_t a = cluster[size_t(p.regions[0])], b = cluster[size_t(p.regions[1])];
        if (a != b) {
            EXPECT_TRUE(joined.count(std::minmax(a, b))) << "clusters " << a << " and " << b;
            built_pairs.insert(std::minmax(a, b));
        }
    }
    // Not every pair qbsp joins is joined here: its portals cross detail brushes inside a
    // cluster (vis ignores them), the tree's portals do not (a detail solid leaf is a wall).
    EXPECT_GE(built_pairs.size() * 10, joined.size() * 9);
}

TEST_P(Quake2Zone, EricwsPvsHoldsEverySampledSightLine)
{
    SHARED_DATA_OR_SKIP(path, std::string("modern-quake/q2/") + GetParam() + ".ericw-vis.bsp");
    const Zone zone = load_zone(path);
    ReferenceParams params;
    params.max_samples = 256;
    params.converge_share = 0.0;
    params.threads = 2;
    const Pvs reference = bake_reference_vis(zone, params, nullptr);
    std::vector<uint64_t> seen(reference.words_per_row()), file(reference.words_per_row());
    uint64_t bits_found = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        reference.decode_row(r, seen);
        zone.baked_pvs->decode_row(r, file);
        for (size_t w = 0; w < seen.size(); ++w) {
            EXPECT_EQ(seen[w] & ~file[w], 0u) << "region " << r << " word " << w;
            bits_found += uint64_t(__builtin_popcountll(seen[w]));
        }
    }
    EXPECT_GT(bits_found, zone.region_count()) << "the reference found pairs beyond each region itself";
}

// The counts `info` shows are the map's: the areas its leaves are in (read here from the raw
// leaves lump: contents, cluster, area) and its func_areaportal entities (counted in the entity
// text), not the lumps' entries, which hold an unused area 0 and each door twice after an unused
// entry 0.
TEST_P(Quake2Zone, InfoCountsTheAreasAndAreaportalsTheMapHolds)
{
    SHARED_DATA_OR_SKIP(path, std::string("modern-quake/q2/") + GetParam() + ".ericw-vis.bsp");
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    const int32_t leaves_at = at<int32_t>(bytes, 8 + 8 * 8), leaves_length = at<int32_t>(bytes, 8 + 8 * 8 + 4);
    std::set<int16_t> areas;
    for (int32_t i = 0; i < leaves_length / 28; ++i)
        if (const int16_t area = at<int16_t>(bytes, size_t(leaves_at + 28 * i + 6)); area > 0)
            areas.insert(area);
    const int32_t entities_at = at<int32_t>(bytes, 8), entities_length = at<int32_t>(bytes, 12);
    const std::string entities(bytes.begin() + entities_at, bytes.begin() + entities_at + entities_length);
    uint64_t doors = 0;
    for (size_t p = entities.find("\"func_areaportal\""); p != std::string::npos;
         p = entities.find("\"func_areaportal\"", p + 1))
        ++doors;
    const Zone zone = load_zone(path);
    const auto count = [&](const char* name) {
        for (const auto& [key, value] : zone.source.counts)
            if (key == name)
                return value;
        ADD_FAILURE() << name << " not counted";
        return uint64_t(0);
    };
    EXPECT_EQ(count("areas"), areas.size());
    EXPECT_EQ(count("areaportals"), doors);
    EXPECT_EQ(zone.area_portals.size(), doors);
}

INSTANTIATE_TEST_SUITE_P(EricwTools, Quake2Zone, ::testing::ValuesIn(kMaps));

TEST(Quake2ZoneRules, PlainLiquidsAndGlassBlockSightTranslucentOnesDoNot)
{
    // q2_liquids: a room with brushes of each content, once plain and once translucent (detail).
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_liquids.ericw-vis.bsp");
    const Zone zone = load_zone(path);
    const PortalSet built = build_zone_portals(zone, PortalOptions{});
    uint32_t plain_liquid_regions = 0, translucent_liquid_regions = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const uint16_t contents = zone.regions[r].vis_contents;
        if ((contents & 0xFF) == 0)
            continue;
        const bool translucent = (contents >> 8) == 0; // cleared by translucency or detail
        if (translucent)
            ++translucent_liquid_regions;
        else
            ++plain_liquid_regions;
        for (const Portal& p : built.portals) {
            if (p.regions[0] != int32_t(r) && p.regions[1] != int32_t(r))
                continue;
            const uint32_t other = uint32_t(p.regions[0] == int32_t(r) ? p.regions[1] : p.regions[0]);
            if (!translucent) {
                EXPECT_EQ(zone.regions[other].vis_contents, contents) << "a plain liquid sees only its own kind";
            }
        }
    }
    EXPECT_GE(plain_liquid_regions, 4u) << "window, lava, slime, water";
    EXPECT_GE(translucent_liquid_regions, 4u);
}

TEST(Quake2ZoneRules, UnvisedMapLoadsWithoutAPvsAndNamesItsSurfaces)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_liquids.bsp");
    const Zone zone = load_zone(path);
    EXPECT_FALSE(zone.baked_pvs);
    EXPECT_GT(zone.region_count(), 0u);
    bool warp = false, translucent = false;
    for (const Material& m : zone.materials) {
        warp |= (m.flags & kMaterialLiquid) != 0;
        translucent |= (m.flags & kMaterialTranslucent) != 0;
        if (m.flags & kMaterialFaint) { // SURF_TRANS33: a kind of translucent surface
            EXPECT_TRUE(m.flags & kMaterialTranslucent) << m.name;
        }
        EXPECT_TRUE(m.has_pixels()) << m.name << ": a flat colour stands in for the .wal";
    }
    EXPECT_TRUE(warp) << "SURF_WARP liquids";
    EXPECT_TRUE(translucent) << "SURF_TRANS33/66";
    // Every face is listed by a region whose leaf lies in front of it (qbsp marks faces that way).
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        for (uint32_t f : zone.faces_of_region(r))
            ASSERT_LT(f, zone.mesh.faces.size());
}

TEST(Quake2ZoneRules, WritingRowsChecksTheZoneAgainstTheMap)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_liquids.bsp");
    SHARED_DATA_OR_SKIP(other_path, "modern-quake/q2/q2_areaportals.bsp");
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    Zone zone = load_zone(path);
    const auto all_visible = [](uint32_t regions) {
        return Pvs::build(regions, [](uint32_t, std::span<uint64_t> row) {
            std::fill(row.begin(), row.end(), ~uint64_t{0});
            return true;
        });
    };
    const quake2::Quake2ZonePvsResult written =
        quake2::write_quake2_zone_pvs(bytes, path, zone, all_visible(uint32_t(zone.region_count())));
    EXPECT_EQ(written.clusters, 18u);
    EXPECT_DOUBLE_EQ(written.mean_visible, 18.0);
    EXPECT_THROW(quake2::write_quake2_zone_pvs(bytes, path, zone, all_visible(3)), std::invalid_argument);
    const Zone other = load_zone(other_path);
    EXPECT_THROW(quake2::write_quake2_zone_pvs(bytes, path, other, all_visible(uint32_t(other.region_count()))),
                 FileError);
    // A region moved onto a leaf without a cluster (a solid one): refused, naming the region.
    size_t solid_leaf = 0;
    while (zone.tree.leaf_region[solid_leaf] != kLeafSolid)
        ++solid_leaf;
    for (int32_t& region : zone.tree.leaf_region)
        if (region == 0)
            region = kLeafSolid;
    zone.tree.leaf_region[solid_leaf] = 0;
    try {
        quake2::write_quake2_zone_pvs(bytes, path, zone, all_visible(uint32_t(zone.region_count())));
        FAIL() << "a region without a cluster was written";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("region 0 has no cluster"), std::string::npos) << e.what();
    }
}

TEST(Quake2ZoneRules, Quake3MapsAreNamedNotOpened)
{
    std::vector<uint8_t> bytes(8 + 17 * 8, 0);
    std::memcpy(bytes.data(), "IBSP", 4);
    bytes[4] = 46;
    const std::string path = testing::TempDir() + "/q3.bsp";
    FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
    try {
        load_zone(path);
        FAIL() << "a Quake 3 map opened";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("Quake 3 map (IBSP 46)"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace pvs
