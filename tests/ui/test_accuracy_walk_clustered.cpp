// Image-space accuracy of the clustered bake (visibility/portal/cluster_vis.h): a generated zone
// (60 rooms), its regions grouped into boxes (box_merge_clusters), portal-full baked over the
// clusters, then 1000 seeded cameras in playable space culled with pvs+frustum against the exact
// ID buffer of the whole zone (the rules of test_accuracy_walk_baked.cpp): no popping pixel that
// an exact ray confirms, and no more unconfirmed ones (cracks) than the leaf-level bake shows:
// the grouping kept every region a real sight line reaches. The ID buffer and the ray casts do
// not use the bake.
#include "render/accuracy_walk.h"
#include "visibility/eval/camera_set.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portalize.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

namespace pvs::ui {
namespace {

TEST(ClusteredPvsWalk, GeneratedZoneClusteredPortalFullNeverPops)
{
    gen::GenParams params;
    params.rooms = 60;
    params.seed = 2026;
    const Zone zone = gen::generate_zone(params);
    const PortalSet portals = build_zone_portals(zone);
    const RegionClusters clusters = box_merge_clusters(zone.regions, portals);
    ASSERT_LT(clusters.cluster_count * 3, zone.region_count() * 2); // a real grouping, not the identity

    VisParams vis;
    vis.method = VisParams::Method::Full;
    vis.threads = 1; // ctest runs tests in parallel already
    VisReport report;
    ClusterReport cluster_report;
    const Pvs baked = bake_clustered_portal_vis(portals, clusters.cluster_of_region, clusters.cluster_count, vis,
                                                &report, &cluster_report);
    ASSERT_FALSE(report.cancelled);
    ASSERT_GT(cluster_report.portals_inside_clusters, 0u);

    const std::vector<Camera> cameras = random_cameras_in_regions(zone, 1000, 2026, Camera{});
    ASSERT_EQ(cameras.size(), 1000u);
    const auto rows = run_accuracy_walk(zone, &baked, cameras, WalkOptions{});
    uint64_t covered = 0, popping = 0, confirmed = 0, culled_regions = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        covered += rows[i].accuracy.covered_pixels;
        popping += rows[i].accuracy.popping_pixels;
        confirmed += rows[i].popping_confirmed;
        culled_regions += rows[i].cull.regions_total - rows[i].cull.regions_after_pvs;
        EXPECT_EQ(rows[i].popping_confirmed, 0u)
            << "camera " << i << " at (" << rows[i].camera.position.x << "," << rows[i].camera.position.y << ","
            << rows[i].camera.position.z << ") yaw " << rows[i].camera.yaw_degrees << " pitch "
            << rows[i].camera.pitch_degrees << " region " << rows[i].cull.region;
    }
    // The rasteriser shows a few pixels through cracks in the generated mesh (no ray confirms
    // them); the leaf-level bake of the same zone shows them too. The clustered PVS, which holds
    // more, must not show more of them.
    const Pvs leaves = bake_portal_vis(portals, uint32_t(zone.region_count()), vis);
    uint64_t leaf_popping = 0, leaf_culled_regions = 0;
    for (const WalkRow& row : run_accuracy_walk(zone, &leaves, cameras, WalkOptions{})) {
        leaf_popping += row.accuracy.popping_pixels;
        leaf_culled_regions += row.cull.regions_total - row.cull.regions_after_pvs;
    }
    EXPECT_LE(popping, leaf_popping);
    EXPECT_LT(culled_regions, leaf_culled_regions); // the grouping's price: it culls less
    EXPECT_EQ(confirmed, 0u);
    EXPECT_GT(covered, 1000u * 320u * 240u / 2u); // the cameras really saw the level
    EXPECT_GT(culled_regions, 0u);                // and the PVS really culled something
}

} // namespace
} // namespace pvs::ui
