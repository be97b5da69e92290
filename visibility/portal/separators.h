// Separating planes (ericw's ClipToSeparators, §3.4; portal_vis.h, "Method::Full", "Speed").
//
// Contract. For windings A (with its plane) and B, edge_separator gives the plane through edge
// i of A that has B in front and A behind, from the first vertex of B that makes one (ericw's
// order, Antony Suter's "first separator per edge"); for_each_separator hands those planes to
// a callback edge by edge. Pure functions of their inputs, no allocation (b_side is the
// caller's scratch of B's point count). Inline: they run in the flow's inner loop.
#pragma once

#include "visibility/portal/flow_frame.h"

#include <cmath>
#include <cstdint>

namespace pvs::portal_vis {

inline bool normals_equal(const Vec& a, const Vec& b)
{
    return std::abs(a.x - b.x) <= kEqualEpsilon && std::abs(a.y - b.y) <= kEqualEpsilon &&
           std::abs(a.z - b.z) <= kEqualEpsilon;
}

// Which side of A's plane each point of B lies on (+1 above +ON_EPSILON, -1 below -ON_EPSILON,
// 0 on it): edge_separator's first look at B, the same for every edge of A, so found once.
inline void sides_to_plane(const WRef& b, const DPlane& a_plane, int8_t* side)
{
    for (uint32_t j = 0; j < b.count; ++j) {
        const double d = a_plane.distance(b.points[j]);
        side[j] = int8_t(int(d > kOnEpsilon) - int(d < -kOnEpsilon));
    }
}

// ericw's separating plane for edge i of winding A and winding B (b_side: sides_to_plane of B
// against A's plane): the first vertex of B making a plane through the edge with B in front
// (none of it below -ON_EPSILON, some of it above +ON_EPSILON) and A behind; `mirror` negates
// it (tests 1 and 3). False when no vertex of B gives one.
// The candidates are tested with the unnormalised normal n, d = dot(n, b - b_j) / |n| compared
// as d^2 against ON_EPSILON^2 with d's sign, so a rejected vertex costs no square root or
// division; the plane returned is computed exactly as ericw's (normalised, then its distance).
inline bool edge_separator(const WRef& a, const WRef& b, const int8_t* b_side, uint32_t i, bool mirror, DPlane& out)
{
    const Vec ai = a.points[i];
    const Vec v1 = a.points[i + 1 == a.count ? 0 : i + 1] - ai;
    const Vec* bp = b.points;
    const uint32_t bn = b.count;
    for (uint32_t j = 0; j < bn; ++j) {
        if (b_side[j] == 0)
            continue; // on A's plane
        const Vec bj = bp[j];
        const Vec cross = glm::cross(v1, bj - ai);
        const double len_sq = glm::dot(cross, cross);
        if (len_sq < kSeparatorMinLengthSq)
            continue; // the three points make no plane
        // The side of A that holds this vertex of B is the side of the new plane that holds B.
        const Vec n = b_side[j] < 0 ? -cross : cross;
        const double limit = kOnEpsilon * kOnEpsilon * len_sq;
        // B's points from j's neighbours out: on a convex B, a vertex that is not the one the
        // plane wants has a neighbour behind, so most candidates fail at the first look (the
        // order does not change the outcome, every point must pass).
        const double nj = glm::dot(n, bj);
        bool front = false, behind = false;
        for (uint32_t step = 1; step < bn && !behind; ++step) {
            // j+1, j-1, j+2, j-2, ...: every other point once.
            const uint32_t offset = (step & 1) != 0 ? (step + 1) / 2 : bn - step / 2;
            const uint32_t k = j + offset < bn ? j + offset : j + offset - bn;
            const double u = glm::dot(n, bp[k]) - nj;
            const bool beyond_epsilon = u * u > limit;
            behind = (u < 0.0) & beyond_epsilon;
            front |= (u > 0.0) & beyond_epsilon;
        }
        if (behind || !front)
            continue;
        DPlane sep;
        sep.normal = cross * (1.0 / std::sqrt(len_sq));
        sep.dist = glm::dot(bj, sep.normal);
        if (b_side[j] < 0)
            sep = sep.flipped();
        out = mirror ? sep.flipped() : sep;
        return true; // the first separator of each edge only (Antony Suter's optimisation)
    }
    return false;
}

// ericw's ClipToSeparators, less the clipping: use(plane) gets the separator of each edge of A
// with B in turn (a_plane: A's plane; b_side: scratch for B's points), while it returns true.
template <class Use>
void for_each_separator(const WRef& a, const DPlane& a_plane, const WRef& b, bool mirror, int8_t* b_side, Use&& use)
{
    sides_to_plane(b, a_plane, b_side);
    DPlane sep;
    for (uint32_t i = 0; i < a.count; ++i)
        if (edge_separator(a, b, b_side, i, mirror, sep) && !use(sep))
            return;
}

} // namespace pvs::portal_vis
