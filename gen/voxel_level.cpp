#include "gen/voxel_level.h"

#include <algorithm>
#include <glm/common.hpp>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace pvs::gen {

namespace {

constexpr int kRoomHeight = 3;  // open cells from floor to ceiling
constexpr int kFloorPitch = 4;  // cells from one floor level to the next (one solid slab between)
constexpr int kMargin = 1;      // solid cells around the world

struct Layout {
    VoxelLevel& level;
    std::mt19937_64& rng;

    int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    // One solid layer under floor 0 inside the margin, so pits and trenches can be dug into it.
    int floor_z(int floor) const { return kMargin + 1 + floor * kFloorPitch; }

    void carve(glm::ivec3 lo, glm::ivec3 hi, Cell content)
    {
        lo = glm::max(lo, glm::ivec3(kMargin));
        hi = glm::min(hi, level.dims - kMargin);
        for (int z = lo.z; z < hi.z; ++z)
            for (int y = lo.y; y < hi.y; ++y)
                for (int x = lo.x; x < hi.x; ++x)
                    level.set(x, y, z, content);
    }

    // Rooms by rejection sampling on each floor's free area (one solid cell between rooms).
    void place_rooms(int count)
    {
        std::vector<std::vector<uint8_t>> taken(size_t(level.floors),
                                                std::vector<uint8_t>(size_t(level.dims.x) * size_t(level.dims.y), 0));
        for (int attempts = 0; int(level.rooms.size()) < count && attempts < count * 200; ++attempts) {
            const int floor = int(level.rooms.size()) % level.floors;
            const glm::ivec3 size{uniform(2, 6), uniform(2, 6), kRoomHeight};
            const glm::ivec3 lo{uniform(kMargin + 1, level.dims.x - kMargin - 1 - size.x),
                                uniform(kMargin + 1, level.dims.y - kMargin - 1 - size.y), floor_z(floor)};
            auto& grid = taken[size_t(floor)];
            bool free = true;
            for (int y = lo.y - 1; y < lo.y + size.y + 1 && free; ++y)
                for (int x = lo.x - 1; x < lo.x + size.x + 1 && free; ++x)
                    free = grid[size_t(y) * size_t(level.dims.x) + size_t(x)] == 0;
            if (!free)
                continue;
            for (int y = lo.y; y < lo.y + size.y; ++y)
                for (int x = lo.x; x < lo.x + size.x; ++x)
                    grid[size_t(y) * size_t(level.dims.x) + size_t(x)] = 1;
            level.rooms.push_back({lo, lo + size, floor});
            carve(lo, lo + size, Cell::Air);
        }
    }

    // An L-shaped corridor, one cell wide and two high, from a's centre to b's centre.
    void corridor(glm::ivec3 a, glm::ivec3 b, Cell content = Cell::Air)
    {
        const int z = a.z;
        const bool x_first = uniform(0, 1) == 0;
        const glm::ivec3 bend = x_first ? glm::ivec3(b.x, a.y, z) : glm::ivec3(a.x, b.y, z);
        for (const auto& [from, to] : {std::pair{a, bend}, std::pair{bend, glm::ivec3(b.x, b.y, z)}}) {
            const glm::ivec3 lo = glm::min(from, to), hi = glm::max(from, to) + glm::ivec3(1, 1, 2);
            for (int zz = lo.z; zz < hi.z; ++zz)
                for (int y = lo.y; y < hi.y; ++y)
                    for (int x = lo.x; x < hi.x; ++x)
                        if (level.at(x, y, zz) == Cell::Solid)
                            carve({x, y, zz}, {x + 1, y + 1, zz + 1}, content);
        }
        ++level.corridors;
    }

    static glm::ivec3 centre(const Room& r) { return {(r.lo.x + r.hi.x) / 2, (r.lo.y + r.hi.y) / 2, r.lo.z}; }

    // Each room joins the nearest earlier room on its floor: every floor is connected.
    void connect_floors()
    {
        for (size_t i = 0; i < level.rooms.size(); ++i) {
            const Room& room = level.rooms[i];
            int best = -1;
            int best_distance = 1 << 30;
            for (size_t j = 0; j < i; ++j) {
                if (level.rooms[j].floor != room.floor)
                    continue;
                const glm::ivec3 d = centre(level.rooms[j]) - centre(room);
                const int distance = std::abs(d.x) + std::abs(d.y);
                if (distance < best_distance) {
                    best_distance = distance;
                    best = int(j);
                }
            }
            if (best >= 0)
                corridor(centre(room), centre(level.rooms[size_t(best)]));
        }
    }

