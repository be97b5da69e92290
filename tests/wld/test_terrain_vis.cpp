// The terrain method (visibility/terrain/terrain_vis.h) on zones whose ground is known: the
// heightfield equals the generator's ground, the PVS holds every sight line found open through
// the voxel grid (exact marching, written here, from corners and inner points of the cells), it
// hides what a wall hides and nothing on flat ground, it is symmetric and the same on any thread
// count, and a zone without a tree is refused.
#include "visibility/bit_row.h"
#include "visibility/geometry/region_boxes.h"
#include "visibility/reference/reference_vis.h"
#include "visibility/terrain/terrain_heightfield.h"
#include "visibility/terrain/terrain_vis.h"
#include "gen/generate_outdoor_zone.h"
#include "gen/grid_axes.h"
#include "gen/grid_zone.h"
#include "gen/terrain_level.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace pvs {
namespace {

using gen::Cell;
using gen::VoxelLevel;

constexpr float kCell = 64.0f;

// One region per open cell, as EverQuest's trees and `gen --outdoor`.
Zone zone_of(const VoxelLevel& level, glm::vec3 origin = glm::vec3(0.0f))
{
    std::vector<uint32_t> labels(level.cells.size());
    std::iota(labels.begin(), labels.end(), 0u);
    return gen::build_grid_zone(level, gen::uniform_grid_axes(level.dims, kCell, origin), labels);
}

// Whether the segment (in cell units) stays out of the solid's inside, marched every 1/200 of a
// cell. A sample is inside the solid when every cell whose closed box holds it is solid (on a face
// between two solid cells it is inside; on the face of one solid cell and an open one it is not).
// Marching can step over a corner of solid thinner than the step, so this errs towards "open",
// the side a PVS must hold anyway.
bool open_line(const VoxelLevel& level, glm::dvec3 a, glm::dvec3 b)
{
    const int steps = int(glm::length(b - a) * 200.0) + 2;
    for (int i = 1; i < steps; ++i) {
        const glm::dvec3 p = a + (b - a) * (double(i) / steps);
        int lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            const double r = std::round(p[k]);
            const bool on_face = std::abs(p[k] - r) < 1e-9;
            lo[k] = on_face ? int(r) - 1 : int(std::floor(p[k]));
            hi[k] = on_face ? int(r) : lo[k];
        }
        bool solid = true;
        for (int z = lo[2]; z <= hi[2] && solid; ++z)
            for (int y = lo[1]; y <= hi[1] && solid; ++y)
                for (int x = lo[0]; x <= hi[0] && solid; ++x)
                    solid = level.at(x, y, z) == Cell::Solid;
        if (solid)
            return false;
    }
    return true;
}

// A point of the region's cell (cell units): a corner of its top face half the time (the points
// that see furthest over a hill), else anywhere in it.
glm::dvec3 point_in(const Region& r, glm::vec3 origin, std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 lo = glm::dvec3((r.bounds.min - origin) / kCell);
    if (rng() % 2)
        return lo + glm::dvec3(double(rng() % 2), double(rng() % 2), 1.0);
    return lo + glm::dvec3(unit(rng), unit(rng), unit(rng));
}

TEST(TerrainHeightfield, EqualsTheGridsGround)
{
    const VoxelLevel level = gen::make_terrain_level({24, 12, 3});
    const glm::vec3 origin(-768.0f, -768.0f, 0.0f);
    const Zone zone = zone_of(level, origin);
    const std::vector<Aabb> boxes = region_volume_boxes(zone.tree, zone.region_count(), zone.bounds());
    for (size_t r = 0; r < zone.region_count(); ++r) {
        ASSERT_EQ(boxes[r].min, zone.regions[r].bounds.min) << "an axis tree gives the leaf box exactly";
        ASSERT_EQ(boxes[r].max, zone.regions[r].bounds.max);
    }
    const Heightfield field = zone_heightfield(zone.tree, boxes);
    ASSERT_EQ(field.columns_x, 24u);
    ASSERT_EQ(field.columns_y, 24u);
    EXPECT_EQ(field.cell_x, 64.0);
    // The first open cell of each column, counted in the grid (walls and buildings included).
    std::vector<int> ground(24 * 24, 0);
    int lowest = 1 << 30;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            int z = 0;
            while (z < level.dims.z && level.at(x, y, z) == Cell::Solid)
                ++z;
            ground[size_t(y * 24 + x)] = z;
            lowest = std::min(lowest, z);
        }
    EXPECT_EQ(field.floor, lowest * 64.0);
    for (uint32_t y = 0; y < 24; ++y)
        for (uint32_t x = 0; x < 24; ++x)
            ASSERT_EQ(field.height(x, y), std::max(lowest, ground[y * 24 + x]) * 64.0) << x << "," << y;
}

