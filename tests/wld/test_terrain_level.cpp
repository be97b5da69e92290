// Procedural outdoor zones (wld/gen/terrain_level.h, generate_outdoor_zone.h): the region tree as
// EverQuest's open zones (one region per open cell, none under the ground), a region count in
// the range the zone is meant for, terrain that really hides (checked by marching sight lines
// through the grid, written here), overhangs, liquids and zone lines where they were placed, and
// bad parameters refused.
#include "gen/generate_outdoor_zone.h"
#include "gen/terrain_level.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace pvs::gen {
namespace {

bool open(Cell c) { return c != Cell::Solid; }

TEST(TerrainLevel, SameParametersSameGridAndSeedsDiffer)
{
    const VoxelLevel a = make_terrain_level({64, 14, 7});
    const VoxelLevel b = make_terrain_level({64, 14, 7});
    const VoxelLevel c = make_terrain_level({64, 14, 8});
    EXPECT_EQ(a.cells, b.cells);
    EXPECT_NE(a.cells, c.cells);
}

TEST(TerrainLevel, GroundIsSolidBelowAndOverhangsExist)
{
    TerrainFeatures f;
    const VoxelLevel level = make_terrain_level({64, 14, 1}, &f);
    ASSERT_EQ(f.ground.size(), 64u * 64u);
    size_t open_under_solid = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const int ground = f.ground[size_t(y) * 64 + size_t(x)];
            ASSERT_GE(ground, 1);
            for (int z = 0; z < ground; ++z)
                ASSERT_EQ(level.at(x, y, z), Cell::Solid) << x << "," << y << "," << z;
            ASSERT_TRUE(open(level.at(x, y, ground)) || level.at(x, y, ground + 1) == Cell::Solid ||
                        ground >= f.town_lo.z)
                << "the first cell above the ground is open, but for walls and buildings";
            for (int z = ground; z + 1 < level.dims.z; ++z)
                open_under_solid += open(level.at(x, y, z)) && level.at(x, y, z + 1) == Cell::Solid ? 1 : 0;
        }
    // The bridge over the lake and the rock arch: open cells under solid ones.
    EXPECT_GT(open_under_solid, 25u);
    for (int x = f.arch_lo.x; x < f.arch_hi.x; ++x)
        EXPECT_EQ(level.at(x, f.arch_lo.y, f.arch_hi.z), Cell::Solid);
    EXPECT_GT(f.buildings, 0);
}

TEST(TerrainLevel, LiquidsAndZoneLinesWhereTheyWerePlaced)
{
    TerrainFeatures f;
    const VoxelLevel level = make_terrain_level({64, 14, 3}, &f);
    EXPECT_EQ(level.at(f.lake_center.x, f.lake_center.y, f.water_level - 1), Cell::Water);
    size_t lava = 0, zone_low = 0, zone_high = 0;
    for (int z = 0; z < level.dims.z; ++z)
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x)
                lava += level.at(x, y, z) == Cell::Lava ? 1 : 0;
            zone_low += level.at(0, y, z) == Cell::ZoneLine ? 1 : 0;
            zone_high += level.at(63, y, z) == Cell::ZoneLine ? 1 : 0;
        }
    EXPECT_GT(lava, 0u);
    EXPECT_GT(zone_low, 0u);
    EXPECT_GT(zone_high, 0u);
}

// A sight line between two cell centres is blocked when a point along it, marched in steps of a
// tenth of a cell, lies in a solid cell.
bool blocked(const VoxelLevel& level, glm::vec3 a, glm::vec3 b)
{
    const int steps = int(glm::length(b - a) * 10.0f) + 1;
    for (int i = 1; i < steps; ++i) {
        const glm::vec3 p = a + (b - a) * (float(i) / float(steps));
        if (level.at(int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z))) == Cell::Solid)
            return true;
    }
    return false;
}

// A sight line open by a margin: no point of the segment within `margin` (max-norm) of a solid
// cell. Exact, not sampled luck: samples every margin / 2 along it, each checked at the eight
// corners of a cube of half-side `margin`; a cube smaller than a cell that overlaps a solid cell
// has a corner inside it, and every point of the segment is within margin / 4 of a sample.
bool open_with_margin(const VoxelLevel& level, glm::vec3 a, glm::vec3 b, float margin = 0.05f)
{
    const int steps = int(glm::length(b - a) / (margin * 0.5f)) + 1;
    for (int i = 0; i <= steps; ++i) {
        const glm::vec3 p = a + (b - a) * (float(i) / float(steps));
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 q = p + margin * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
            if (level.at(int(std::floor(q.x)), int(std::floor(q.y)), int(std::floor(q.z))) == Cell::Solid)
                return false;
        }
    }
    return true;
}

TEST(TerrainLevel, HillsHideOnePartOfTheGroundFromAnother)
{
    TerrainFeatures f;
    const VoxelLevel level = make_terrain_level({64, 14, 1}, &f);
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> column(0, 63);
    int pairs = 0, hidden = 0;
    while (pairs < 400) {
        const int x0 = column(rng), y0 = column(rng), x1 = column(rng), y1 = column(rng);
        const int z0 = f.ground[size_t(y0) * 64 + size_t(x0)], z1 = f.ground[size_t(y1) * 64 + size_t(x1)];
        if (!open(level.at(x0, y0, z0)) || !open(level.at(x1, y1, z1)))
            continue;
        ++pairs;
        hidden += blocked(level, glm::vec3(x0, y0, z0) + 0.5f, glm::vec3(x1, y1, z1) + 0.5f) ? 1 : 0;
    }
    EXPECT_GT(hidden, pairs / 4) << "of ground cells a person stands in, many pairs cannot see each other";
    EXPECT_LT(hidden, pairs) << "and some can";
}

