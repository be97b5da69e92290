// Sight lines through a BSP tree's open space: the geometric test behind the sampled reference
// (reference_vis.h) and the exact popping check (ui/accuracy_walk.h). It decides "is this
// segment in open space" from the tree's leaves, not from a mesh, so a line cannot slip through
// a crack between two triangles of a wall: the wall is a solid (or outside) leaf, and no part of
// a leaf is missing.
//
// The walk. The segment origin + t * direction, t in [0, t_end], is split by each node plane it
// crosses, front to back (an explicit stack, the classic recursive hull check of Quake's
// SV_RecursiveHullCheck without the hull), so the leaves come out in the order the segment
// meets them, each with the interval [t0, t1] it spends there. All arithmetic is in double on
// the tree's float planes taken exactly: distances at the interval ends pick the side, and a
// crossing is at t = -s0 / s1 (s0: distance of the origin, s1: dot of normal and direction),
// the same value for both halves, so consecutive intervals meet exactly. Intervals of zero
// length (the segment through an edge or a vertex of a cell) are not visited: they are
// measure zero for the random rays that use this, and visiting them would let a line see round
// a corner it only touches. A segment lying in a plane goes where the tree's TieRule says.
//
// What stops a line (trace() returns the t where it stopped, with blocked = true):
//  - a solid (kLeafSolid) or outside (kLeafOutside) leaf, or a leaf naming a region id outside
//    the zone: walls, the void, corrupt leaves;
//  - a region the previous region does not see through (media.h: by default air and liquids see
//    each other, sky only sky), with the sky rule given at construction; two leaves of one region
//    always see each other (TraceEnd::refused_region names it);
//  - a node index out of range (a corrupt tree): treated as solid.
// A segment that starts in such a leaf is blocked at t = 0 and visits nothing. A tree with no
// root (no tree at all) blocks every segment: callers test has_tree() first.
//
// Cost: O(nodes on the way) per segment, no allocation once the caller's scratch stack has grown
// to the tree's depth. Thread-safe: trace() only reads; each thread passes its own scratch.
#pragma once

#include "visibility/portal/media.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace pvs {

// The margin of open_beam() that the reference and the popping check use (zone units): half
// Quake vis's ON_EPSILON.
inline constexpr double kBeamMargin = 0.05;

struct TraceEnd {
    double t = 0.0;       // where the walk stopped: t_end, or the entry of the leaf that blocked it
    bool blocked = false; // stopped by a leaf it cannot see into (not by reaching t_end)
    int32_t last_region = -1; // the last region visited, -1 when none was
    // blocked by the content rule (media.h), not by a wall: the open region the line could not
    // enter from last_region; -1 when a solid, outside or corrupt leaf stopped it (or nothing did)
    int32_t refused_region = -1;
};

class TreeTracer {
public:
    struct StackItem {
        int32_t child;
        double t0, t1;
    };
    using Scratch = std::vector<StackItem>;

    TreeTracer() = default;
    TreeTracer(const BspTree& tree, const std::vector<Region>& regions, SkyPortals sky);

    bool has_tree() const { return root_ != kNoRoot; }
    size_t region_count() const { return medium_.size(); }

    // Walks the segment (see above), calling visit(region, t0, t1) for each open leaf it passes
    // through, in order (consecutive leaves of one region each call it). `direction` need not be
    // unit length; t is in its units.
    template <class Visit>
    TraceEnd trace(const glm::dvec3& origin, const glm::dvec3& direction, double t_end, Scratch& stack,
                   Visit&& visit) const;

    // Whether a segment already found open (from `from` along the unit `direction` for
    // `length`) stays open when moved by `margin` across itself: its four companions, up, down,
    // left and right of it, both ends moved alike, are traced (the segment itself is not again). A line that is open only because it passes a wall's edge or
    // corner by less than the margin, or through a gap narrower than it, is not: such hair-thin
    // lines are real in exact geometry but are what every vis tool drops by its epsilon and what
    // a viewer sees at most as a sparkle. Both the reference and the popping check ask this.
    bool open_beam(const glm::dvec3& from, const glm::dvec3& direction, double length, double margin,
                   Scratch& scratch) const;