TEST(TerrainVis, HoldsEverySightLineOpenThroughTheGrid)
{
    const VoxelLevel level = gen::make_terrain_level({24, 12, 5});
    const glm::vec3 origin(0.0f);
    const Zone zone = zone_of(level, origin);
    TerrainVisReport report;
    const Pvs pvs = bake_terrain_vis(zone, {}, &report);
    ASSERT_EQ(pvs.region_count(), zone.region_count());
    std::mt19937 rng(11);
    std::uniform_int_distribution<size_t> region(0, zone.region_count() - 1);
    size_t open_pairs = 0, hidden = 0, pairs = 0;
    for (int i = 0; i < 6000; ++i) {
        const size_t a = region(rng), b = region(rng);
        ++pairs;
        hidden += !pvs.visible(uint32_t(a), uint32_t(b));
        for (int tries = 0; tries < 4; ++tries) {
            const glm::dvec3 pa = point_in(zone.regions[a], origin, rng), pb = point_in(zone.regions[b], origin, rng);
            if (open_line(level, pa, pb)) {
                ++open_pairs;
                ASSERT_TRUE(pvs.visible(uint32_t(a), uint32_t(b)))
                    << a << " sees " << b << " along an open line from (" << pa.x << ", " << pa.y << ", " << pa.z
                    << ") to (" << pb.x << ", " << pb.y << ", " << pb.z << ")";
                break;
            }
        }
    }
    EXPECT_GT(open_pairs, 1000u);
    EXPECT_GT(hidden, pairs / 20) << "the hills hide something";
    EXPECT_GT(report.mean_visible, 0.0);
}

TEST(TerrainVis, AWallHidesTheGroundBehindItAndNotTheSkyAboveIt)
{
    VoxelLevel level;
    level.dims = {20, 6, 10};
    level.cells.assign(size_t(20) * 6 * 10, Cell::Air);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 20; ++x) {
            level.set(x, y, 0, Cell::Solid);
            for (int z = 0; z < 6 && x == 10; ++z)
                level.set(x, y, z, Cell::Solid);
        }
    const Zone zone = zone_of(level);
    const Pvs pvs = bake_terrain_vis(zone, {});
    auto region_at = [&](int x, int y, int z) {
        const glm::vec3 c = (glm::vec3(x, y, z) + 0.5f) * kCell;
        for (size_t r = 0; r < zone.region_count(); ++r)
            if (zone.regions[r].bounds.contains(c))
                return uint32_t(r);
        return UINT32_MAX;
    };
    // Every line between cells whose tops are below the wall's (cells z <= 4, tops <= 5 < 6) on
    // either side crosses x in (10, 11) below the wall's top: hidden, whatever the method's slack.
    for (int z = 1; z <= 4; ++z)
        for (int x = 0; x < 10; ++x)
            for (int x2 = 11; x2 < 20; ++x2)
                ASSERT_FALSE(pvs.visible(region_at(x, 2, z), region_at(x2, 3, std::min(4, z + x2 % 3))))
                    << x << "," << z << " -> " << x2;
    // Above the wall's top, the two sides see each other.
    EXPECT_TRUE(pvs.visible(region_at(2, 2, 8), region_at(17, 2, 8)));
    EXPECT_TRUE(pvs.visible(region_at(0, 0, 1), region_at(9, 5, 1)));
    EXPECT_TRUE(pvs.visible(region_at(2, 2, 1), region_at(17, 2, 9))) << "over the wall, from the ground to the sky";
}

TEST(TerrainVis, FlatGroundHidesNothing)
{
    VoxelLevel level;
    level.dims = {16, 12, 6};
    level.cells.assign(size_t(16) * 12 * 6, Cell::Air);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x)
            level.set(x, y, 0, Cell::Solid);
    const Zone zone = zone_of(level);
    TerrainVisReport report;
    bake_terrain_vis(zone, {}, &report);
    EXPECT_EQ(report.mean_visible, double(zone.region_count()));
}

TEST(TerrainVis, SymmetricAndTheSameOnAnyThreadCount)
{
    const Zone zone = zone_of(gen::make_terrain_level({24, 10, 9}));
    TerrainVisParams one, three;
    one.threads = 1;
    three.threads = 3;
    const Pvs a = bake_terrain_vis(zone, one), b = bake_terrain_vis(zone, three);
    std::vector<uint64_t> ra(a.words_per_row()), rb(b.words_per_row());
    size_t hidden = 0;
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        std::fill(ra.begin(), ra.end(), 0);
        std::fill(rb.begin(), rb.end(), 0);
        a.decode_row(r, ra);
        b.decode_row(r, rb);
        ASSERT_EQ(ra, rb) << "row " << r;
        for (uint32_t c = 0; c < zone.region_count(); ++c) {
            hidden += !bits::test(ra, c);
            ASSERT_EQ(bits::test(ra, c), a.visible(c, r)) << r << "," << c;
        }
    }
    EXPECT_GT(hidden, 0u);
}

