// A frame of the portal flow (ericw's pstack_t; portal_vis.h, "Method::Full", "Memory"): the
// windings it holds and the clip that makes them.
//
// Contract. A frame owns three fixed windings of kStackPoints points (slots). A WRef points
// either at a portal's points in the graph (owner == nullptr) or at one of a frame's slots;
// clip_winding returns the part of a winding in front of a plane, written to a free slot of
// the frame it is given, and frees the input's slot when the input was that frame's. It never
// allocates: a result that would not fit in a slot is given up (the unclipped input is
// returned: conservative). A frame's separator caches (tests 0 and 1) and its mightsee are
// filled by the flow (flow.h); the frame only holds them.
#pragma once

#include "visibility/bit_row.h"
#include "visibility/portal/portal_graph.h"

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

constexpr uint32_t kStackPoints = 24;   // MAX_WINDING_FIXED: points of a frame's winding
constexpr int kStackWindings = 3;       // STACK_WINDINGS: windings per frame
constexpr uint32_t kMaxSeparators = 64; // MAX_SEPARATORS: cached planes per test per frame

// A winding seen through a handle: its points belong to a portal (owner == nullptr) or to one
// of a frame's fixed windings. Clipped windings keep their input's sphere (still a bound).
struct WRef {
    const Vec* points = nullptr; // nullptr: no winding
    uint32_t count = 0;
    Vec origin{0.0};
    double radius = 0.0;
    const void* owner = nullptr;
    int slot = -1;

    explicit operator bool() const { return points != nullptr; }
};

// A frame's planes for test 0 or 1, found edge by edge as targets need them: a target is
// clipped by the planes found so far, then by new ones until it is gone or every edge of A has
// been tried. Every target thus meets the same planes in the same order as if all had been
// built first; the ones never needed are never built.
struct SeparatorCache {
    uint32_t next_edge = 0; // edges of A tried so far
    uint32_t count = 0;
    DPlane planes[kMaxSeparators];
    std::vector<int8_t> b_side; // sides_to_plane of B, found with the first edge
};

struct Frame {
    uint32_t leaf = 0;
    uint32_t entry = 0; // the directed portal that led into leaf
    uint32_t cursor = 0, end = 0; // the leaf's outgoing portals still to try
    WRef source, pass;            // for the child frame: what is left of the source, the pass
    DPlane portalplane;           // for the child frame: the plane of the portal it came through
    std::vector<uint64_t> mightsee; // for the child frame; words outside [lo, hi) are zero (never read)
    uint32_t lo = 0, hi = 0;
    bool slot_used[kStackWindings] = {};
    SeparatorCache separators[2];
    Vec slots[kStackWindings][kStackPoints];

    Frame(size_t words, uint32_t max_points) : mightsee(words, 0)
    {
        for (SeparatorCache& cache : separators)
            cache.b_side.resize(max_points);
    }
    // Whether region `r` is in the mightsee this frame passes on (read within [lo, hi) only).
    bool may_see(uint32_t r) const
    {
        const uint32_t word = r >> 6;
        return word >= lo && word < hi && bits::test(mightsee, r);
    }
};

// The area of a (convex, planar) winding; 0 for none.
inline double winding_area(const WRef& w)
{
    Vec twice(0.0);
    for (uint32_t i = 1; i + 1 < w.count; ++i)
        twice += glm::cross(w.points[i] - w.points[0], w.points[i + 1] - w.points[0]);
    return 0.5 * glm::length(twice);
}

inline void release_slot(const WRef& w, Frame& f)
{
    if (w.owner == &f)
        f.slot_used[w.slot] = false;
}

inline int acquire_slot(Frame& f)
{
    for (int i = 0; i < kStackWindings; ++i)
        if (!f.slot_used[i]) {
            f.slot_used[i] = true;
            return i;
        }
    assert(false && "portal vis: a frame needs at most three windings");
    return -1;
}

// A clip whose result would not fit in a frame's winding: the slot back, the unclipped input
// (conservative).
inline WRef overflowed(Frame& f, int slot, const WRef& in)
{
    f.slot_used[slot] = false;
    return in;
}

// ericw's ClipStackWinding: the front part of `in`; the input itself when it has no point
// behind, when all its points are on the plane, when its points are only within ON_EPSILON in
// front (some beyond kDropEpsilon: ericw drops such a winding, portal_graph.h) or when the
// result would not fit in a frame's winding; an empty handle when nothing is in front. Frees `in` when it was one of
// f's windings and a new one is returned (or none). `dists` and `sides`: scratch for at least
// in.count + 1 entries. Inline: the flow, the passages and the target checks all clip in their
// inner loops.
inline WRef clip_winding(const WRef& in, const DPlane& split, Frame& f, double* dists, uint8_t* sides)
{
    enum : uint8_t { kFront = 0, kBack = 1, kOn = 2 };
    if (!in)
        return in;
    const double centre = split.distance(in.origin);
    if (centre < -in.radius) {
        release_slot(in, f);
        return {};
    }
    if (centre > in.radius)
        return in;

    // Locals (and scratch passed in, not reached through an object): the byte stores to `sides`
    // would otherwise make the compiler reload every pointer after each of them.
    const Vec* points = in.points;
    const uint32_t n = in.count;
    const Vec normal = split.normal;
    const double dist = split.dist;
    // Branch-free: which side a point is on is data, not control flow.
    uint32_t front = 0, back = 0, ahead = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double d = glm::dot(normal, points[i]) - dist;
        dists[i] = d;
        const uint32_t is_front = d > kOnEpsilon, is_back = d < -kOnEpsilon;
        sides[i] = uint8_t(is_back + 2 * (1 - is_front - is_back)); // kFront, kBack or kOn
        front += is_front;
        back += is_back;
        ahead += d > kDropEpsilon;
    }
    dists[n] = dists[0];
    sides[n] = sides[0];
    if (front == 0 && back == 0)
        return in; // lying on the plane: kept unclipped (ericw issue #261)
    if (front == 0) {
        if (ahead)
            return in; // in front by less than ON_EPSILON only: ericw drops it, which can lose a
                       // sight line up to 0.1 wide; kept whole (conservative, kDropEpsilon)
        release_slot(in, f);
        return {};
    }
    if (back == 0)
        return in;

    const int slot = acquire_slot(f);
    if (slot < 0)
        return in; // cannot happen (see acquire); unclipped is conservative
    Vec* out = f.slots[slot];
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const Vec& p1 = points[i];
        if (sides[i] != kBack) {
            if (m == kStackPoints)
                return overflowed(f, slot, in);
            out[m++] = p1;
            if (sides[i] == kOn)
                continue;
        }
        if (sides[i + 1] == kOn || sides[i + 1] == sides[i])
            continue;
        const Vec& p2 = points[i + 1 == n ? 0 : i + 1];
        const double t = dists[i] / (dists[i] - dists[i + 1]);
        Vec mid;
        for (int j = 0; j < 3; ++j) {
            if (normal[j] == 1.0)
                mid[j] = dist; // axial plane: no round-off on its axis
            else if (normal[j] == -1.0)
                mid[j] = -dist;
            else
                mid[j] = p1[j] + t * (p2[j] - p1[j]);
        }
        if (m == kStackPoints)
            return overflowed(f, slot, in);
        out[m++] = mid;
    }
    const WRef result{out, m, in.origin, in.radius, &f, slot};
    release_slot(in, f);
    return result;
}

} // namespace pvs::portal_vis
