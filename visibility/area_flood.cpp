#include "visibility/area_flood.h"

#include <algorithm>

namespace pvs {

std::vector<uint8_t> areas_reached(const Zone& zone, int32_t from_area, std::span<const uint8_t> closed)
{
    int32_t highest = -1;
    for (int32_t area : zone.region_areas)
        highest = std::max(highest, area);
    for (const AreaPortal& portal : zone.area_portals)
        highest = std::max({highest, portal.areas[0], portal.areas[1]});
    const size_t areas = size_t(highest + 1);
    if (from_area < 0 || size_t(from_area) >= areas)
        return std::vector<uint8_t>(areas, 1);
    std::vector<uint8_t> reached(areas, 0);
    reached[size_t(from_area)] = 1;
    // Few areas and portals (Quake 2's limits: 256 and 1024): sweep until nothing changes.
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t p = 0; p < zone.area_portals.size(); ++p) {
            if (p < closed.size() && closed[p])
                continue;
            const AreaPortal& portal = zone.area_portals[p];
            if (portal.areas[0] < 0 || portal.areas[1] < 0)
                continue;
            uint8_t& a = reached[size_t(portal.areas[0])];
            uint8_t& b = reached[size_t(portal.areas[1])];
            if (a != b) {
                a = b = 1;
                grew = true;
            }
        }
    }
    return reached;
}

size_t keep_reached_areas(const Zone& zone, std::span<const uint8_t> reached, std::vector<uint32_t>& regions)
{
    const size_t before = regions.size();
    std::erase_if(regions, [&](uint32_t r) {
        if (r >= zone.region_areas.size())
            return false;
        const int32_t area = zone.region_areas[r];
        return area >= 0 && size_t(area) < reached.size() && !reached[size_t(area)];
    });
    return before - regions.size();
}

} // namespace pvs
