// Image-space accuracy of pvscope's own PVS: on every Quake map in ../shared/data, portals
// built from the map's tree (build_zone_portals, ericw's default sky rule), portal-full baked
// (level 4), then 2000 seeded cameras (1000 under the sanitizers, where this suite is most of the
// test run's time; the sanitizers check memory, the camera count the sweep) at 640x480 in playable space (the same camera rules and the same
// sight-line confirmation through the tree as test_accuracy_walk.cpp, where the reasons are written down) culled
// with pvs+frustum against the exact ID buffer of the whole zone: no pixel may pop. The bake is
// the thing under test; the ID buffer and the ray casts do not use it.
#include "tests/support/test_data.h"
#include "render/accuracy_walk.h"
#include "visibility/eval/camera_set.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"

#include <gtest/gtest.h>

#include <string>

namespace pvs::ui {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr size_t kCameras = 1000;
#else
constexpr size_t kCameras = 2000;
#endif

class BakedPvsWalk : public testing::TestWithParam<const char*> {};

TEST_P(BakedPvsWalk, PortalFullNeverPopsOnTheSeededCameras)
{
    const std::string map = std::string("quake/") + GetParam() + ".bsp";
    SHARED_DATA_OR_SKIP(path, map);
    const Zone& zone = *test::shared_zone(map);

    VisParams params;
    params.method = VisParams::Method::Full;
    params.threads = 1; // ctest runs tests in parallel already
    VisReport report;
    const Pvs baked = bake_portal_vis(build_zone_portals(zone), uint32_t(zone.region_count()), params, &report);
    ASSERT_FALSE(report.cancelled);
    ASSERT_GT(report.portals, 0u);

    Camera lens;
    lens.aspect = 640.0f / 480.0f;
    const std::vector<Camera> cameras = random_cameras_in_regions(zone, kCameras, 2026, lens);
    ASSERT_EQ(cameras.size(), kCameras);
    WalkOptions options;
    options.width = 640;
    options.height = 480;
    const auto rows = run_accuracy_walk(zone, &baked, cameras, options);
    uint64_t covered = 0, confirmed = 0, culled_regions = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        covered += rows[i].accuracy.covered_pixels;
        confirmed += rows[i].popping_confirmed;
        culled_regions += rows[i].cull.regions_total - rows[i].cull.regions_after_pvs;
        EXPECT_EQ(rows[i].popping_confirmed, 0u)
            << map << " camera " << i << " at (" << rows[i].camera.position.x << "," << rows[i].camera.position.y
            << "," << rows[i].camera.position.z << ") yaw " << rows[i].camera.yaw_degrees << " pitch "
            << rows[i].camera.pitch_degrees << " region " << rows[i].cull.region;
    }
    EXPECT_EQ(confirmed, 0u);
    EXPECT_GT(covered, kCameras * 640u * 480u / 2u); // the cameras really saw the level
    EXPECT_GT(culled_regions, 0u);                // and the PVS really culled something
}

INSTANTIATE_TEST_SUITE_P(QuakeMaps, BakedPvsWalk, testing::Values("e1m1", "e1m2", "e2m1", "start", "end", "dm2"),
                         [](const testing::TestParamInfo<const char*>& map) { return std::string(map.param); });

} // namespace
} // namespace pvs::ui
