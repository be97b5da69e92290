// Cluster formation (visibility/portal/region_clusters.h, box_clusters.h) on hand-built trees
// and boxes whose right grouping is worked out in the comments; and on a generated zone, where
// every box cluster must be a box the generator's own cells fill (checked against the voxel
// boxes, kd_bsp.h) and portals must join the regions of a multi-region cluster.
#include "tests/support/test_data.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/portalize.h"
#include "visibility/portal/region_clusters.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace pvs {
namespace {

Region box_region(glm::vec3 lo, glm::vec3 hi, uint32_t flags = 0)
{
    Region region;
    region.bounds.grow(lo);
    region.bounds.grow(hi);
    region.flags = flags;
    return region;
}

// A tree: root splits x = 0; front = leaf 0; back = node 1 splitting y = 0 into leaves 1, 2.
BspTree two_level_tree(int32_t leaf0, int32_t leaf1, int32_t leaf2)
{
    BspTree tree;
    tree.nodes.push_back({glm::vec3(1, 0, 0), 0.0f, {~0, 1}});
    tree.nodes.push_back({glm::vec3(0, 1, 0), 0.0f, {~1, ~2}});
    tree.leaf_region = {leaf0, leaf1, leaf2};
    tree.root = 0;
    return tree;
}

TEST(RegionClusters, AnAllOpenTreeIsOneCluster)
{
    const std::vector<Region> regions(3);
    const RegionClusters clusters = bsp_subtree_clusters(two_level_tree(0, 1, 2), regions);
    EXPECT_EQ(clusters.cluster_count, 1u);
    EXPECT_EQ(clusters.cluster_of_region, (std::vector<uint32_t>{0, 0, 0}));
}

TEST(RegionClusters, ASolidLeafKeepsItsSubtreeApartButNotItsOpenSibling)
{
    // Back subtree holds a solid leaf: leaves 0 and 2 stay alone. Regions 0 and 1 (leaf 2).
    const std::vector<Region> regions(2);
    const RegionClusters clusters = bsp_subtree_clusters(two_level_tree(0, kLeafSolid, 1), regions);
    EXPECT_EQ(clusters.cluster_count, 2u);
    EXPECT_EQ(clusters.cluster_of_region, (std::vector<uint32_t>{0, 1}));
    // Leaves 1 and 2 open, leaf 0 outside: the back subtree is one cluster.
    const RegionClusters back = bsp_subtree_clusters(two_level_tree(kLeafOutside, 0, 1), regions);
    EXPECT_EQ(back.cluster_of_region, (std::vector<uint32_t>{0, 0}));
}

TEST(RegionClusters, SkyAndAirStayApartAndTheBoundSplitsBigSubtrees)
{
    std::vector<Region> regions(3);
    regions[2].flags = kRegionSky;
    const RegionClusters mixed = bsp_subtree_clusters(two_level_tree(0, 1, 2), regions);
    EXPECT_EQ(mixed.cluster_of_region, (std::vector<uint32_t>{0, 1, 2}));

    const std::vector<Region> air(3);
    ClusterOptions two;
    two.max_regions = 2;
    const RegionClusters bounded = bsp_subtree_clusters(two_level_tree(0, 1, 2), air, two);
    EXPECT_EQ(bounded.cluster_of_region, (std::vector<uint32_t>{0, 1, 1}));
}

TEST(RegionClusters, ARegionInTwoLeavesJoinsBothClustersAndBadTreesDoNotHang)
{
    // root: front = node 1 (leaves: regions 0, 1), back = node 2 (front = node 3 (leaves:
    // regions 1, 2), back = a solid leaf). Node 1 and node 3 are clusters {0, 1} and {1, 2};
    // region 1 is in both, so they merge. Region 3 is in no leaf: a cluster of its own.
    BspTree shared_tree;
    shared_tree.nodes.push_back({glm::vec3(1, 0, 0), 0.0f, {1, 2}});
    shared_tree.nodes.push_back({glm::vec3(0, 1, 0), 0.0f, {~0, ~1}});
    shared_tree.nodes.push_back({glm::vec3(0, 1, 0), 0.0f, {3, ~4}});
    shared_tree.nodes.push_back({glm::vec3(0, 0, 1), 0.0f, {~2, ~3}});
    shared_tree.leaf_region = {0, 1, 1, 2, kLeafSolid};
    shared_tree.root = 0;
    const RegionClusters shared = bsp_subtree_clusters(shared_tree, std::vector<Region>(4));
    EXPECT_EQ(shared.cluster_of_region, (std::vector<uint32_t>{0, 0, 0, 1}));
    EXPECT_EQ(shared.cluster_count, 2u);

    BspTree cycle = two_level_tree(0, 1, 2);
    cycle.nodes[1].children[1] = 0; // back to the root
    const RegionClusters result = bsp_subtree_clusters(cycle, std::vector<Region>(3));
    EXPECT_EQ(result.cluster_of_region.size(), 3u);
    BspTree empty;
    EXPECT_EQ(bsp_subtree_clusters(empty, std::vector<Region>(2)).cluster_count, 2u);
}

void add_portal(PortalSet& set, int32_t a, int32_t b)
{
    Portal portal;
    portal.regions[0] = a;
    portal.regions[1] = b;
    set.portals.push_back(portal); // the merge reads only the regions
}

TEST(BoxClusters, FourBoxesOfASquareBecomeOneAndAnLShapeNeedsALowerFill)
{
    // 2 x 2 unit squares: 0 = (0,0), 1 = (1,0), 2 = (0,1), 3 = (1,1); portals 0-1, 2-3, 0-2, 1-3.
    const std::vector<Region> square{box_region({0, 0, 0}, {1, 1, 1}), box_region({1, 0, 0}, {2, 1, 1}),
                                     box_region({0, 1, 0}, {1, 2, 1}), box_region({1, 1, 0}, {2, 2, 1})};
    PortalSet portals;
    add_portal(portals, 0, 1);
    add_portal(portals, 2, 3);
    add_portal(portals, 0, 2);
    add_portal(portals, 1, 3);
    const RegionClusters one = box_merge_clusters(square, portals);
    EXPECT_EQ(one.cluster_count, 1u);

    // Without box 3: 0-1 merge into a 2 x 1 box; adding 2 would fill 3 of the 2 x 2 box.
    const std::vector<Region> l_shape(square.begin(), square.begin() + 3);
    PortalSet l_portals;
    add_portal(l_portals, 0, 1);
    add_portal(l_portals, 0, 2);
    const RegionClusters boxes = box_merge_clusters(l_shape, l_portals);
    EXPECT_EQ(boxes.cluster_of_region, (std::vector<uint32_t>{0, 0, 1}));
    BoxClusterOptions three_quarters;
    three_quarters.min_fill = 0.75f;
    EXPECT_EQ(box_merge_clusters(l_shape, l_portals, three_quarters).cluster_count, 1u);
    three_quarters.max_extent = 1.5f; // the 2 x 2 union is too wide, so is the 2 x 1 box
    EXPECT_EQ(box_merge_clusters(l_shape, l_portals, three_quarters).cluster_count, 3u);
    three_quarters.max_extent = 0.0f;
    three_quarters.max_regions = 2;
    EXPECT_EQ(box_merge_clusters(l_shape, l_portals, three_quarters).cluster_of_region,
              (std::vector<uint32_t>{0, 0, 1}));
}

TEST(BoxClusters, BoxesThatDoNotShareAPortalOrAFullFaceStayApart)
{
    // 0 and 1 touch along x = 1 but 1 is taller: the union is not a box. 2 touches 0 but has no portal.
    const std::vector<Region> regions{box_region({0, 0, 0}, {1, 1, 1}), box_region({1, 0, 0}, {2, 1, 2}),
                                      box_region({0, 1, 0}, {1, 2, 1})};
    PortalSet portals;
    add_portal(portals, 0, 1);
    add_portal(portals, 0, 0);  // ignored: one region
    add_portal(portals, -1, 2); // ignored: out of range
    add_portal(portals, 2, 7);
    EXPECT_EQ(box_merge_clusters(regions, portals).cluster_count, 3u);
}

TEST(BoxClusters, GeneratedZoneClustersAreBoxesFilledByTheirRegions)
{
    gen::GenParams params;
    params.rooms = 60;
    params.seed = 2026;
    const Zone zone = gen::generate_zone(params);
    const PortalSet portals = build_zone_portals(zone);
    const RegionClusters clusters = box_merge_clusters(zone.regions, portals);
    ASSERT_EQ(clusters.cluster_of_region.size(), zone.region_count());
    EXPECT_LT(clusters.cluster_count, zone.region_count());

    // Independently: each cluster's bounding box volume equals the sum of its regions' volumes
    // (disjoint boxes filling a box), and a multi-region cluster has a portal inside it.
    std::map<uint32_t, Aabb> box;
    std::map<uint32_t, double> volume;
    std::map<uint32_t, int> members, inner_portals;
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const uint32_t c = clusters.cluster_of_region[r];
        ASSERT_LT(c, clusters.cluster_count);
        box[c].grow(zone.regions[r].bounds);
        const glm::vec3 size = zone.regions[r].bounds.max - zone.regions[r].bounds.min;
        volume[c] += double(size.x) * size.y * size.z;
        ++members[c];
    }
    for (const Portal& portal : portals.portals)
        if (clusters.cluster_of_region[size_t(portal.regions[0])] == clusters.cluster_of_region[size_t(portal.regions[1])])
            ++inner_portals[clusters.cluster_of_region[size_t(portal.regions[0])]];
    for (const auto& [c, b] : box) {
        const glm::vec3 size = b.max - b.min;
        EXPECT_NEAR(volume[c], double(size.x) * size.y * size.z, 1e-3 * volume[c]) << "cluster " << c;
        if (members[c] > 1) {
            EXPECT_GE(inner_portals[c], members[c] - 1) << "cluster " << c;
        }
    }
}

