// The portal graph of the portal-vis baker (portal_vis.h, "Input"): directed portals, their
// points, and the portals leaving each region.
//
// Contract. build_graph turns a PortalSet in PRT1 orientation into 2 directed portals per usable
// input portal: 2i leads into regions[1], 2i+1 into regions[0], so the twin of d is d ^ 1 and
// every directed plane's normal points into the region the portal leads to. Unusable portals
// (portal_vis.h lists the reasons) are skipped and counted in Graph::skipped. The graph owns
// every point (as doubles, the backward portal's points reversed) and never changes after
// build_graph, so the threads of the bake share it read-only.
//
// Layout, after ericw-tools vis: directed portals in one array, their points in one array, the
// portals leaving each region as compressed rows (leaf_first / leaf_portals, in directed-index
// order, as ericw's leaf lists).
#pragma once

#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs::portal_vis {

// ericw-tools vis constants (§3.7).
constexpr double kOnEpsilon = 0.1;            // VIS_ON_EPSILON: side tests, clips, separators
// A clip drops a winding only when no point of it is more than this in front (flow_frame.h);
// one with points only up to ON_EPSILON in front is kept whole. Below the reference's beam
// margin (kBeamMargin, 0.05): a sight line the reference proves passes at least that far in
// front of every plane that bounds it, so no such line is lost; above the float noise of
// points on a shared edge (~1e-3), so walks do not go on through windings that only touch.
constexpr double kDropEpsilon = 0.02;
constexpr double kEqualEpsilon = 0.001;       // VIS_EQUAL_EPSILON: coplanar exit, per component
constexpr double kCoplanarFacing = -0.99;     // base vis: coplanar portals facing each other
constexpr double kSeparatorMinLengthSq = 0.1; // ClipToSeparators: unnormalised |cross|^2

using Vec = glm::dvec3;

struct DPlane {
    Vec normal{0.0};
    double dist = 0.0;
    double distance(const Vec& p) const { return glm::dot(normal, p) - dist; }
    DPlane flipped() const { return {-normal, -dist}; }
};

struct DirectedPortal {
    DPlane plane;    // normal into `leaf`
    Vec origin{0.0}; // bounding sphere of the winding: centre = mean of the points
    double radius = 0.0;
    uint32_t first_point = 0;
    uint32_t point_count = 0;
    uint32_t leaf = 0;  // the region it leads into
    uint32_t owner = 0; // the region it leaves
};

struct Graph {
    uint32_t leaf_count = 0;
    size_t words = 0;
    std::vector<DirectedPortal> portals;
    std::vector<Vec> points;
    std::vector<uint32_t> leaf_first; // leaf_count + 1 offsets into leaf_portals
    std::vector<uint32_t> leaf_portals;
    // Per entry of leaf_portals, the region that portal leads into: a flood skips most portals
    // by it (their region is reached already) without loading the portal itself.
    std::vector<uint32_t> leaf_portal_dest;
    // Per region: a sphere holding every point of its portals (target checks reject a region
    // whose whole sphere lies behind a plane without clipping its portals one by one).
    std::vector<Vec> leaf_centre;
    std::vector<double> leaf_radius;
    // Per pair of directed portals (2i, 2i + 1): the index of the input portal they come from.
    std::vector<uint32_t> input_portal;
    uint32_t max_points = 0;
    size_t used = 0;
    size_t skipped = 0;

    size_t bytes() const
    {
        return portals.capacity() * sizeof(DirectedPortal) + points.capacity() * sizeof(Vec) +
               (leaf_first.capacity() + leaf_portals.capacity() + leaf_portal_dest.capacity() + input_portal.capacity()) *
                   sizeof(uint32_t) +
               leaf_centre.capacity() * sizeof(Vec) + leaf_radius.capacity() * sizeof(double);
    }
};

// Directed portals and per-region portal lists from the input (§2.5, §3.1).
Graph build_graph(const PortalSet& set, uint32_t region_count);

} // namespace pvs::portal_vis
