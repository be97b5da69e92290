#include "wld/doom/doom_specials.h"

#include <algorithm>
#include <iterator>

namespace pvs::doom {

namespace {

// Vanilla Doom line types that act on the sector behind the line (manual doors).
constexpr uint16_t kManualDoors[] = {1, 26, 27, 28, 31, 32, 33, 34, 117, 118};

// Vanilla Doom line types that move the tagged sectors' floors or ceilings.
constexpr uint16_t kTaggedMovers[] = {
    // doors
    2, 3, 4, 16, 29, 42, 46, 50, 61, 63, 75, 76, 86, 90, 99, 103, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114,
    115, 116, 133, 134, 135, 136, 137,
    // floors and donuts
    5, 9, 14, 15, 18, 19, 20, 22, 23, 24, 30, 36, 37, 38, 45, 47, 55, 56, 58, 59, 60, 64, 65, 66, 67, 68, 69, 70, 71,
    82, 83, 84, 91, 92, 93, 94, 95, 96, 98, 101, 102, 119, 128, 129, 130, 131, 140,
    // lifts and perpetual platforms
    10, 21, 53, 62, 87, 88, 120, 121, 122, 123,
    // ceilings and crushers
    6, 25, 40, 41, 43, 44, 49, 72, 73, 77, 141,
    // stairs
    7, 8, 100, 127};

constexpr uint16_t kFirstGeneralized = 0x2F80; // Boom: crushers, stairs, lifts, doors, ceilings, floors

template <size_t N>
bool contains(const uint16_t (&list)[N], uint16_t special)
{
    return std::find(list, list + N, special) != list + N;
}

} // namespace

bool special_moves_heights(uint16_t special)
{
    return special >= kFirstGeneralized || contains(kManualDoors, special) || contains(kTaggedMovers, special);
}

std::vector<bool> moving_sectors(const DoomMap& map)
{
    std::vector<bool> moving(map.sectors.size(), false);
    for (size_t s = 0; s < map.sectors.size(); ++s)
        moving[s] = map.sectors[s].special == 10 || map.sectors[s].special == 14;
    for (const Linedef& line : map.linedefs) {
        if (!special_moves_heights(line.special))
            continue;
        if (contains(kManualDoors, line.special)) {
            if (line.side[1] >= 0)
                moving[map.sidedefs[size_t(line.side[1])].sector] = true;
            continue;
        }
        if (line.tag == 0)
            continue;
        for (size_t s = 0; s < map.sectors.size(); ++s)
            if (map.sectors[s].tag == line.tag)
                moving[s] = true;
    }
    return moving;
}

} // namespace pvs::doom
