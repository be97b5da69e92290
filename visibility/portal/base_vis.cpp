// Base portal vis (base_vis.h).
#include "visibility/portal/base_vis.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace pvs::portal_vis {
namespace {

// Whether every point of a winding with bounding sphere (o, r), whose centre is at distance
// d_origin from `plane`, lies more than `limit` in front of it: decided from the sphere alone,
// so the winding's points need not be read (on the generated zones most tested portals are far
// in front, and loading their points was a cache miss per test). The margin covers the round-off
// of the distances the point loop would compute, a few ulps of the magnitudes involved: 1e-9 of
// them is a million times that. So whenever this says yes, the loop would have found its first
// point beyond `limit` too, and skipping it changes no result.
bool sphere_beyond(const DPlane& plane, double d_origin, const Vec& o, double r, double limit)
{
    const double magnitude = std::abs(plane.dist) + std::abs(o.x) + std::abs(o.y) + std::abs(o.z) + r;
    return d_origin - r > limit + 1e-9 * magnitude;
}

} // namespace

std::vector<TestedPortal> tested_portals(const Graph& g)
{
    std::vector<TestedPortal> table(g.leaf_portals.size());
    for (size_t k = 0; k < table.size(); ++k) {
        const DirectedPortal& t = g.portals[g.leaf_portals[k]];
        table[k] = {t.plane, t.origin, t.radius};
    }
    return table;
}

bool portal_might_see(const Graph& g, const DirectedPortal& p, const TestedPortal& tested, const DirectedPortal& t)
{
    const Vec* pp = &g.points[p.first_point];

    // 1. t is not entirely behind p: a vertex in front, or all on p's plane (coplanar).
    double d = p.plane.distance(tested.origin);
    if (d < -tested.radius)
        return false;
    bool t_coplanar = false;
    if (!sphere_beyond(p.plane, d, tested.origin, tested.radius, kOnEpsilon)) {
        const Vec* tp = &g.points[t.first_point];
        uint32_t not_behind = 0, j = 0;
        for (; j < t.point_count; ++j) {
            d = p.plane.distance(tp[j]);
            not_behind += d > -kOnEpsilon;
            if (d > kOnEpsilon)
                break;
        }
        if (j == t.point_count) {
            if (not_behind != t.point_count)
                return false; // no point in front
            t_coplanar = true;
        }
    }
    // 2. p is not entirely in front of t: a vertex behind t's plane, or all on it.
    d = tested.plane.distance(p.origin);
    if (d > p.radius)
        return false;
    bool p_coplanar = false;
    if (!sphere_beyond(tested.plane.flipped(), -d, p.origin, p.radius, kOnEpsilon)) {
        uint32_t not_front = 0, j = 0;
        for (; j < p.point_count; ++j) {
            d = tested.plane.distance(pp[j]);
            not_front += d < kOnEpsilon;
            if (d < -kOnEpsilon)
                break;
        }
        if (j == p.point_count) {
            if (not_front != p.point_count)
                return false; // no point behind
            p_coplanar = true;
        }
    }
    // 3. Coplanar exception used: reject a portal facing back at p (p's twin, among others).
    if ((t_coplanar || p_coplanar) && glm::dot(p.plane.normal, tested.plane.normal) < kCoplanarFacing)
        return false;
    return true;
}

uint32_t base_portal_vis(const Graph& g, const std::vector<TestedPortal>& tested, uint32_t pi,
                         std::vector<uint32_t>& stack, uint64_t* mightsee)
{
    const std::span<uint64_t> row(mightsee, g.words);
    std::fill(row.begin(), row.end(), 0);
    const DirectedPortal& p = g.portals[pi];
    uint32_t count = 1;
    bits::set(row, p.leaf);
    stack.clear();
    stack.push_back(p.leaf);
    while (!stack.empty()) {
        const uint32_t leaf = stack.back();
        stack.pop_back();
        for (uint32_t k = g.leaf_first[leaf]; k < g.leaf_first[leaf + 1]; ++k) {
            const uint32_t ti = g.leaf_portals[k];
            const uint32_t dest = g.leaf_portal_dest[k];
            if (ti == pi || bits::test(row, dest) || !portal_might_see(g, p, tested[k], g.portals[ti]))
                continue;
            bits::set(row, dest);
            ++count;
            stack.push_back(dest);
        }
    }
    return count;
}

} // namespace pvs::portal_vis
