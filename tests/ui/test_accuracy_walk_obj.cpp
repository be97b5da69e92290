// Exact popping on a zone without a tree (an OBJ level): the sight line of a popping pixel is
// traced against the mesh with Embree (sight_check.h), and cameras go where the mesh says open
// space is (camera_set.h). On the two closed rooms of tests/support/obj_boxes.h:
//  - with a PVS whose every cell row is empty, everything a camera in a room sees pops, and every
//    popping pixel is confirmed (its line meets that face first, from the front): no crack;
//  - with every row full, nothing pops;
//  - every random camera stands inside one of the rooms, never in the rock between.
#include "tests/support/obj_boxes.h"
#include "render/accuracy_walk.h"
#include "render/method_compare.h"
#include "visibility/eval/camera_set.h"
#include "wld/obj/obj_reader.h"

#include <gtest/gtest.h>

namespace pvs::ui {
namespace {

Zone rooms_with_grid()
{
    const std::string text = test::two_closed_rooms_obj();
    Zone zone = read_obj_zone(std::vector<uint8_t>(text.begin(), text.end()), "rooms.obj");
    zone.view_grid = grid_over_points(zone.mesh.positions, 10.0f, 1.0f);
    return zone;
}

TEST(AccuracyWalkObj, EmptyRowsPopEverythingAndEveryPixelIsConfirmed)
{
    const Zone zone = rooms_with_grid();
    ASSERT_TRUE(zone.view_grid);
    const auto cells = uint32_t(zone.view_grid->cell_count());
    const Pvs empty = Pvs::build_rows(cells, 2, [](uint32_t, std::span<uint64_t>) { return true; });
    const Pvs full = Pvs::build_rows(cells, 2, [](uint32_t, std::span<uint64_t> row) {
        row[0] = 3;
        return true;
    });
    Camera lens;
    lens.aspect = 4.0f / 3.0f;
    const std::vector<Camera> cameras = random_cameras_in_regions(zone, 20, 3, lens);
    ASSERT_EQ(cameras.size(), 20u);
    for (const Camera& c : cameras)
        EXPECT_TRUE(c.position.x < 100.0f || c.position.x > 110.0f) << "a camera in the rock";
    WalkOptions options;
    options.width = 64;
    options.height = 48;
    const auto empty_rows = run_accuracy_walk(zone, &empty, cameras, options);
    const auto full_rows = run_accuracy_walk(zone, &full, cameras, options);
    for (size_t i = 0; i < cameras.size(); ++i) {
        EXPECT_EQ(empty_rows[i].accuracy.covered_pixels, 64u * 48u) << i; // inside a closed room
        EXPECT_EQ(empty_rows[i].accuracy.popping_pixels, empty_rows[i].accuracy.covered_pixels) << i;
        EXPECT_EQ(empty_rows[i].popping_confirmed, empty_rows[i].accuracy.popping_pixels) << i;
        EXPECT_EQ(empty_rows[i].popping_cracks, 0u) << i;
        EXPECT_EQ(full_rows[i].accuracy.popping_pixels, 0u) << i;
    }
}

// `pvscope compare` on a zone without a tree: every method that needs none, against the mesh
// reference, with cameras and exact popping; the raster, a lower bound, misses only what the
// reference found and it did not, and adds nothing in two closed rooms.
TEST(AccuracyWalkObj, CompareRunsTheMethodsThatNeedNoTree)
{
    const Zone zone = rooms_with_grid();
    CompareOptions options;
    options.reference_samples = 1024;
    options.cameras = 6;
    options.width = 32;
    options.height = 24;
    options.threads = 2;
    const CompareResult result = run_compare(zone, options);
    ASSERT_FALSE(result.cancelled);
    EXPECT_EQ(result.cameras, 6u);
    bool raster = false;
    for (const CompareRow& row : result.rows) {
        EXPECT_NE(row.method, "portal-fast");
        EXPECT_NE(row.method, "portal-full");
        EXPECT_NE(row.method, "clustered");
        if (row.method == "raster") {
            raster = true;
            EXPECT_EQ(row.excess_bits, 0u) << row.params;
        }
    }
    EXPECT_TRUE(raster);
}

} // namespace
} // namespace pvs::ui
