// The ground truth of grid zones (visibility/reference/mesh_reference.h, mesh_tracer.h): sight
// lines against the mesh with Embree in robust mode.
//  - two closed rooms with rock between (a hand-made OBJ): a cell inside a room sees that room
//    only, a cell in the rock has no point in open space and an empty row;
//  - on the HateEngine E1M1 level: e1m1's start (inside) is in open space, a point under the
//    floor is not; a line from inside never meets a back face first;
//  - the registry's "reference" on a grid zone is this one, and more rays only add.
#include "tests/support/test_data.h"
#include "tests/support/obj_boxes.h"
#include "visibility/bit_row.h"
#include "visibility/eval/pvs_gap.h"
#include "visibility/methods/vis_method.h"
#include "visibility/reference/mesh_reference.h"
#include "visibility/reference/mesh_tracer.h"
#include "wld/obj/obj_reader.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace pvs::test {
namespace {


TEST(MeshReference, TwoClosedRoomsSeeOnlyThemselves)
{
    const std::string text = two_closed_rooms_obj();
    Zone zone = read_obj_zone(std::vector<uint8_t>(text.begin(), text.end()), "rooms.obj");
    zone.view_grid = grid_over_points(zone.mesh.positions, 10.0f, 1.0f);
    ASSERT_TRUE(zone.view_grid);
    MeshReferenceParams params;
    params.points_per_cell = 8;
    params.rays_per_point = 64;
    params.threads = 2;
    MeshReferenceReport report;
    const Pvs rows = bake_mesh_reference_grid(zone, *zone.view_grid, params, &report);
    ASSERT_EQ(rows.row_count(), zone.view_grid->cell_count());
    std::vector<uint64_t> row(rows.words_per_row());
    for (uint32_t cell = 0; cell < rows.row_count(); ++cell) {
        const float x = zone.view_grid->cell_bounds(cell).center().x;
        rows.decode_row(cell, row);
        const bool a = bits::test(row, 0), b = bits::test(row, 1);
        if (x < 100.0f)
            EXPECT_TRUE(a && !b) << "cell " << cell;
        else if (x > 110.0f)
            EXPECT_TRUE(b && !a) << "cell " << cell;
        else
            EXPECT_FALSE(a || b) << "cell " << cell << " in the rock";
    }
    EXPECT_EQ(report.open_cells, 20u * 5u * 10u); // every cell of both rooms, none of the rock
}

TEST(MeshReference, E1m1ObjOpenSpaceAndFrontHits)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.obj");
    const Zone zone = load_zone(path);
    const MeshTracer tracer(zone);
    EXPECT_EQ(tracer.triangle_count(), zone.mesh.triangle_count());
    EXPECT_TRUE(tracer.in_open_space({480.0f, -352.0f, 88.0f}));  // e1m1's start
    EXPECT_FALSE(tracer.in_open_space({480.0f, -352.0f, 40.0f})); // under its floor (z 64)
    const MeshTracer::Hit down = tracer.first_hit({480.0f, -352.0f, 88.0f}, {0.0f, 0.0f, -1.0f},
                                                  std::numeric_limits<float>::infinity());
    ASSERT_TRUE(down.hit);
    EXPECT_TRUE(down.front);
    EXPECT_NEAR(down.t, 24.0f, 1e-3f);
}

TEST(MeshReference, RegistryReferenceOnAGridZoneAndMoreRaysOnlyAdd)
{
    SHARED_DATA_OR_SKIP(path, "hateengine/E1M1.obj");
    const Zone zone = load_zone(path);
    const VisMethod& reference = *find_vis_method("reference");
    MethodSettings settings;
    settings.threads = 2;
    settings.samples = 256; // 16 points a cell, 16 rays each
    const MethodRun coarse = reference.run(zone, settings);
    settings.samples = 1024; // the same 16 points, 64 rays each: the first 16 directions included
    const MethodRun fine = reference.run(zone, settings);
    ASSERT_TRUE(coarse.pvs && fine.pvs);
    EXPECT_EQ(coarse.pvs->row_count(), zone.view_grid->cell_count());
    EXPECT_EQ(pvs_gap(&*coarse.pvs, *fine.pvs).excess_bits, 0u);
    EXPECT_GT(pvs_gap(&*fine.pvs, *fine.pvs).bits, pvs_gap(&*coarse.pvs, *coarse.pvs).bits);
}

} // namespace
} // namespace pvs::test
