// The layout of a procedural zone as a grid of cubic cells, each solid or open with a content
// (air, water, lava, slime, PvP arena, zone line). Rooms of varied size on a few floors,
// doorways, corridors, shafts and stairs between floors, a water pool, a lava pit, a slime
// channel, a PvP arena and a zone-line doorway at the edge of the world.
//
// Everything comes from the seed: the same (rooms, seed) always gives the same grid.
#pragma once

#include <cstdint>
#include <glm/ext/vector_int3.hpp>
#include <vector>

namespace pvs::gen {

enum class Cell : uint8_t { Solid = 0, Air, Water, Lava, Slime, Pvp, ZoneLine };

struct Room {
    glm::ivec3 lo, hi; // open cells lo <= c < hi
    int floor;
};

struct VoxelLevel {
    glm::ivec3 dims{0};
    std::vector<Cell> cells; // x fastest, then y, then z
    std::vector<Room> rooms;
    int floors = 0;
    int shafts = 0, stairs = 0, corridors = 0;

    size_t index(int x, int y, int z) const { return (size_t(z) * size_t(dims.y) + size_t(y)) * size_t(dims.x) + size_t(x); }
    Cell at(int x, int y, int z) const
    {
        if (x < 0 || y < 0 || z < 0 || x >= dims.x || y >= dims.y || z >= dims.z)
            return Cell::Solid;
        return cells[index(x, y, z)];
    }
    void set(int x, int y, int z, Cell c) { cells[index(x, y, z)] = c; }
};

inline constexpr int kMinRooms = 5;
inline constexpr int kMaxRooms = 5000;

// Throws std::invalid_argument when rooms is outside [kMinRooms, kMaxRooms].
VoxelLevel make_voxel_level(int rooms, uint64_t seed);

} // namespace pvs::gen
