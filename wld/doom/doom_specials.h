// Which sectors of a Doom map move (doors, lifts, floors, ceilings, crushers, stairs): the ones
// whose heights as built do not hold while the map is played, so a PVS that lets heights block
// sight (`bake --heights`) is only safe where none of them matters.
//
// A sector moves when it is the back sector of a manual door line (specials 1, 26-28, 31-34,
// 117, 118: they act on the sector behind the line), the tagged sector (tag != 0) of a line
// whose special moves a floor or ceiling (vanilla Doom's door, lift, floor, ceiling, crusher,
// stair and donut types; every Boom generalized type, specials 0x2F80 and up), or has sector
// special 10 or 14 (a door that closes after 30 s / opens after 5 min). Approximations, on the
// side of the sectors named: stairs (7, 8, 100, 127) and donuts (9) also move the sectors next to
// the tagged one, which are not followed here; a special that only changes light or texture is
// not counted.
#pragma once

#include "wld/doom/doom_map.h"

#include <vector>

namespace pvs::doom {

// True when linedef special `special` moves a floor or a ceiling.
bool special_moves_heights(uint16_t special);

// One flag per sector of `map`.
std::vector<bool> moving_sectors(const DoomMap& map);

} // namespace pvs::doom
