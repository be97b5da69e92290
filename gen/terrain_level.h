// The layout of a procedural outdoor zone, as EverQuest's open zones are built: a heightfield of
// hills and valleys on a grid of cubic cells (cells under the ground are solid), a walled town
// with hollow buildings, a lake (water) with a bridge over it, a lava pit, a rock arch (an
// overhang: open cells under solid ones) and zone lines along two opposite edges. Air fills the
// rest up to the top of the grid. Hills are high enough that one valley cannot see the next.
//
// Everything comes from the seed and the sizes: the same parameters always give the same grid.
#pragma once

#include "gen/voxel_level.h"

#include <glm/ext/vector_int2.hpp>
#include <vector>

#include <cstdint>

namespace pvs::gen {

struct TerrainParams {
    int columns = 64;  // cells along x and y
    int height = 14;   // cells along z (up)
    uint64_t seed = 1;
};

// What make_terrain_level placed, for reports and tests (cell coordinates).
struct TerrainFeatures {
    glm::ivec3 town_lo{0}, town_hi{0}; // the walled town's inside, open cells lo <= c < hi
    int buildings = 0;
    glm::ivec2 lake_center{0};
    int lake_radius = 0, water_level = 0;
    glm::ivec2 lava_center{0};
    int bridge_z = 0;           // the bridge's deck: solid cells at this z over the lake
    glm::ivec3 arch_lo{0}, arch_hi{0}; // the open cells under the rock arch
    std::vector<int> ground;    // per column (x + y * columns): the terrain's first open z (walls
                                // and buildings stand on it: their columns open higher)
};

inline constexpr int kMinTerrainColumns = 24;
inline constexpr int kMaxTerrainColumns = 512;
inline constexpr int kMinTerrainHeight = 10;
inline constexpr int kMaxTerrainHeight = 64;

// Throws std::invalid_argument when columns or height are outside their ranges above.
VoxelLevel make_terrain_level(const TerrainParams& params, TerrainFeatures* features = nullptr);

} // namespace pvs::gen