// Small zones squeeze every placement range (24 columns once crashed on an empty one): every
// size and seed gives a grid whose ground is solid below and that has the features.
TEST(TerrainLevel, EverySizeFromTheSmallestBuildsTheFeatures)
{
    for (int columns : {kMinTerrainColumns, 25, 27, 31, 40, 64, 100})
        for (uint64_t seed = 1; seed <= 6; ++seed) {
            TerrainFeatures f;
            const VoxelLevel level = make_terrain_level({columns, kMinTerrainHeight + int(seed % 3), seed}, &f);
            ASSERT_EQ(level.cells.size(), size_t(columns) * size_t(columns) * size_t(level.dims.z));
            size_t water = 0, open_cells = 0;
            for (Cell c : level.cells) {
                water += c == Cell::Water ? 1 : 0;
                open_cells += open(c) ? 1 : 0;
            }
            EXPECT_GT(water, 0u) << columns << " columns, seed " << seed;
            EXPECT_GT(open_cells, level.cells.size() / 4) << columns << " columns, seed " << seed;
            for (int y = 0; y < columns; ++y)
                for (int x = 0; x < columns; ++x)
                    ASSERT_EQ(level.at(x, y, 0), Cell::Solid) << "the bottom layer is ground";
        }
}

TEST(OutdoorZone, OneRegionPerOpenCellInTheIntendedRange)
{
    const Zone zone = generate_outdoor_zone({});
    const VoxelLevel level = make_terrain_level({64, 14, 1});
    size_t open_cells = 0;
    for (Cell c : level.cells)
        open_cells += open(c) ? 1 : 0;
    EXPECT_EQ(zone.region_count(), open_cells);
    EXPECT_GE(zone.region_count(), 10000u);
    EXPECT_LE(zone.region_count(), 40000u);
    size_t water = 0, lava = 0, zone_line = 0;
    for (const Region& r : zone.regions) {
        const glm::vec3 extent = r.bounds.max - r.bounds.min;
        ASSERT_FLOAT_EQ(extent.x, 64.0f);
        ASSERT_FLOAT_EQ(extent.y, 64.0f);
        ASSERT_FLOAT_EQ(extent.z, 64.0f);
        water += (r.flags & kRegionWater) ? 1 : 0;
        lava += (r.flags & kRegionLava) ? 1 : 0;
        zone_line += (r.flags & kRegionZoneLine) ? 1 : 0;
    }
    EXPECT_GT(water, 0u);
    EXPECT_GT(lava, 0u);
    EXPECT_GT(zone_line, 0u);
    EXPECT_FALSE(zone.baked_pvs);
}

// Baked (as `gen --outdoor` does), with the terrain method: every pair of cells whose centres see each
// other along a sight line open by a margin (checked through the grid here) has its bit.
TEST(OutdoorZone, BakedPvsHoldsEveryOpenSightLineAndSaysHowItWasMade)
{
    OutdoorParams p;
    p.size = 1536.0f; // 24 columns
    p.bake = true;
    const Zone zone = generate_outdoor_zone(p);
    ASSERT_TRUE(zone.baked_pvs);
    EXPECT_TRUE(std::any_of(zone.source.notes.begin(), zone.source.notes.end(), [](const std::string& n) {
        return n.find("PVS baked with terrain") != std::string::npos;
    }));
    const VoxelLevel level = make_terrain_level({24, p.height, p.seed});
    const glm::vec3 origin = -glm::vec3(level.dims) * p.cell_size * 0.5f * glm::vec3(1, 1, 0);
    std::mt19937 rng(9);
    std::uniform_int_distribution<size_t> region(0, zone.region_count() - 1);
    size_t open_lines = 0;
    for (int i = 0; i < 3000; ++i) {
        const size_t a = region(rng), b = region(rng);
        const glm::vec3 ca = (zone.regions[a].bounds.center() - origin) / p.cell_size;
        const glm::vec3 cb = (zone.regions[b].bounds.center() - origin) / p.cell_size;
        if (!open_with_margin(level, ca, cb))
            continue;
        ++open_lines;
        ASSERT_TRUE(zone.baked_pvs->visible(uint32_t(a), uint32_t(b))) << a << " sees " << b;
    }
    EXPECT_GT(open_lines, 100u);
}

TEST(OutdoorZone, BadParametersAreRefused)
{
    OutdoorParams p;
    p.cell_size = 0;
    EXPECT_THROW(generate_outdoor_zone(p), std::invalid_argument);
    p = {};
    p.size = 64.0f * 8; // 8 columns
    EXPECT_THROW(generate_outdoor_zone(p), std::invalid_argument);
    p = {};
    p.height = 3;
    EXPECT_THROW(generate_outdoor_zone(p), std::invalid_argument);
    EXPECT_THROW(make_terrain_level({1000, 14, 1}), std::invalid_argument);
}

} // namespace
} // namespace pvs::gen
