// e1m1.bsp, compiled elsewhere (id's map source, Txqbsp + WVis): the known answers of
// ../shared/data/README.md and ../shared/formats/quake-doom-hepvs.md §1.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/region_lookup.h"
#include "visibility/zone_stats.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <map>

namespace pvs {
namespace {

uint64_t source_count(const Zone& zone, const std::string& key)
{
    for (const auto& [k, v] : zone.source.counts)
        if (k == key)
            return v;
    ADD_FAILURE() << "no source count " << key;
    return 0;
}

class E1m1 : public ::testing::Test {
protected:
    void SetUp() override
    {
        SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
        zone_ = test::shared_zone("quake/e1m1.bsp");
        ASSERT_NE(zone_, nullptr);
    }
    static const Zone* zone_;
};
const Zone* E1m1::zone_ = nullptr;

TEST_F(E1m1, HasOneRegionPerVisLeaf)
{
    EXPECT_EQ(zone_->region_count(), 1206u);
    EXPECT_EQ(source_count(*zone_, "leaves"), 1593u);
    EXPECT_EQ(zone_->tree.nodes.size(), 2912u);
    EXPECT_EQ(zone_->tree.leaf_region[0], kLeafSolid);
}

TEST_F(E1m1, LeafContentsMatchTheKnownCounts)
{
    EXPECT_EQ(source_count(*zone_, "leaves.empty"), 1407u);
    EXPECT_EQ(source_count(*zone_, "leaves.solid"), 1u);
    EXPECT_EQ(source_count(*zone_, "leaves.water"), 33u);
    EXPECT_EQ(source_count(*zone_, "leaves.slime"), 108u);
    EXPECT_EQ(source_count(*zone_, "leaves.sky"), 44u);
    EXPECT_EQ(source_count(*zone_, "leaves.lava"), 0u);
}

TEST_F(E1m1, PvsMeanOverAllRowsIs142)
{
    ASSERT_TRUE(zone_->baked_pvs.has_value());
    const Pvs& pvs = *zone_->baked_pvs;
    EXPECT_EQ(pvs.region_count(), 1206u);
    EXPECT_EQ(pvs.missing_row_count(), 0u);
    const PvsDensity density = compute_pvs_density(pvs);
    EXPECT_NEAR(density.mean_visible, 142.0, 0.05);
    EXPECT_NEAR(density.mean_percent, 11.8, 0.05);
}

TEST_F(E1m1, EveryLeafSeesItself)
{
    const Pvs& pvs = *zone_->baked_pvs;
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t r = 0; r < pvs.region_count(); ++r) {
        pvs.decode_row(r, row);
        ASSERT_TRUE(bits::test(row, r)) << "region " << r;
    }
}

TEST_F(E1m1, OneChangelevelToE1m2MarksTheRegionsItTouches)
{
    EXPECT_EQ(source_count(*zone_, "trigger_changelevel"), 1u);
    ASSERT_EQ(zone_->zone_lines.size(), 1u);
    const ZoneLine& line = zone_->zone_lines[0];
    EXPECT_EQ(line.target, "e1m2");
    // Model 52 stores (1289,521,-279)-(1335,567,-129): the true box is one unit larger (§1.7).
    EXPECT_EQ(line.bounds.min, glm::vec3(1288, 520, -280));
    EXPECT_EQ(line.bounds.max, glm::vec3(1336, 568, -128));
    size_t flagged = 0;
    for (const Region& r : zone_->regions) {
        if (!(r.flags & kRegionZoneLine))
            continue;
        ++flagged;
        EXPECT_EQ(r.zone_line, 0);
        EXPECT_TRUE(r.bounds.overlaps(line.bounds));
    }
    EXPECT_GE(flagged, 1u);
    // The trigger's centre is in open space, so its region must be among the flagged ones.
    const PointLocation at = locate_point(zone_->tree, line.bounds.center());
    ASSERT_TRUE(at.in_region());
    EXPECT_TRUE(zone_->regions[at.region].flags & kRegionZoneLine);
}

TEST_F(E1m1, PlayerStartIsInLeaf1199)
{
    // §1.5: info_player_start (480,-352,88) falls in leaf 1199, contents empty.
    const PointLocation at = locate_point(zone_->tree, {480, -352, 88});
    EXPECT_EQ(at.leaf, 1199);
    EXPECT_EQ(at.region, 1198);
    EXPECT_EQ(zone_->regions[1198].flags & (kRegionWater | kRegionSlime | kRegionLava | kRegionSky), 0u);
}

TEST_F(E1m1, LiquidFlagsFollowLeafContents)
{
    const ZoneStats s = compute_zone_stats(*zone_);
    // Counts over the world's vis leaves only (the README's counts include brush-entity leaves).
    uint32_t water = 0, slime = 0, sky = 0;
    for (const Region& r : zone_->regions) {
        water += (r.flags & kRegionWater) != 0;
        slime += (r.flags & kRegionSlime) != 0;
        sky += (r.flags & kRegionSky) != 0;
    }
    EXPECT_EQ(s.flag_counts[0], water);
    EXPECT_GT(water, 0u);
    EXPECT_GT(slime, 0u);
    EXPECT_GT(sky, 0u);
    EXPECT_LE(water, 33u);
    EXPECT_LE(slime, 108u);
    EXPECT_LE(sky, 44u);
}

TEST_F(E1m1, MiptexDecodesWithTheKnownSizes)
{
    // §1.6: texture slipbotsd is 16x64.
    bool found = false;
    for (const Material& m : zone_->materials) {
        if (m.name != "slipbotsd")
            continue;
        found = true;
        EXPECT_EQ(m.width, 16u);
        EXPECT_EQ(m.height, 64u);
        EXPECT_EQ(material_rgba(m).size(), 16u * 64u * 4u);
    }
    EXPECT_TRUE(found);
}

TEST_F(E1m1, FacesAreFansWithCounterClockwiseFrontsAndRegionListsAreInRange)
{
    const Mesh& mesh = zone_->mesh;
    EXPECT_EQ(mesh.positions.size(), mesh.uvs.size());
    uint64_t triangles = 0;
    for (const Face& f : mesh.faces) {
        EXPECT_EQ(f.first_triangle, triangles);
        triangles += f.triangle_count;
        ASSERT_LT(f.material, zone_->materials.size());
    }
    EXPECT_EQ(triangles, mesh.triangle_count());
    for (uint32_t face : zone_->region_faces)
        ASSERT_LT(face, mesh.faces.size());
    EXPECT_EQ(zone_->region_face_offsets.back(), zone_->region_faces.size());
}

} // namespace
} // namespace pvs
