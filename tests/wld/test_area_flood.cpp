// Quake 2 areas and areaportals (visibility/area_flood.h, read by wld/quake2/ibsp38_zone.h) on
// ericw's q2_areaportals: four areas (0 is the null area), two func_areaportal doors, number 1
// between areas 2 and 3 and number 2 between areas 1 and 2 (the map's areas lump). Each door's
// brush is the CONTENTS_AREAPORTAL leaf between its two areas; shutting a door drops the areas
// behind it, as the engine's areabits do.
#include "tests/support/test_data.h"
#include "visibility/area_flood.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

namespace pvs {
namespace {

const AreaPortal* portal_numbered(const Zone& zone, uint32_t number)
{
    for (const AreaPortal& p : zone.area_portals)
        if (p.number == number)
            return &p;
    return nullptr;
}

size_t index_of(const Zone& zone, const AreaPortal* portal) { return size_t(portal - zone.area_portals.data()); }

bool touches(const Aabb& a, const Aabb& b)
{
    for (int k = 0; k < 3; ++k)
        if (a.max[k] < b.min[k] || b.max[k] < a.min[k])
            return false;
    return true;
}

TEST(AreaPortals, TwoDoorsBetweenTheAreasTheMapNames)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_areaportals.ericw-vis.bsp");
    const Zone zone = load_zone(path);
    ASSERT_EQ(zone.area_portals.size(), 2u);
    const AreaPortal* one = portal_numbered(zone, 1);
    const AreaPortal* two = portal_numbered(zone, 2);
    ASSERT_TRUE(one && two);
    EXPECT_EQ(one->areas[0], 2);
    EXPECT_EQ(one->areas[1], 3);
    EXPECT_EQ(two->areas[0], 1);
    EXPECT_EQ(two->areas[1], 2);
    ASSERT_EQ(zone.region_areas.size(), zone.region_count());
    // Each door's box touches regions of both its areas and no region of a third area.
    for (const AreaPortal* door : {one, two}) {
        ASSERT_FALSE(door->bounds.empty()) << "door " << door->number;
        std::set<int32_t> areas;
        for (uint32_t r = 0; r < zone.region_count(); ++r)
            if (touches(zone.regions[r].bounds, door->bounds))
                areas.insert(zone.region_areas[r]);
        EXPECT_TRUE(areas.count(door->areas[0]) && areas.count(door->areas[1])) << "door " << door->number;
        EXPECT_EQ(areas.size(), 2u) << "door " << door->number;
    }
}

TEST(AreaPortals, ShuttingADoorDropsTheAreasBehindIt)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_areaportals.ericw-vis.bsp");
    const Zone zone = load_zone(path);
    ASSERT_EQ(zone.area_portals.size(), 2u);
    std::vector<uint8_t> closed(2, 0);
    EXPECT_EQ(areas_reached(zone, 1, closed), (std::vector<uint8_t>{0, 1, 1, 1}));
    closed[index_of(zone, portal_numbered(zone, 2))] = 1; // the door between areas 1 and 2
    EXPECT_EQ(areas_reached(zone, 1, closed), (std::vector<uint8_t>{0, 1, 0, 0}));
    EXPECT_EQ(areas_reached(zone, 3, closed), (std::vector<uint8_t>{0, 0, 1, 1}));
    closed.assign(2, 0);
    closed[index_of(zone, portal_numbered(zone, 1))] = 1; // between 2 and 3
    EXPECT_EQ(areas_reached(zone, 1, closed), (std::vector<uint8_t>{0, 1, 1, 0}));
    EXPECT_EQ(areas_reached(zone, -1, closed), (std::vector<uint8_t>{1, 1, 1, 1})) << "no camera area: all";

    // The culled list keeps exactly the regions of reached areas, in order.
    std::vector<uint32_t> regions(zone.region_count());
    for (uint32_t r = 0; r < regions.size(); ++r)
        regions[r] = r;
    const std::vector<uint8_t> reached = areas_reached(zone, 1, closed);
    const size_t dropped = keep_reached_areas(zone, reached, regions);
    size_t in_area_3 = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        in_area_3 += zone.region_areas[r] == 3;
    EXPECT_EQ(dropped, in_area_3);
    EXPECT_GT(dropped, 0u);
    EXPECT_TRUE(std::is_sorted(regions.begin(), regions.end()));
    for (uint32_t r : regions)
        EXPECT_NE(zone.region_areas[r], 3);
}

TEST(AreaPortals, ZonesWithoutAreasDropNothing)
{
    Zone zone;
    zone.regions.resize(3);
    std::vector<uint32_t> regions{0, 1, 2};
    EXPECT_TRUE(areas_reached(zone, 0, {}).empty());
    EXPECT_EQ(keep_reached_areas(zone, areas_reached(zone, 0, {}), regions), 0u);
    EXPECT_EQ(regions.size(), 3u);
}

} // namespace
} // namespace pvs