    // The region holding `point` (the tree's TieRule on planes, as locate_point, but in double),
    // or kLeafSolid / kLeafOutside; kLeafSolid without a tree or for a corrupt leaf.
    int32_t region_at(const glm::dvec3& point) const;

    // Whether a line may pass from region `from` into region `to` (media.h; same region: yes).
    bool passes(int32_t from, int32_t to) const
    {
        if (from == to)
            return true;
        const RegionMedium& a = medium_[size_t(from)];
        const RegionMedium& b = medium_[size_t(to)];
        return sees_through(Medium(a.medium), a.vis_contents, Medium(b.medium), b.vis_contents, sky_);
    }

private:
    struct Node {
        double nx, ny, nz, dist;
        int32_t children[2];
    };
    static constexpr int32_t kNoRoot = 0x7fffffff;
    static constexpr int32_t kCorruptChild = ~0x7fffffff; // leaf 0x7fffffff: out of any range

    // The leaf's region, or -1 when a line cannot enter it (solid, outside, out of range).
    int32_t open_region(int32_t leaf) const
    {
        if (leaf < 0 || size_t(leaf) >= leaf_region_.size())
            return -1;
        const int32_t region = leaf_region_[size_t(leaf)];
        return region >= 0 && size_t(region) < medium_.size() ? region : -1;
    }

    std::vector<Node> nodes_;
    std::vector<int32_t> leaf_region_;
    struct RegionMedium {
        uint8_t medium;        // Medium
        uint16_t vis_contents; // Region::vis_contents
    };
    std::vector<RegionMedium> medium_; // per region
    int32_t root_ = kNoRoot;
    bool ties_go_front_ = false;
    SkyPortals sky_ = SkyPortals::SkyToSky;
};

template <class Visit>
TraceEnd TreeTracer::trace(const glm::dvec3& origin, const glm::dvec3& direction, double t_end, Scratch& stack,
                           Visit&& visit) const
{
    TraceEnd end;
    if (root_ == kNoRoot || !(t_end > 0.0)) {
        end.blocked = root_ == kNoRoot;
        return end;
    }
    stack.clear();
    stack.push_back({root_, 0.0, t_end});
    int32_t previous = -1;
    while (!stack.empty()) {
        StackItem item = stack.back();
        stack.pop_back();
        int32_t child = item.child;
        double t0 = item.t0, t1 = item.t1;
        while (child >= 0) {
            if (size_t(child) >= nodes_.size()) {
                child = kCorruptChild; // a node index out of range: solid
                break;
            }
            const Node& node = nodes_[size_t(child)];
            const double s0 = node.nx * origin.x + node.ny * origin.y + node.nz * origin.z - node.dist;
            const double s1 = node.nx * direction.x + node.ny * direction.y + node.nz * direction.z;
            const double d0 = s0 + t0 * s1, d1 = s0 + t1 * s1;
            if (d0 == 0.0 && d1 == 0.0) {
                child = node.children[ties_go_front_ ? 0 : 1];
                continue;
            }
            if (d0 >= 0.0 && d1 >= 0.0) {
                child = node.children[0];
                continue;
            }
            if (d0 <= 0.0 && d1 <= 0.0) {
                child = node.children[1];
                continue;
            }
            const int near_side = d0 > 0.0 ? 0 : 1;
            const double t_split = -s0 / s1;
            if (!(t_split > t0)) { // round-off: the whole interval is on the far side
                child = node.children[1 - near_side];
                continue;
            }
            if (!(t_split < t1)) {
                child = node.children[near_side];
                continue;
            }
            stack.push_back({node.children[1 - near_side], t_split, t1});
            child = node.children[near_side];
            t1 = t_split;
        }
        const int32_t region = open_region(~child);
        if (region < 0 || (previous >= 0 && !passes(previous, region))) {
            end.t = t0;
            end.blocked = true;
            end.last_region = previous;
            end.refused_region = region;
            return end;
        }
        visit(region, t0, t1);
        previous = region;
    }
    end.t = t_end;
    end.last_region = previous;
    return end;
}

} // namespace pvs
