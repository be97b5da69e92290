// The camera -> region cache of an existing EverQuest client, kept as a baseline to measure
// against: it walks the BSP tree only when the camera has moved at least `refresh_distance`
// units (5 in that client) from where it last walked, and otherwise keeps the old region. Cheap,
// and wrong for every frame after the camera crosses a split plane until it has gone 5 units
// further: the frame is culled with the old region's PVS row, so regions the new one sees pop.
// pvscope's own culler has no such cache (culler.h: every frame walks the tree); `pvscope walk
// --region-cache 5` measures the popping this one causes over a walk (docs/stability.md).
//
// Not thread-safe; one per moving camera.
#pragma once

#include "visibility/region_locator.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace pvs {

class StaleRegionCache {
public:
    StaleRegionCache(const Zone& zone, float refresh_distance);

    // The region the cache gives for `position` (kLeafSolid / kLeafOutside when the last walk
    // found none), walking the tree only on the first call and after a move of refresh_distance.
    int32_t region(const glm::vec3& position);
    uint64_t walks() const { return walks_; }

private:
    RegionLocator locator_;
    float refresh_distance_;
    bool valid_ = false;
    glm::vec3 walked_at_{0.0f};
    int32_t region_ = kLeafOutside;
    uint64_t walks_ = 0;
};

} // namespace pvs
