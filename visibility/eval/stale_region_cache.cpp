#include "visibility/eval/stale_region_cache.h"

#include <glm/geometric.hpp>

namespace pvs {

StaleRegionCache::StaleRegionCache(const Zone& zone, float refresh_distance)
    : locator_(zone.tree, zone.bounds()), refresh_distance_(refresh_distance)
{
}

int32_t StaleRegionCache::region(const glm::vec3& position)
{
    // The client compares squared distances; the same test, written plainly.
    if (valid_ && glm::distance(position, walked_at_) < refresh_distance_)
        return region_;
    region_ = locator_.locate(position).region;
    walked_at_ = position;
    valid_ = true;
    ++walks_;
    return region_;
}

} // namespace pvs
