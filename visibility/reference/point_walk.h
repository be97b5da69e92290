// Everything a point sees through the portals, as a portal renderer finds it: the third source of
// the sampled reference's sight lines (reference_vis.h).
//
// Why. Lines drawn at random find a narrow line of sight (through two doorways far apart) only
// when both their ends fall in the thin set of lines that pass it: a search in four dimensions.
// From one point, the regions it sees are found exactly by clipping: a region S is seen from
// the eye through a chain of portals when the last portal, clipped to the cone from the eye
// through the window before it, keeps some area. Points on the portals of a region A see
// everything A sees (a sight line from A to B leaves A through one of A's portals), so sampling
// eyes on A's portals is a search in two dimensions, and each eye answers for every direction.
//
// The walk. An eye on portal P0 (from region `from` into region `into`) starts in `into` with the
// whole half-space beyond P0 in view. In a region R entered through window W (a convex polygon on
// the portal it came through), each other portal Q of R with the eye at least 0.01 units on R's
// side of its plane (nearer, float noise between coplanar portals' planes could put the eye on
// both sides of a wall cut into pieces) is clipped to the cone from the eye over W (one plane
// through the eye per edge of W); what is left, W', is the window into the region S behind Q,
// and the walk goes on into S with W'. Every point of W' is reached from the eye by a segment
// through P0, every window before it and R: the regions are convex (the leaves of the tree), so
// each piece of the segment between two windows lies in the region between them. In exact
// arithmetic different chains to the same portal see through disjoint cones (a line crosses one
// sequence of convex regions) and no chain returns to a region, so the walk ends without marking
// anything; a depth limit and a window budget bound it where rounding or hostile input would not.
// Windows of almost no area (under kMinWindowArea) are dropped: a sight line through them would
// not pass the reference's beam test.
//
// What it returns: for each region reached, a Sight: the region and a point inside the widest of
// the windows the walk entered it through (the mean of the window's corners, interior to the
// convex window), in the order the regions were first reached. The walk
// is exact in double on the portals' float points, but it is not the proof: the reference traces
// the line from the eye through that point in the tree (tree_trace.h, line_witness.h) and sets
// only what the trace proves, so a walk fooled by rounding can waste a line, never set a bit.
//
// Cost: one clip of a portal by the window's cone per portal met, no allocation once the
// scratch has grown. Thread-safe: walk() only reads; each thread passes its own scratch.
#pragma once

#include "visibility/reference/portal_sampler.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace pvs {

class PortalWalker {
public:
    // Windows with less area than this (zone units squared) are dropped (see above).
    static constexpr double kMinWindowArea = 1e-6;
    static constexpr uint32_t kMaxDepth = 1024; // walk() recurses: about 150 bytes of stack a level
    static constexpr uint32_t kMaxWindowsPerWalk = 1u << 18;
    static constexpr uint32_t kMaxWindowPoints = 64;

    struct Sight {
        uint32_t region;
        glm::dvec3 aim; // a point inside the widest window through which the walk entered the region
    };
    struct Scratch {
        std::vector<glm::dvec3> pool;  // the windows of the current chain, back to back
        std::vector<glm::dvec3> cones; // their cones' plane normals (planes through the eye)
        std::vector<glm::dvec3> clip[2]; // a clip's ping-pong buffers
        std::vector<uint32_t> stamp;   // per region: the walk that last reached it
        std::vector<uint32_t> sight_of; // per region, when stamped: its index in sights (or none)
        std::vector<double> sight_area; // per sight: the area of its window
        uint32_t walk = 0;
        uint32_t windows = 0;
        bool truncated = false;        // the last walk hit the depth limit or the window budget
        std::vector<Sight> sights;
    };

    PortalWalker() = default;
    // `portals` as PortalSampler takes them (the same portals are left out); `links` from it.
    PortalWalker(const PortalSet& portals, const PortalSampler& links, uint32_t region_count);

    // The regions seen from `eye`, a point on `portal`, looking from region `from` through it
    // (into the other region of the portal), into scratch.sights in the order first reached.
    // The region behind the portal itself is not listed (every line through the portal reaches it).
    // Precondition: `portal` is one of links(from)'s portals.
    void walk(const glm::dvec3& eye, uint32_t portal, uint32_t from, Scratch& scratch) const;

    // The point at fraction u of the portal's perimeter, moved `inset` toward the mean of its
    // corners (at most halfway there).
    glm::dvec3 boundary_point(uint32_t portal, double u, double inset) const;

    // The portal's plane, normal into regions[0] (PRT1's orientation, portalize.h).
    glm::dvec4 plane(uint32_t portal) const { return planes_[portal]; }

private:
    void enter(const glm::dvec3& eye, uint32_t region, uint32_t came_through, size_t window_first,
               size_t window_count, uint32_t depth, Scratch& scratch) const;

    const PortalSampler* links_ = nullptr;
    std::vector<glm::dvec4> planes_;      // per portal
    std::vector<uint32_t> point_first_;   // per portal + 1
    std::vector<glm::dvec3> points_;
    std::vector<int32_t> front_region_;   // per portal: regions[0]
    std::vector<int32_t> back_region_;    // per portal: regions[1]
    uint32_t regions_ = 0;
};

} // namespace pvs
