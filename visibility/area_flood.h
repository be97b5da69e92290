// Quake 2's area culling, the engine's "areabits": a map is cut into areas by its areaportals
// (func_areaportal: doors), and when a door shuts its areaportal, the engine draws nothing of an
// area that no chain of open areaportals links to the camera's area, whatever the PVS says (vis
// itself sees through every areaportal). Zone::region_areas and Zone::area_portals carry them
// (Quake 2 maps only; other zones have none and nothing is dropped).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

// Per area (the highest area any region or areaportal names, plus one): 1 when open areaportals
// join it to `from_area`. `closed[p]` is 1 for a closed Zone::area_portals[p] (missing entries
// count as open). A `from_area` outside the areas reaches every area: nothing is dropped.
std::vector<uint8_t> areas_reached(const Zone& zone, int32_t from_area, std::span<const uint8_t> closed);

// Keeps, in order, the regions of `regions` whose area `reached` holds (regions without an area,
// or areas past its end, are kept). Returns how many were dropped.
size_t keep_reached_areas(const Zone& zone, std::span<const uint8_t> reached, std::vector<uint32_t>& regions);

} // namespace pvs
