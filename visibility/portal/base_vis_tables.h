// Base vis's float tables: what the flood of base_vis.h reads, in floats and in flood order,
// and the verdicts they make certain.
//
// Contract. base_vis_tables copies a graph's portals into the tables (the graph is not kept);
// quick_verdict answers portal_might_see (base_vis.h) for one pair when the floats make the
// answer certain and says kUndecided otherwise: it never contradicts the exact test. Read-only
// after construction, so any number of threads share one.
#pragma once

#include "visibility/portal/portal_graph.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

// Three and four floats: a point; a plane (normal, dist) or a sphere (centre, radius).
struct Float3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};
struct Float4 {
    float x = 0.0f, y = 0.0f, z = 0.0f, w = 0.0f;
};

// One slot of the flood's table: a leaf's header, then one slot per portal leaving it (40 bytes).
struct FloodSlot {
    Float4 sphere;     // the portal's bounding sphere, radius rounded up (header: the leaf's)
    Float4 plane;      // the portal's plane (header: unused)
    uint32_t leaf = 0; // the leaf the portal leads into (header: how many portals leave it)
    uint32_t slot = 0; // that leaf's header slot (header: its first entry of Graph::leaf_portals)
};

// What base vis reads, in floats, built for it and freed after: about 15 MB at 5000 rooms.
//
// Why: a flood reaches about half the zone, so at 5000 rooms it streamed most of the graph's
// per-leaf arrays from the last-level cache for each of 126 000 portals; nearly every test is
// decided far from its threshold. So each leaf's part of the flood is one run of slots (its
// header with the sphere around every point of the portals leaving it, then per portal its
// plane, sphere, destination and the destination's run), two or three cache lines where the
// graph's arrays took six, and the points (only read when a sphere straddles a plane) are in
// their own array, in Graph::leaf_portals order. When the leaf's sphere lies beyond ON_EPSILON
// in front of the source portal's plane, each of its portals passes the first test unread.
// A float answer is taken only when it holds with `slack` to spare, a bound on the difference
// between a float comparison and its double counterpart (34 float ulps of the zone's
// magnitudes, over three times the rounding's bound); otherwise portal_might_see decides on the
// doubles. So the answer is always the exact test's (tested on every pair of a real map and of
// a generated zone, where the floats decide 99.98 % and 100 % of the pairs).
struct BaseVisTables {
    std::vector<FloodSlot> slots;      // per leaf: header, then its portals
    std::vector<uint32_t> leaf_slot;   // per leaf: its header slot
    std::vector<uint32_t> point_first; // per entry of Graph::leaf_portals, and one past the last
    std::vector<Float3> points;        // every entry's points, in entry order
    double slack = 0.0;
    float slack_f = 0.0f;  // slack, and ON_EPSILON + slack: what the float tests compare with
    float beyond_f = 0.0f;
};

BaseVisTables base_vis_tables(const Graph& g);

// n.x - d in floats.
inline float distance(const Float4& plane, float x, float y, float z)
{
    return plane.x * x + plane.y * y + plane.z * z - plane.w;
}
inline float distance(const Float4& plane, const Float4& centre)
{
    return distance(plane, centre.x, centre.y, centre.z);
}

// Whether every portal leaving the leaf whose header sphere is `leaf` is certainly in front of
// the source plane `p_plane` (test 1 passes for each).
inline bool leaf_in_front(const BaseVisTables& tables, const Float4& p_plane, const Float4& leaf)
{
    return distance(p_plane, leaf) - leaf.w > tables.beyond_f;
}

// The source portal of one flood, as quick_verdict reads it.
struct SourcePortal {
    Float4 plane, sphere;
    const Float3* points = nullptr; // its entry's run of BaseVisTables::points
    uint32_t point_count = 0;
    SourcePortal(const Graph& g, const BaseVisTables& tables, uint32_t pi);
    bool leaf_in_front(const BaseVisTables& tables, const FloodSlot& header) const
    {
        return portal_vis::leaf_in_front(tables, plane, header.sphere);
    }
};

enum class Verdict : uint8_t { kUndecided, kMightSee, kCannotSee };

// quick_verdict's sphere tests alone, for a source with float plane `p_plane` and sphere
// `p_sphere`: kUndecided where they leave the pair to verdict_near_planes.
inline Verdict sphere_verdict(const BaseVisTables& tables, const Float4& p_plane, const Float4& p_sphere,
                              const FloodSlot& t, bool leaf_in_front)
{
    // 2. p's sphere against t's plane; 1. t's leaf's sphere, or its own, against p's plane.
    const float d2 = distance(t.plane, p_sphere);
    if (d2 - tables.slack_f > p_sphere.w)
        return Verdict::kCannotSee;
    const bool p_behind = -d2 - p_sphere.w > tables.beyond_f;
    if (leaf_in_front) {
        if (p_behind)
            return Verdict::kMightSee;
    } else {
        const float d1 = distance(p_plane, t.sphere);
        if (d1 + tables.slack_f < -t.sphere.w)
            return Verdict::kCannotSee;
        if (p_behind && d1 - t.sphere.w > tables.beyond_f)
            return Verdict::kMightSee;
    }
    return Verdict::kUndecided;
}

// quick_verdict where the spheres do not decide: the points and the coplanar rule.
Verdict verdict_near_planes(const BaseVisTables& tables, const SourcePortal& p, const FloodSlot& t, size_t k,
                            bool leaf_in_front);

// portal_might_see's answer for the tested portal of slot `t`, entry k of Graph::leaf_portals,
// when the floats make it certain, else kUndecided. `leaf_in_front`: SourcePortal::leaf_in_front
// of the leaf the portal leaves. (Base vis asks the spheres of many sources at once,
// source_lanes.h; this is the one-pair form its tests compare with.)
inline Verdict quick_verdict(const BaseVisTables& tables, const SourcePortal& p, const FloodSlot& t, size_t k,
                             bool leaf_in_front)
{
    const Verdict spheres = sphere_verdict(tables, p.plane, p.sphere, t, leaf_in_front);
    return spheres != Verdict::kUndecided ? spheres : verdict_near_planes(tables, p, t, k, leaf_in_front);
}

} // namespace pvs::portal_vis
