// The regression net for the culler's speed (tests/baselines/cull_work.tsv, tests/support/
// work_baseline.h): its counted work per frame (row words read, block boxes decided, region boxes
// tested: visibility/cull_work.h) summed over 300 seeded cameras in regions, on every shared
// Quake level with its own PVS, the demo zone and the default outdoor zone. A count is the same on
// any machine, so a rise more than 5 % above the baseline is a slower culler, whatever the clock.
// The answers themselves are checked against brute force elsewhere (test_culler.cpp).
#include "tests/support/test_data.h"
#include "tests/support/work_baseline.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
#include "gen/generate_outdoor_zone.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

namespace {

using namespace pvs;

// As `pvscope walk --cameras 300`: seed 1, 70 degrees, 4:3.
test::WorkCounts cull_work(const Zone& zone)
{
    Camera lens;
    lens.fov_y_degrees = 70.0f;
    lens.aspect = 4.0f / 3.0f;
    const std::vector<Camera> cameras = random_cameras_in_regions(zone, 300, 1, lens);
    Culler culler(zone, zone.baked_pvs ? &*zone.baked_pvs : nullptr);
    std::vector<uint32_t> visible;
    CullOptions options;
    options.time_stages = false;
    CullWork total;
    uint64_t drawn = 0;
    for (const Camera& camera : cameras) {
        const CullStats stats = culler.cull(camera, options, visible);
        total += stats.work;
        drawn += stats.regions_after_frustum;
    }
    return {{"row_words", total.row_words}, {"blocks", total.blocks}, {"boxes", total.boxes}, {"drawn", drawn}};
}

class SharedLevelCullWork : public testing::TestWithParam<const char*> {};

TEST_P(SharedLevelCullWork, WithinBaseline)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone* zone = test::shared_zone(GetParam());
    ASSERT_NE(zone, nullptr);
    ASSERT_TRUE(zone->baked_pvs.has_value());
    test::check_work("cull_work.tsv", GetParam(), cull_work(*zone));
}

INSTANTIATE_TEST_SUITE_P(SharedLevels, SharedLevelCullWork,
                         testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp",
                                         "quake/start.bsp", "quake/end.bsp", "modern-quake/q1/lqdm5.ericw-vis.bsp"),
                         [](const testing::TestParamInfo<const char*>& p) { return test::param_name(p.param); });

TEST(CullWork, DemoZoneWithinBaseline)
{
    const Zone zone = gen::generate_zone(gen::demo_zone_params());
    test::check_work("cull_work.tsv", "demo zone", cull_work(zone));
}

TEST(CullWork, OutdoorZoneWithinBaseline)
{
    gen::OutdoorParams params;
    params.bake = true;
    const Zone zone = gen::generate_outdoor_zone(params);
    test::check_work("cull_work.tsv", "outdoor zone", cull_work(zone));
}

} // namespace
