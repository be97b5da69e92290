// The grid-accelerated locator must give exactly the plain walk's answer: on random points,
// on points exactly on cell boundaries and split planes, outside the grid, and for NaN.
#include "tests/support/test_data.h"
#include "visibility/region_locator.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pvs {
namespace {

class Locator : public ::testing::TestWithParam<const char*> {};

TEST_P(Locator, AgreesWithThePlainWalkEverywhere)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone zone = load_zone(path);
    const Aabb box = zone.bounds();
    const RegionLocator locator(zone.tree, box);
    EXPECT_GT(locator.mean_skipped_depth(), 1.0);

    std::mt19937 rng(3);
    // Sample a little beyond the bounds so points outside the grid are covered too.
    const glm::vec3 pad = box.size() * 0.05f;
    std::uniform_real_distribution<float> ux(box.min.x - pad.x, box.max.x + pad.x),
        uy(box.min.y - pad.y, box.max.y + pad.y), uz(box.min.z - pad.z, box.max.z + pad.z);
    for (int i = 0; i < 200000; ++i) {
        glm::vec3 p{ux(rng), uy(rng), uz(rng)};
        if (i % 4 == 1)
            p = glm::round(p / 16.0f) * 16.0f; // on the grid lines of a 16-unit map: split planes and cell edges
        const PointLocation expected = locate_point(zone.tree, p), got = locator.locate(p);
        ASSERT_EQ(got.leaf, expected.leaf) << "point " << i << " (" << p.x << "," << p.y << "," << p.z << ")";
    }
    // Points on the planes of the tree itself.
    for (const BspNode& node : zone.tree.nodes) {
        const glm::vec3 on_plane = node.normal * node.dist;
        ASSERT_EQ(locator.locate(on_plane).leaf, locate_point(zone.tree, on_plane).leaf);
    }
    const glm::vec3 nan{std::nanf(""), 0.0f, 0.0f};
    EXPECT_EQ(locator.locate(nan).leaf, locate_point(zone.tree, nan).leaf);
}

INSTANTIATE_TEST_SUITE_P(SharedData, Locator,
                         ::testing::Values("quake/e1m1.bsp", "quake/dm2.bsp", "quake/end.bsp", "visdemo/example.bsp"),
                         [](const ::testing::TestParamInfo<const char*>& param) { return test::param_name(param.param); });

TEST(LocatorEdgeCases, EmptyBoundsAndLeafRootFallBackToTheWalk)
{
    BspTree tree;
    tree.nodes.push_back({{0.0f, 0.0f, 1.0f}, 5.0f, {~1, ~0}});
    tree.leaf_region = {kLeafSolid, 0};
    tree.root = 0;
    const RegionLocator no_grid(tree, Aabb{});
    EXPECT_EQ(no_grid.locate({0, 0, 6}).region, 0);
    EXPECT_EQ(no_grid.locate({0, 0, 5}).region, kLeafSolid); // on the plane: back (Quake rule)
    Aabb box;
    box.grow({-10, -10, -10});
    box.grow({10, 10, 10});
    const RegionLocator grid(tree, box, 1000);
    for (float z = -10.0f; z <= 10.0f; z += 0.25f)
        ASSERT_EQ(grid.locate({1, 1, z}).region, locate_point(tree, {1, 1, z}).region) << z;
}

} // namespace
} // namespace pvs
