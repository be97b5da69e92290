#include "visibility/portal/box_clusters.h"

#include <algorithm>
#include <cmath>

namespace pvs {
namespace {

double box_volume(const Aabb& box)
{
    const glm::vec3 size = glm::max(box.size(), glm::vec3(0.0f));
    return double(size.x) * double(size.y) * double(size.z);
}

class BoxMerger {
public:
    BoxMerger(const std::vector<Region>& regions, const BoxClusterOptions& options)
        : options_(options), union_(regions.size()), box_(regions.size()), volume_(regions.size()),
          members_(regions.size(), 1)
    {
        for (size_t r = 0; r < regions.size(); ++r) {
            box_[r] = regions[r].bounds;
            volume_[r] = box_volume(regions[r].bounds);
        }
    }

    // One pass over the portals; true when something merged.
    bool pass(const PortalSet& portals)
    {
        bool merged = false;
        for (const Portal& portal : portals.portals) {
            const int32_t a = portal.regions[0], b = portal.regions[1];
            if (a < 0 || b < 0 || size_t(a) >= union_.size() || size_t(b) >= union_.size())
                continue;
            merged = try_merge(union_.find(uint32_t(a)), union_.find(uint32_t(b))) || merged;
        }
        return merged;
    }

    RegionClusters clusters() { return union_.clusters(); }

private:
    bool try_merge(uint32_t a, uint32_t b)
    {
        if (a == b)
            return false;
        if (options_.max_regions != 0 && members_[a] + members_[b] > options_.max_regions)
            return false;
        Aabb u = box_[a];
        u.grow(box_[b]);
        const glm::vec3 extent = u.size();
        if (options_.max_extent > 0.0f &&
            (extent.x > options_.max_extent || extent.y > options_.max_extent || extent.z > options_.max_extent))
            return false;
        const double filled = volume_[a] + volume_[b];
        if (filled < double(options_.min_fill) * box_volume(u) * (1.0 - 1e-4))
            return false;
        const uint32_t root = union_.join_roots(a, b), child = root == a ? b : a;
        box_[root] = u;
        volume_[root] = filled;
        members_[root] += members_[child];
        return true;
    }

    BoxClusterOptions options_;
    RegionUnion union_;
    std::vector<Aabb> box_;
    std::vector<double> volume_;
    std::vector<uint32_t> members_;
};

bool inside(const Aabb& box, const glm::vec3& p, float tolerance)
{
    for (int a = 0; a < 3; ++a)
        if (p[a] < box.min[a] - tolerance || p[a] > box.max[a] + tolerance)
            return false;
    return true;
}

// The axis on which the boxes touch (overlap within tolerance), or -1.
int touching_axis(const Aabb& a, const Aabb& b, float tolerance)
{
    for (int axis = 0; axis < 3; ++axis) {
        const float overlap = std::min(a.max[axis], b.max[axis]) - std::max(a.min[axis], b.min[axis]);
        if (std::abs(overlap) <= tolerance)
            return axis;
    }
    return -1;
}

bool portal_between_boxes(const std::vector<Region>& regions, const PortalSet& portals, const Portal& portal,
                          float tolerance)
{
    const Aabb& a = regions[size_t(portal.regions[0])].bounds;
    const Aabb& b = regions[size_t(portal.regions[1])].bounds;
    if (a.empty() || b.empty() || size_t(portal.first_point) + portal.point_count > portals.points.size())
        return false;
    const int axis = touching_axis(a, b, tolerance);
    if (axis < 0)
        return false;
    const float plane = std::max(a.min[axis], b.min[axis]);
    for (uint32_t i = 0; i < portal.point_count; ++i) {
        const glm::vec3& p = portals.points[portal.first_point + i];
        if (std::abs(p[axis] - plane) > tolerance || !inside(a, p, tolerance) || !inside(b, p, tolerance))
            return false;
    }
    return true;
}

} // namespace

bool regions_are_boxes(const std::vector<Region>& regions, const PortalSet& portals, float tolerance)
{
    if (portals.portals.empty())
        return false;
    for (const Portal& portal : portals.portals) {
        const int32_t a = portal.regions[0], b = portal.regions[1];
        if (a < 0 || b < 0 || size_t(a) >= regions.size() || size_t(b) >= regions.size() || a == b)
            continue;
        if (!portal_between_boxes(regions, portals, portal, tolerance))
            return false;
    }
    return true;
}

RegionClusters box_merge_clusters(const std::vector<Region>& regions, const PortalSet& portals,
                                  const BoxClusterOptions& options)
{
    BoxMerger merger(regions, options);
    for (int pass = 0; pass < 64 && merger.pass(portals); ++pass) {
    }
    return merger.clusters();
}

} // namespace pvs
