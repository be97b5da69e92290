// The ground truth of grid zones (visibility/reference/mesh_reference.h, mesh_tracer.h): sight
// lines against the mesh with Embree in robust mode.
//  - two closed rooms with rock between (a hand-made OBJ): a cell inside a room sees that room
//    only, a cell in the rock has no point in open space and an empty row;
//  - on the HateEngine E1M1 level: e1m1's start (inside) is in open space, a point under the
//    floor is not; a line from inside never meets a back face first;
//  - the registry's "reference" on a grid zone is this one, and more rays only add.
#include "tests/support/test_data.h"
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

// Six inward faces of a box (zone coordinates), written y-up as OBJ files are.
std::string closed_box(const std::string& name, const glm::vec3& lo, const glm::vec3& hi, int& first_vertex)
{
    std::string text = "o " + name + "\n";
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    for (const glm::vec3& p : c)
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.z) + " " + std::to_string(-p.y) + "\n";
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
    for (const auto& q : quads)
        text += "f " + std::to_string(first_vertex + q[0]) + " " + std::to_string(first_vertex + q[1]) + " " +
                std::to_string(first_vertex + q[2]) + " " + std::to_string(first_vertex + q[3]) + "\n";
    first_vertex += 8;
    return text;
}

TEST(MeshReference, TwoClosedRoomsSeeOnlyThemselves)
{
    int v = 1;
    std::string text = closed_box("room_a", {0, 0, 0}, {100, 100, 50}, v);
    text += closed_box("room_b", {110, 0, 0}, {210, 100, 50}, v);
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
