// The raster baker (visibility/raster/): cube maps rendered on the CPU from points in each cell.
//  - known visibility on a hand-made OBJ of two closed rooms with a wall between: a cell inside a
//    room sees that room's object only; a cell in the rock between them has no point in open
//    space and an empty row, or, rendering every point as the HateEngine baker does, sees both
//    (through the walls' culled backs, or the backs themselves when drawn); and the
//    failure of the HateEngine lattice, built on it: its points on a cell's far faces sit on the
//    wall at x = 100 and see the other room through it;
//  - a lower bound: on a generated zone every raster row lies inside portal-full's (an upper
//    bound), and on every stability case nothing outside the truth (test_stability_cases.cpp);
//  - denser sampling only adds: more points per region, or a lattice step halved;
//  - deterministic for any thread count; cancel stops it;
//  - the two engines (pixel rays, the rasteriser) see the same faces but at triangle edges;
//  - translucent faces (Quake 2 glass) hide nothing: glass in room A's wall shows A room B's far
//    wall, while room B, whose own wall stays opaque, still sees only itself - both engines.
#include "tests/support/obj_boxes.h"
#include "visibility/bit_row.h"
#include "visibility/eval/pvs_gap.h"
#include "visibility/methods/vis_method.h"
#include "visibility/raster/raster_vis.h"
#include "visibility/raster/ray_cube.h"
#include "visibility/reference/mesh_tracer.h"
#include "gen/generate_zone.h"
#include "wld/obj/obj_reader.h"

#include <gtest/gtest.h>

#include <string>

