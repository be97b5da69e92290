// Base vis's exact test (base_vis.h).
#include "visibility/portal/base_vis.h"

#include <cmath>

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

bool portal_might_see(const Graph& g, const DirectedPortal& p, const DirectedPortal& t)
{
    const Vec* pp = &g.points[p.first_point];

    // 1. t is not entirely behind p: a vertex in front, or all on p's plane (coplanar).
    double d = p.plane.distance(t.origin);
    if (d < -t.radius)
        return false;
    bool t_coplanar = false;
    if (!sphere_beyond(p.plane, d, t.origin, t.radius, kOnEpsilon)) {
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
    d = t.plane.distance(p.origin);
    if (d > p.radius)
        return false;
    bool p_coplanar = false;
    if (!sphere_beyond(t.plane.flipped(), -d, p.origin, p.radius, kOnEpsilon)) {
        uint32_t not_front = 0, j = 0;
        for (; j < p.point_count; ++j) {
            d = t.plane.distance(pp[j]);
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
    if ((t_coplanar || p_coplanar) && glm::dot(p.plane.normal, t.plane.normal) < kCoplanarFacing)
        return false;
    return true;
}

} // namespace pvs::portal_vis
