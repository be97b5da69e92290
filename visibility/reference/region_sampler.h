// Uniform random points inside regions' volumes (not their bounding boxes): where the sampled
// reference (reference_vis.h) starts its sight lines.
//
// A region's volume is the union of its leaves' convex cells (bsp_volume.h, for_each_leaf_cell
// in the world box zone_portal_world). Each cell is cut into tetrahedra, a fan from the mean of
// its vertices over every face triangle; a point is drawn by picking a tetrahedron with
// probability proportional to its volume (a binary search in the region's cumulative volumes)
// and then a uniform point in it (the fold of the unit cube onto the tetrahedron of Rocchini and
// Cignoni, "Generating Random Points in a Tetrahedron", 2000). The cells are computed with
// kCellEpsilon, so a point may lie up to that far outside the exact volume: callers that need the
// point in the region check it (the reference rejects samples whose trace does not start there).
//
// Deterministic: point() is a pure function of the region and four numbers in [0, 1).
// Memory: 4 vertices (double) and a cumulative volume per tetrahedron; e1m1: about 30 000
// tetrahedra, 3 MB. Building walks every leaf cell once (e1m1: about 0.1 s).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs {

class RegionSampler {
public:
    RegionSampler() = default;
    explicit RegionSampler(const Zone& zone);

    size_t region_count() const { return region_first_.empty() ? 0 : region_first_.size() - 1; }
    // Whether the region has a volume to sample (regions the tree never reaches, or whose cells
    // are empty, have none).
    bool has_volume(uint32_t region) const { return region_first_[region] != region_first_[region + 1]; }
    double volume(uint32_t region) const;
    // A point of the region's volume from four uniform numbers in [0, 1): u0 picks the
    // tetrahedron, u1..u3 the point in it. Precondition: has_volume(region).
    glm::dvec3 point(uint32_t region, double u0, double u1, double u2, double u3) const;
    size_t memory_bytes() const
    {
        return tetrahedra_.capacity() * sizeof(Tetrahedron) + cumulative_.capacity() * sizeof(double) +
               region_first_.capacity() * sizeof(uint32_t);
    }

private:
    struct Tetrahedron {
        glm::dvec3 v[4];
    };
    std::vector<Tetrahedron> tetrahedra_;  // grouped by region
    std::vector<double> cumulative_;       // per tetrahedron: volume of its region's tetrahedra up to it
    std::vector<uint32_t> region_first_;   // region r owns tetrahedra [first[r], first[r+1])
};

} // namespace pvs