namespace pvs {
namespace {


Zone two_rooms()
{
    const std::string text = test::two_closed_rooms_obj();
    Zone zone = read_obj_zone(std::vector<uint8_t>(text.begin(), text.end()), "two_rooms.obj");
    // Cells of 10 units (grid size 1): x cells 0..9 in A, 10 in the wall, 11..20 in B.
    zone.view_grid = grid_over_points(zone.mesh.positions, 10.0f, 1.0f);
    return zone;
}

std::vector<uint32_t> row_of(const Pvs& pvs, uint32_t cell)
{
    std::vector<uint64_t> row(pvs.words_per_row());
    pvs.decode_row(cell, row);
    std::vector<uint32_t> out;
    bits::for_each_set(row, [&](size_t r) { out.push_back(uint32_t(r)); });
    return out;
}

TEST(RasterVis, TwoRoomsAndAWall)
{
    const Zone zone = two_rooms();
    ASSERT_TRUE(zone.view_grid);
    const ViewGrid& grid = *zone.view_grid;
    ASSERT_EQ(grid.counts.x, 21u);
    RasterParams params;
    params.raster.resolution = 16;
    params.threads = 2;
    params.points_per_region = 8;
    const Pvs open_random = bake_raster_grid(zone, grid, params); // the default: points in open space
    params.lattice = Lattice::Centred;
    params.step = 5.0f; // the centre and 8 lattice points a cell
    const Pvs open_only = bake_raster_grid(zone, grid, params);
    params.open_space_only = false; // as the HateEngine baker: every point renders
    const Pvs with_culling = bake_raster_grid(zone, grid, params);
    params.lattice = Lattice::HateEngine;
    const Pvs hateengine = bake_raster_grid(zone, grid, params);
    params.lattice = Lattice::Centred;
    params.raster.cull_back_faces = false;
    const Pvs both_sides = bake_raster_grid(zone, grid, params);
    const std::vector<uint32_t> a{0}, b{1}, ab{0, 1};
    for (uint32_t cell = 0; cell < grid.cell_count(); ++cell) {
        const float x = grid.cell_bounds(cell).center().x;
        SCOPED_TRACE("cell " + std::to_string(cell) + " at x " + std::to_string(x));
        if (x < 100.0f) {
            EXPECT_EQ(row_of(open_random, cell), a);
            EXPECT_EQ(row_of(open_only, cell), a);
            EXPECT_EQ(row_of(with_culling, cell), a);
            EXPECT_EQ(row_of(both_sides, cell), a); // the room's own walls hide the other room
            // The last cells before the wall have lattice points on it: they see room B.
            EXPECT_EQ(row_of(hateengine, cell), x > 90.0f ? ab : a);
        } else if (x > 110.0f) {
            EXPECT_EQ(row_of(open_random, cell), b);
            EXPECT_EQ(row_of(open_only, cell), b);
            EXPECT_EQ(row_of(with_culling, cell), b);
        } else {
            // In the rock between the rooms: the rooms' walls turn their backs to it, so with
            // culling the eye looks through them at the floors and far walls inside; drawn,
            // the backs themselves are what it sees. Both rooms either way.
            EXPECT_EQ(row_of(with_culling, cell), ab);
            EXPECT_EQ(row_of(both_sides, cell), ab);
            EXPECT_TRUE(row_of(open_only, cell).empty()); // no point in open space: no camera
            EXPECT_TRUE(row_of(open_random, cell).empty());
        }
    }
}

TEST(RasterVis, ALowerBoundInsidePortalFull)
{
    const Zone zone = gen::generate_zone({12, 5});
    MethodSettings settings;
    settings.threads = 2;
    settings.raster_resolution = 32;
    settings.raster_points = 8;
    const MethodRun raster = find_vis_method("raster")->run(zone, settings);
    const MethodRun full = find_vis_method("portal-full")->run(zone, settings);
    ASSERT_TRUE(raster.pvs && full.pvs);
    const PvsGap gap = pvs_gap(&*raster.pvs, *full.pvs);
    EXPECT_EQ(gap.excess_bits, 0u) << "raster rows outside portal-full's";
    EXPECT_GT(gap.bits, uint64_t(zone.region_count()) * 2) << "it sees more than each region itself";
}

TEST(RasterVis, DenserSamplingOnlyAddsAndThreadsDoNotMatter)
{
    const Zone zone = gen::generate_zone({10, 7});
    RasterParams params;
    params.raster.resolution = 24;
    params.points_per_region = 3;
    params.threads = 1;
    const Pvs sparse = bake_raster_regions(zone, params);
    params.points_per_region = 9;
    const Pvs dense = bake_raster_regions(zone, params);
    params.threads = 2;
    const Pvs dense_two_threads = bake_raster_regions(zone, params);
    EXPECT_EQ(pvs_gap(&sparse, dense).excess_bits, 0u) << "a denser bake lost a region";
    const PvsGap same = pvs_gap(&dense_two_threads, dense);
    EXPECT_EQ(same.missing_bits + same.excess_bits, 0u);

    const Zone rooms = two_rooms();
    RasterParams lattice;
    lattice.raster.resolution = 16;
    lattice.lattice = Lattice::HateEngine; // offsets k * step: halving the step keeps every point
    lattice.step = 10.0f;                  // centre + far corner
    const Pvs coarse = bake_raster_grid(rooms, *rooms.view_grid, lattice);
    lattice.step = 5.0f; // holds those points and more
    const Pvs fine = bake_raster_grid(rooms, *rooms.view_grid, lattice);
    EXPECT_EQ(pvs_gap(&coarse, fine).excess_bits, 0u);
    EXPECT_EQ(grid_cell_points(*rooms.view_grid, 0, 5.0f).size(), 1u + 8u);
    EXPECT_EQ(grid_cell_points(*rooms.view_grid, 0, 0.0f).size(), 1u);
}

TEST(RasterVis, CancelStops)
{
    const Zone zone = gen::generate_zone({10, 7});
    RasterParams params;
    params.raster.resolution = 16;
    params.threads = 2;
    params.progress = [](double) { return false; };
    RasterReport report;
    bake_raster_regions(zone, params, &report);
    EXPECT_TRUE(report.cancelled);
    EXPECT_LT(report.cells, zone.region_count());
}

} // namespace
} // namespace pvs

