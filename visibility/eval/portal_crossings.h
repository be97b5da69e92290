// The crossing invariant: a short segment across the middle of every portal between two open
// regions traces open through the tree. A portal is where two leaf cells share a face, so in
// exact geometry nothing solid lies between them; when a loader builds two planes of one line
// by different float arithmetic (Doom: a wall from a rounded GL vertex, the node from the
// linedef), the tree gets a sliver of solid along the boundary, and every sight line the
// reference traces across it is cut. This finds such slivers on any zone with a tree.
//
// For each portal with two open regions whose media see each other (media.h, `sky`):
//   - its centre c is the mean of its points (inside a convex polygon), its normal n Newell's,
//     pointing into regions[0] (the PRT convention of portalize.h and .prt files: points
//     clockwise seen from the front);
//   - the segment from c - h n to c + h n is traced (tree_trace.h), h = half_length, halved
//     (down to half_length / 256) until its ends lie in regions[1] and regions[0] by the tree
//     (a cell thinner than h puts an end in a third leaf, which proves nothing);
//   - it is blocked when the trace stops before its end (a solid, outside or opaque leaf on
//     the way); the crossing's position, and where it stopped, are kept.
// Portals whose ends cannot be placed (a cell thinner than half_length / 256 on one side, a
// degenerate polygon, a region id out of range) are counted as unplaced, not judged.
// Cost: up to 9 point lookups and one short trace per portal; no allocation per portal.
#pragma once

#include "visibility/portal/media.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs {

struct BlockedCrossing {
    uint32_t portal = 0;              // index into the PortalSet
    int32_t regions[2] = {-1, -1};    // as the portal's
    glm::dvec3 centre{0.0};           // the portal's centre, where the segment crosses it
    glm::dvec3 normal{0.0};           // unit, into regions[0]
    glm::dvec3 blocked_at{0.0};       // where the trace stopped
    double half_length = 0;           // the segment's half length that placed its ends
};

struct CrossingReport {
    size_t portals = 0;       // portals in the set
    size_t traced = 0;        // crossings traced (open or blocked)
    size_t unplaced = 0;      // portals whose segment ends could not be placed (see above)
    size_t opaque = 0;        // portals between regions whose media do not see each other: not traced
    std::vector<BlockedCrossing> blocked;

    size_t open() const { return traced - blocked.size(); }
};

inline constexpr double kCrossingHalfLength = 1.0;

CrossingReport trace_portal_crossings(const Zone& zone, const PortalSet& portals, SkyPortals sky = SkyPortals::SkyToSky,
                                      double half_length = kCrossingHalfLength);

} // namespace pvs
