// Uniform random points on portals, and which portals each region has: the second sampler of the
// reference (reference_vis.h). Lines drawn through a point on a portal of A and a point on a
// portal of B are the natural sight lines between two rooms (they pass their doorways), so they
// find thin lines of sight far sooner than lines from random points in the rooms' volumes.
//
// A portal's polygon is cut into a triangle fan; point() picks a triangle with probability
// proportional to its area and a uniform point in it. Portals with a region out of range, one
// region on both sides, fewer than three points or no area are left out (no links, no points).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace pvs {

class PortalSampler {
public:
    struct Link {
        uint32_t portal; // index into the PortalSet
        uint32_t other;  // the region on the other side
    };

    PortalSampler() = default;
    PortalSampler(const PortalSet& portals, uint32_t region_count);

    // The usable portals of a region and the regions behind them, in portal order.
    std::span<const Link> links(uint32_t region) const
    {
        return std::span<const Link>(links_).subspan(link_first_[region], link_first_[region + 1] - link_first_[region]);
    }
    // A point of the portal from three uniform numbers in [0, 1). Precondition: the portal is
    // one of links()' portals.
    glm::dvec3 point(uint32_t portal, double u0, double u1, double u2) const;
    size_t memory_bytes() const;

private:
    std::vector<Link> links_;
    std::vector<uint32_t> link_first_;      // per region + 1
    std::vector<uint32_t> triangle_first_;  // per portal + 1: its fan triangles
    std::vector<glm::dvec3> triangles_;     // three corners per fan triangle
    std::vector<double> cumulative_area_;   // per fan triangle, within its portal
};

} // namespace pvs