namespace pvs {
namespace {

// The two engines draw the same pixel centres (ray_cube.h, cube_raster.h): the rasteriser by
// edge functions, the rays exactly. On a generated zone they must see the same faces but for
// pixels a triangle edge crosses, and give the same rows but for those; on the two rooms,
// where every face is large, the same rows exactly, with and without back faces, from a centred
// lattice that renders points in the rooms and in the rock (not the HateEngine lattice: its eyes
// sit exactly on a wall, where the near plane and the ray's start decide differently).
TEST(RasterEngines, RaysAndTheRasteriserSeeTheSameFaces)
{
    const Zone zone = gen::generate_zone({10, 3});
    const MeshTracer tracer(zone);
    CubeRasterOptions options;
    options.resolution = 48;
    CubeRaster raster(zone, options);
    RayCube rays(tracer, options);
    size_t both = 0, only_one = 0;
    for (uint32_t r = 0; r < zone.region_count(); r += 3) {
        const Aabb& box = zone.regions[r].bounds;
        const glm::vec3 eye = box.center();
        std::vector<uint8_t> a(zone.mesh.faces.size(), 0), b(zone.mesh.faces.size(), 0);
        raster.render(eye, a);
        rays.render(eye, b);
        for (size_t f = 0; f < a.size(); ++f) {
            both += a[f] && b[f] ? 1 : 0;
            only_one += a[f] != b[f] ? 1 : 0;
        }
    }
    ASSERT_GT(both, 50u);
    EXPECT_LE(double(only_one), 0.02 * double(both)) << only_one << " faces seen by one engine only, " << both
                                                     << " by both";

    const Zone rooms = two_rooms();
    for (bool cull : {true, false}) {
        RasterParams params;
        params.raster.resolution = 16;
        params.raster.cull_back_faces = cull;
        params.lattice = Lattice::Centred;
        params.step = 10.0f;
        params.open_space_only = false;
        params.engine = RasterEngine::Rays;
        const Pvs by_rays = bake_raster_grid(rooms, *rooms.view_grid, params);
        params.engine = RasterEngine::Rasteriser;
        const Pvs by_raster = bake_raster_grid(rooms, *rooms.view_grid, params);
        const PvsGap gap = pvs_gap(&by_rays, by_raster);
        EXPECT_EQ(gap.missing_bits + gap.excess_bits, 0u) << (cull ? "culling back faces" : "drawing back faces");
    }
}

// Room A's wall at x = 100 made glass (translucent); room B's wall at x = 110 stays opaque. From
// A the eye looks through its own wall, across the rock, at B's wall: A sees B. From B its own
// opaque wall hides A, and A's glass, facing away from B, is culled: B sees B only. Without the
// translucent material both rooms see themselves only (TwoRoomsAndAWall).
TEST(RasterVis, TranslucentFacesHideNothing)
{
    Zone zone = two_rooms();
    ASSERT_TRUE(zone.view_grid);
    Material glass;
    glass.name = "glass";
    glass.flags = kMaterialTranslucent;
    zone.materials.push_back(glass);
    // Room A is one face (one object, one material); its quad at x = 100 is written last, so
    // its last two triangles become a face of their own, in room A, made of glass.
    ASSERT_EQ(zone.region_count(), 2u);
    ASSERT_EQ(zone.faces_of_region(0).size(), 1u);
    Face& room_a = zone.mesh.faces[zone.faces_of_region(0)[0]];
    ASSERT_GE(room_a.triangle_count, 2u);
    Face wall{room_a.first_triangle + room_a.triangle_count - 2, 2, uint32_t(zone.materials.size() - 1)};
    for (uint32_t t = wall.first_triangle; t < wall.first_triangle + 2; ++t)
        for (uint32_t k = 0; k < 3; ++k)
            ASSERT_EQ(zone.mesh.positions[zone.mesh.indices[3 * t + k]].x, 100.0f) << "room A's wall at x = 100";
    room_a.triangle_count -= 2;
    zone.region_faces.insert(zone.region_faces.begin() + zone.region_face_offsets[1], uint32_t(zone.mesh.faces.size()));
    ++zone.region_face_offsets[1];
    ++zone.region_face_offsets[2];
    zone.mesh.faces.push_back(wall);
    ASSERT_EQ(translucent_face_mask(zone).size(), zone.mesh.faces.size());
    const ViewGrid& grid = *zone.view_grid;
    const std::vector<uint32_t> b{1}, ab{0, 1};
    for (RasterEngine engine : {RasterEngine::Rays, RasterEngine::Rasteriser}) {
        RasterParams params;
        params.raster.resolution = 16;
        params.points_per_region = 4;
        params.engine = engine;
        const Pvs pvs = bake_raster_grid(zone, grid, params);
        for (uint32_t cell = 0; cell < grid.cell_count(); ++cell) {
            const float x = grid.cell_bounds(cell).center().x;
            SCOPED_TRACE(std::string(engine == RasterEngine::Rays ? "rays" : "rasteriser") + ", cell at x " +
                         std::to_string(x));
            if (x < 100.0f) {
                EXPECT_EQ(row_of(pvs, cell), ab);
            } else if (x > 110.0f) {
                EXPECT_EQ(row_of(pvs, cell), b);
            }
        }
    }
}

} // namespace
} // namespace pvs
