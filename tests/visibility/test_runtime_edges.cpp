// Runtime failure modes, on the crafted door-8 case (wld/gen/stability_cases.h:
// room A x in [0, 128], doorway D x in [128, 136] y in [60, 68], room B x in [136, 264], open
// from z = 0 to 96; its tree sends points on a plane to the high side, TieRule::OnPlaneGoesFront):
// every odd camera gets a defined result, stated in culler.h, and never an empty frame.
//  - exactly on a split plane inside the doorway (a portal): the high side's region, D;
//  - exactly on a wall's face, inside the wall, outside the world, at NaN: not in a region, the
//    PVS stage skipped, every region handed to the frustum;
//  - in a region whose row is empty: that region alone;
//  - crossing a plane between two frames: the second frame is culled from the new region (no
//    cache), while the 5-unit stale cache of an EverQuest client keeps the old one until the
//    camera has gone 5 units from where it last walked the tree;
//  - a forced region out of range: not in a region.
// And the portal walk (camera_set.h) that `walk --path portals` measures the stale cache on.
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
#include "visibility/eval/stale_region_cache.h"
#include "visibility/portal/portalize.h"
#include "visibility/region_lookup.h"
#include "gen/stability_cases.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <limits>
#include <set>

namespace pvs::test {
namespace {

class RuntimeEdges : public ::testing::Test {
protected:
    void SetUp() override
    {
        c_ = gen::make_stability_case("door-8");
        for (uint32_t r = 0; r < c_.region_names.size(); ++r)
            index_[c_.region_names[r]] = int32_t(r);
    }
    int32_t region(const std::string& name) const { return index_.at(name); }
    CullStats cull(const glm::vec3& at, const Pvs* pvs, std::vector<uint32_t>& visible, CullOptions options = {})
    {
        Camera camera = c_.camera;
        camera.position = at;
        Culler culler(c_.zone, pvs);
        return culler.cull(camera, options, visible);
    }

    gen::StabilityCase c_;
    std::map<std::string, int32_t> index_;
};

TEST_F(RuntimeEdges, OnASplitPlaneInADoorwayTheHighSideWins)
{
    std::vector<uint32_t> visible;
    const CullStats on_portal = cull({128.0f, 64.0f, 48.0f}, &c_.truth, visible);
    EXPECT_EQ(on_portal.camera, CameraPlace::InRegion);
    EXPECT_EQ(on_portal.region, region("D"));
    EXPECT_TRUE(on_portal.pvs_used);
    const CullStats on_far_portal = cull({136.0f, 64.0f, 48.0f}, &c_.truth, visible);
    EXPECT_EQ(on_far_portal.region, region("B"));
}

TEST_F(RuntimeEdges, NotInARegionSkipsThePvsAndDrawsWhatTheFrustumKeeps)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<uint32_t> visible;
    for (const glm::vec3& at : {glm::vec3(128.0f, 20.0f, 48.0f), // on the wall's face: the wall's side
                                glm::vec3(132.0f, 20.0f, 48.0f), // inside the wall
                                glm::vec3(1.0e6f, 0.0f, 0.0f),   // outside the world
                                glm::vec3(nan, 0.0f, 0.0f)}) {
        const CullStats s = cull(at, &c_.truth, visible, {CullMode::Pvs});
        EXPECT_NE(s.camera, CameraPlace::InRegion) << at.x << "," << at.y;
        EXPECT_EQ(s.region, -1);
        EXPECT_FALSE(s.pvs_used);
        EXPECT_EQ(visible.size(), c_.zone.regions.size()); // mode Pvs: nothing left to cull it
    }
}

TEST_F(RuntimeEdges, AnEmptyRowStillDrawsTheCamerasRegion)
{
    const auto regions = uint32_t(c_.zone.regions.size());
    const Pvs empty = Pvs::build(regions, [](uint32_t, std::span<uint64_t>) { return true; });
    std::vector<uint32_t> visible;
    const CullStats s = cull({64.0f, 64.0f, 48.0f}, &empty, visible, {CullMode::Pvs});
    EXPECT_TRUE(s.pvs_used);
    EXPECT_EQ(s.regions_after_pvs, 1u);
    EXPECT_EQ(visible, std::vector<uint32_t>{uint32_t(region("A"))});
}

TEST_F(RuntimeEdges, CrossingAPlaneBetweenFramesSwitchesRowsAtOnceButNotThroughAStaleCache)
{
    std::vector<uint32_t> visible;
    const glm::vec3 before(127.99f, 64.0f, 48.0f), after(128.01f, 64.0f, 48.0f), later(133.0f, 64.0f, 48.0f);
    Culler culler(c_.zone, &c_.truth);
    Camera camera = c_.camera;
    camera.position = before;
    EXPECT_EQ(culler.cull(camera, {}, visible).region, region("A"));
    camera.position = after;
    EXPECT_EQ(culler.cull(camera, {}, visible).region, region("D"));

    StaleRegionCache cache(c_.zone, 5.0f);
    EXPECT_EQ(cache.region(before), region("A"));
    EXPECT_EQ(cache.region(after), region("A")); // moved 0.02: the stale region
    EXPECT_EQ(cache.walks(), 1u);
    EXPECT_EQ(cache.region(later), region("D")); // 5.01 from where it walked: walks again
    EXPECT_EQ(cache.walks(), 2u);

    CullOptions forced;
    forced.forced_region = region("A");
    camera.position = after;
    EXPECT_EQ(culler.cull(camera, forced, visible).region, region("A"));
    forced.forced_region = 99;
    const CullStats out_of_range = culler.cull(camera, forced, visible);
    EXPECT_EQ(out_of_range.camera, CameraPlace::Outside);
    EXPECT_FALSE(out_of_range.pvs_used);
}

// The portal walk: every camera in a region, `step` apart along each leg (never more), and every
// region of the chain-20 case (a corridor of 20 pieces between two rooms) visited.
TEST(PortalWalk, StepsThroughEveryRegionInOpenSpace)
{
    const gen::StabilityCase c = gen::make_stability_case("chain-20");
    const PortalSet portals = build_zone_portals(c.zone);
    const std::vector<Camera> cameras = cameras_along_portals(c.zone, portals, 2.0f, 100000, 7, Camera{});
    ASSERT_GT(cameras.size(), 100u);
    std::set<int32_t> visited;
    for (size_t i = 0; i < cameras.size(); ++i) {
        const PointLocation at = locate_point(c.zone.tree, cameras[i].position);
        ASSERT_TRUE(at.in_region()) << i;
        visited.insert(at.region);
        if (i > 0) {
            EXPECT_LE(glm::distance(cameras[i].position, cameras[i - 1].position), 2.0f + 1e-3f) << i;
        }
    }
    EXPECT_EQ(visited.size(), c.zone.regions.size());
    EXPECT_EQ(cameras_along_portals(c.zone, portals, 2.0f, 10, 7, Camera{}).size(), 10u);
    EXPECT_TRUE(cameras_along_portals(c.zone, PortalSet{}, 2.0f, 10, 7, Camera{}).empty());
}

} // namespace
} // namespace pvs::test