TEST(TerrainVis, ProgressCanCancelAndAZoneWithoutATreeIsRefused)
{
    const Zone zone = zone_of(gen::make_terrain_level({24, 10, 2}));
    TerrainVisParams params;
    params.progress = [](double) { return false; };
    TerrainVisReport report;
    bake_terrain_vis(zone, params, &report);
    EXPECT_TRUE(report.cancelled);
    Zone no_tree;
    no_tree.regions.resize(3);
    EXPECT_THROW(bake_terrain_vis(no_tree, {}), std::invalid_argument);
}

// The sampled reference (an independent computation: sight lines traced through the tree) finds
// nothing the terrain method hides, on a small zone open to the sky and at its edges, where the
// tree's leaves run on past the zone: lines count only inside the world box, for both.
// The small zone with a ridge, a hill and a gap, open at its top and edges.
VoxelLevel ridge_level()
{
    VoxelLevel level;
    level.dims = {12, 10, 7};
    level.cells.assign(size_t(12) * 10 * 7, Cell::Air);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x) {
            const int ground = 1 + (x == 6 && y != 2 ? 4 : 0) + ((x - 2) * (x - 2) + (y - 7) * (y - 7) < 3 ? 2 : 0);
            for (int z = 0; z < ground; ++z)
                level.set(x, y, z, Cell::Solid);
        }
    return level;
}

// Every bit the reference finds is in the PVS; returns the bits the PVS hides.
size_t expect_holds_the_reference(const Zone& zone, const Pvs& terrain, const Pvs& reference)
{
    std::vector<uint64_t> t(terrain.words_per_row()), r(reference.words_per_row());
    size_t hidden = 0;
    for (uint32_t a = 0; a < zone.region_count(); ++a) {
        terrain.decode_row(a, t);
        reference.decode_row(a, r);
        for (uint32_t b = 0; b < zone.region_count(); ++b) {
            hidden += !bits::test(t, b);
            EXPECT_FALSE(bits::test(r, b) && !bits::test(t, b)) << "the reference sees " << a << " -> " << b;
        }
    }
    return hidden;
}

// Regions of many sizes (the tree's merged boxes, as real zones have): sources grown to powers of
// two; and a parent-table budget too small for the grid, which coarsens it. Both stay conservative.
TEST(TerrainVis, RegionsOfManySizesAndACoarsenedGridHoldTheReference)
{
    const VoxelLevel level = ridge_level();
    const Zone zone = gen::build_grid_zone(level, gen::uniform_grid_axes(level.dims, kCell, glm::vec3(0.0f)));
    ASSERT_LT(zone.region_count(), size_t(12) * 10 * 6) << "merged regions";
    ReferenceParams reference_params;
    reference_params.seed = 5;
    const Pvs reference = bake_reference_vis(zone, reference_params);
    TerrainVisReport fine, coarse;
    const Pvs fine_pvs = bake_terrain_vis(zone, {}, &fine);
    EXPECT_GT(fine.footprint_sizes, 1u);
    expect_holds_the_reference(zone, fine_pvs, reference); // merged air boxes reach over the ridge: little hides
    TerrainVisParams tight;
    tight.table_budget_bytes = 4096;
    const Pvs coarse_pvs = bake_terrain_vis(zone, tight, &coarse);
    EXPECT_LT(coarse.columns_x, fine.columns_x) << "the grid coarsened";
    expect_holds_the_reference(zone, coarse_pvs, reference);
}

TEST(TerrainVis, HoldsEveryPairTheReferenceFinds)
{
    const Zone zone = zone_of(ridge_level());
    TerrainVisReport report;
    const Pvs terrain = bake_terrain_vis(zone, {}, &report);
    ReferenceParams params;
    params.seed = 3;
    const Pvs reference = bake_reference_vis(zone, params);
    size_t found = 0;
    std::vector<uint64_t> r(reference.words_per_row());
    for (uint32_t a = 0; a < zone.region_count(); ++a) {
        reference.decode_row(a, r);
        found += bits::count(r);
    }
    const size_t hidden = expect_holds_the_reference(zone, terrain, reference);
    EXPECT_GT(hidden, 1000u) << "the ridge hides something";
    EXPECT_GT(found, hidden) << "and the reference found sight lines";
}

} // namespace
} // namespace pvs