// A unit-square portal on the plane x = x0, spanning y and z in [0, 1].
void add_square_portal(PortalSet& set, int32_t a, int32_t b, float x0)
{
    Portal portal;
    portal.regions[0] = a;
    portal.regions[1] = b;
    portal.first_point = uint32_t(set.points.size());
    portal.point_count = 4;
    set.points.insert(set.points.end(), {{x0, 0, 0}, {x0, 1, 0}, {x0, 1, 1}, {x0, 0, 1}});
    set.portals.push_back(portal);
}

TEST(BoxClusters, RegionsAreBoxesWhenEveryPortalLiesOnTheFaceTwoBoxesShare)
{
    const std::vector<Region> touching{box_region({0, 0, 0}, {1, 1, 1}), box_region({1, 0, 0}, {2, 1, 1})};
    PortalSet portals;
    add_square_portal(portals, 0, 1, 1.0f);
    EXPECT_TRUE(regions_are_boxes(touching, portals));
    EXPECT_FALSE(regions_are_boxes(touching, PortalSet{})); // nothing to judge by

    PortalSet off_face; // the portal is not on the shared face x = 1
    add_square_portal(off_face, 0, 1, 0.5f);
    EXPECT_FALSE(regions_are_boxes(touching, off_face));

    // Bounds that overlap on every axis (as Quake leaves' boxes across a sloped portal do).
    const std::vector<Region> overlapping{box_region({0, 0, 0}, {1.5f, 1, 1}), box_region({1, 0, 0}, {2, 1, 1})};
    EXPECT_FALSE(regions_are_boxes(overlapping, portals));
}

TEST(BoxClusters, GeneratedZonesHaveBoxRegionsQuakeMapsDoNot)
{
    const Zone generated = gen::generate_zone({60, 2026, 32.0f});
    EXPECT_TRUE(regions_are_boxes(generated.regions, build_zone_portals(generated)));

    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    const Zone& e1m1 = *test::shared_zone("quake/e1m1.bsp");
    EXPECT_FALSE(regions_are_boxes(e1m1.regions, build_zone_portals(e1m1)));
}

} // namespace
} // namespace pvs