    // Floors join through shafts (a hole through the slab into a corridor below) and stairs
    // (a flight of one-cell steps from the floor below up through the slab).
    void join_floors()
    {
        for (int floor = 1; floor < level.floors; ++floor) {
            std::vector<size_t> upper, lower;
            for (size_t i = 0; i < level.rooms.size(); ++i)
                (level.rooms[i].floor == floor ? upper : lower).push_back(i);
            std::erase_if(upper, [&](size_t i) { return level.rooms[i].floor != floor; });
            std::erase_if(lower, [&](size_t i) { return level.rooms[i].floor != floor - 1; });
            if (upper.empty() || lower.empty())
                continue;
            const int links = std::max(1, int(upper.size()) / 12);
            for (int k = 0; k < links; ++k) {
                const Room& top = level.rooms[upper[size_t(uniform(0, int(upper.size()) - 1))]];
                const Room& bottom = level.rooms[lower[size_t(uniform(0, int(lower.size()) - 1))]];
                const glm::ivec3 c = centre(top);
                if ((floor + k) % 2 == 1) {
                    // Shaft: open the slab and the cells below it, then reach it from the room below.
                    const glm::ivec3 below{c.x, c.y, floor_z(floor - 1)};
                    carve(below, {c.x + 1, c.y + 1, c.z}, Cell::Air);
                    corridor(centre(bottom), below);
                    ++level.shafts;
                } else {
                    // Stairs: steps rising one cell per cell along x, ending under the room above.
                    const int steps = kFloorPitch;
                    const glm::ivec3 foot{c.x - steps, c.y, floor_z(floor - 1)};
                    for (int s = 0; s <= steps; ++s)
                        carve({foot.x + s, foot.y, foot.z + s}, {foot.x + s + 1, foot.y + 1, foot.z + s + kRoomHeight - 1},
                              Cell::Air);
                    corridor(centre(bottom), foot);
                    ++level.stairs;
                }
            }
        }
    }

    // The features every demo zone shows, placed in the first rooms (rooms are random, so
    // these are random places).
    void add_features()
    {
        auto& rooms = level.rooms;
        // Water pool: the lowest layer of room 0.
        const Room& pool = rooms[0];
        carve(pool.lo, {pool.hi.x, pool.hi.y, pool.lo.z + 1}, Cell::Water);
        // Lava pit: a hole below the floor of room 1, one cell deep.
        const Room& pit = rooms[1];
        carve({pit.lo.x, pit.lo.y, pit.lo.z - 1}, {pit.lo.x + 2, pit.lo.y + 2, pit.lo.z}, Cell::Lava);
        // Slime channel: a trench along room 2's floor, one cell wide.
        const Room& channel = rooms[2];
        carve({channel.lo.x, channel.lo.y, channel.lo.z - 1}, {channel.hi.x, channel.lo.y + 1, channel.lo.z},
              Cell::Slime);
        // PvP arena: the largest room on floor 0 that holds no other feature.
        size_t arena = 3;
        for (size_t i = 3; i < rooms.size(); ++i) {
            const glm::ivec3 a = rooms[i].hi - rooms[i].lo, b = rooms[arena].hi - rooms[arena].lo;
            if (rooms[i].floor == 0 && a.x * a.y > b.x * b.y)
                arena = i;
        }
        carve(rooms[arena].lo, rooms[arena].hi, Cell::Pvp);
        // Zone line: a corridor from room 4 (or the last room) west to the edge of the world,
        // whose last cell is the zone line.
        const Room& exit = rooms[std::min<size_t>(4, rooms.size() - 1)];
        const glm::ivec3 start = centre(exit.floor == 0 ? exit : rooms[0]);
        const glm::ivec3 edge{kMargin, start.y, start.z};
        corridor(start, edge);
        carve(edge, edge + glm::ivec3(1, 1, 2), Cell::ZoneLine);
    }
};

} // namespace

VoxelLevel make_voxel_level(int rooms, uint64_t seed)
{
    if (rooms < kMinRooms || rooms > kMaxRooms)
        throw std::invalid_argument("rooms must be from " + std::to_string(kMinRooms) + " to " +
                                    std::to_string(kMaxRooms) + ", got " + std::to_string(rooms));
    std::mt19937_64 rng(seed);
    VoxelLevel level;
    level.floors = std::clamp(rooms / 20 + 1, 1, 4);
    // Each room needs about 40 cells of floor area with its surroundings; leave room to spare.
    const int per_floor = (rooms + level.floors - 1) / level.floors;
    const int side = std::max(14, int(std::ceil(std::sqrt(double(per_floor) * 40.0))));
    level.dims = {side + 2 * kMargin, side + 2 * kMargin, level.floors * kFloorPitch + 2 * kMargin + 1};
    level.cells.assign(size_t(level.dims.x) * size_t(level.dims.y) * size_t(level.dims.z), Cell::Solid);

    Layout layout{level, rng};
    layout.place_rooms(rooms);
    if (int(level.rooms.size()) < std::min(rooms, 5))
        throw std::logic_error("generator could not place the minimum number of rooms");
    layout.connect_floors();
    layout.join_floors();
    layout.add_features();
    return level;
}

} // namespace pvs::gen
