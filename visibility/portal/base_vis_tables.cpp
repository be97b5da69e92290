// Base vis's float tables (base_vis_tables.h).
#include "visibility/portal/base_vis_tables.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace pvs::portal_vis {
namespace {

// A double as a float, clamped to the float range (a conversion out of range is undefined).
// Clamped values only occur where the slack is infinite (base_vis_tables), so none decides.
float to_float(double v)
{
    constexpr double kMax = std::numeric_limits<float>::max();
    return float(std::clamp(v, -kMax, kMax));
}

Float4 float_plane(const DPlane& plane)
{
    return {to_float(plane.normal.x), to_float(plane.normal.y), to_float(plane.normal.z), to_float(plane.dist)};
}

// A sphere whose float radius is not below the double one (the float tests read it as a bound).
Float4 float_sphere(const Vec& centre, double radius)
{
    float r = to_float(radius);
    if (double(r) < radius)
        r = std::nextafter(r, std::numeric_limits<float>::infinity());
    return {to_float(centre.x), to_float(centre.y), to_float(centre.z), r};
}

float distance(const Float4& plane, const Float3& point)
{
    return distance(plane, point.x, point.y, point.z);
}

double abs_sum(const Vec& v)
{
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}

// The sphere around every point of the portals leaving `leaf`, centred on their box; widens
// `magnitude` to cover its centre and radius.
Float4 leaf_sphere(const Graph& g, uint32_t leaf, double& magnitude)
{
    Vec lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    auto each_point = [&](auto&& visit) {
        for (uint32_t k = g.leaf_first[leaf]; k < g.leaf_first[leaf + 1]; ++k) {
            const DirectedPortal& t = g.portals[g.leaf_portals[k]];
            for (uint32_t j = 0; j < t.point_count; ++j)
                visit(g.points[t.first_point + j]);
        }
    };
    each_point([&](const Vec& v) { lo = glm::min(lo, v), hi = glm::max(hi, v); });
    if (lo.x > hi.x) // no portal leaves it: never asked
        return {};
    const Vec centre = 0.5 * (lo + hi);
    double radius = 0.0;
    each_point([&](const Vec& v) { radius = std::max(radius, glm::length(v - centre)); });
    magnitude = std::max(magnitude, abs_sum(centre) + radius);
    return float_sphere(centre, radius);
}

// How one side test ends, as the exact loop would decide it from the double distances (each
// within `slack` of the float ones): kPass and kFail certain, kOnPlane = passes with every point
// on the plane (the coplanar exception decides), kUndecided.
enum class Side : uint8_t { kUndecided, kPass, kOnPlane, kFail };

// Test 1 on t's points against p's plane: it passes at a point with d > ON_EPSILON, passes "on
// the plane" when every point has |d| < ON_EPSILON, and fails otherwise (no point in front, some
// d <= -ON_EPSILON). Test 2 is the same on p's points against t's flipped plane.
Side points_in_front(const Float4& plane, const Float3* points, uint32_t count, float epsilon, float slack)
{
    bool none_in_front = true, some_behind = false, all_on = count != 0;
    for (uint32_t j = 0; j < count; ++j) {
        const float d = distance(plane, points[j]);
        if (d > epsilon + slack)
            return Side::kPass;
        none_in_front &= d < epsilon - slack;
        some_behind |= d < -epsilon - slack;
        all_on &= d > -epsilon + slack && d < epsilon - slack;
    }
    if (none_in_front && some_behind)
        return Side::kFail;
    return all_on ? Side::kOnPlane : Side::kUndecided;
}

} // namespace

BaseVisTables base_vis_tables(const Graph& g)
{
    BaseVisTables tables;
    const size_t n = g.leaf_portals.size();
    double max_dist = 0.0, max_extent = 0.0;
    tables.leaf_slot.resize(g.leaf_count);
    uint32_t next_slot = 0;
    for (uint32_t leaf = 0; leaf < g.leaf_count; ++leaf) {
        tables.leaf_slot[leaf] = next_slot;
        next_slot += 1 + g.leaf_first[leaf + 1] - g.leaf_first[leaf];
    }
    tables.slots.resize(g.leaf_count + n);
    tables.point_first.resize(n + 1);
    size_t point_count = 0;
    for (uint32_t leaf = 0; leaf < g.leaf_count; ++leaf) {
        FloodSlot* slot = &tables.slots[tables.leaf_slot[leaf]];
        slot->sphere = leaf_sphere(g, leaf, max_extent);
        slot->leaf = g.leaf_first[leaf + 1] - g.leaf_first[leaf];
        slot->slot = g.leaf_first[leaf];
        for (uint32_t k = g.leaf_first[leaf]; k < g.leaf_first[leaf + 1]; ++k) {
            const DirectedPortal& t = g.portals[g.leaf_portals[k]];
            *++slot = {float_sphere(t.origin, t.radius), float_plane(t.plane), t.leaf, tables.leaf_slot[t.leaf]};
            max_dist = std::max(max_dist, std::abs(t.plane.dist));
            max_extent = std::max(max_extent, abs_sum(t.origin) + t.radius);
        }
    }
    for (size_t k = 0; k < n; ++k) {
        tables.point_first[k] = uint32_t(point_count);
        point_count += g.portals[g.leaf_portals[k]].point_count;
    }
    tables.point_first[n] = uint32_t(point_count);
    tables.points.resize(point_count);
    for (size_t k = 0; k < n; ++k) {
        const DirectedPortal& t = g.portals[g.leaf_portals[k]];
        for (uint32_t j = 0; j < t.point_count; ++j) {
            const Vec& v = g.points[t.first_point + j];
            tables.points[tables.point_first[k] + j] = {to_float(v.x), to_float(v.y), to_float(v.z)};
            max_extent = std::max(max_extent, abs_sum(v));
        }
    }
    // Every float comparison below differs from its double counterpart by less than 10 float
    // ulps (u = 2^-24) of M = max_dist + max_extent: a distance n.x - d rounds its inputs and
    // four operations (within 6u M, |normal components| <= 1), the comparison's subtraction adds
    // 2u M and a radius rounded up 2u M. The slack is 2e-6 M, 34u M: over three times that. It
    // also covers the exact test's own margin (1e-9 of the magnitudes, sphere_beyond) and the
    // double rounding of the exact distances. (At 5000 generated rooms, M = 11 139: slack 0.022,
    // so points on a plane, |d| < ON_EPSILON - slack, are still decided in floats.)
    // Past 1e30 (far beyond any level's units) a float distance could overflow: the slack is
    // then infinite and every test goes to the doubles.
    const double magnitude = max_dist + max_extent;
    tables.slack = magnitude < 1e30 ? 2e-6 * magnitude : std::numeric_limits<double>::infinity();
    tables.slack_f = float(tables.slack);
    tables.beyond_f = float(kOnEpsilon + tables.slack);
    return tables;
}

SourcePortal::SourcePortal(const Graph& g, const BaseVisTables& tables, uint32_t pi)
{
    const DirectedPortal& p = g.portals[pi];
    plane = float_plane(p.plane);
    sphere = float_sphere(p.origin, p.radius);
    for (uint32_t k = g.leaf_first[p.owner]; k < g.leaf_first[p.owner + 1]; ++k)
        if (g.leaf_portals[k] == pi) {
            points = &tables.points[tables.point_first[k]];
            point_count = tables.point_first[k + 1] - tables.point_first[k];
        }
}

Verdict verdict_near_planes(const BaseVisTables& tables, const SourcePortal& p, const FloodSlot& t, size_t k,
                            bool leaf_in_front)
{
    const float slack = tables.slack_f, epsilon = float(kOnEpsilon), beyond = tables.beyond_f;
    // 2. p is not entirely in front of t: p's sphere against t's plane, then p's points. The
    // exact test fails at once when the sphere is beyond t's radius in front, so the points
    // answer only when it certainly is not (a radius is within one float ulp of the double).
    const Float4 t_plane = t.plane;
    const float d2 = distance(t_plane, p.sphere);
    if (d2 - slack > p.sphere.w)
        return Verdict::kCannotSee;
    Side behind = Side::kPass;
    if (!(-d2 - p.sphere.w > beyond)) { // (written so that a NaN goes on to undecided)
        if (d2 + 2.0f * slack >= p.sphere.w)
            return Verdict::kUndecided;
        const Float4 flipped{-t_plane.x, -t_plane.y, -t_plane.z, -t_plane.w};
        behind = points_in_front(flipped, p.points, p.point_count, epsilon, slack);
        if (behind == Side::kFail || behind == Side::kUndecided)
            return behind == Side::kFail ? Verdict::kCannotSee : Verdict::kUndecided;
    }
    // 1. t is not entirely behind p: its leaf's sphere, its own, then its points.
    Side in_front = Side::kPass;
    if (!leaf_in_front) {
        const Float4& s = t.sphere;
        const float d1 = distance(p.plane, s);
        if (d1 + slack < -s.w)
            return Verdict::kCannotSee;
        if (!(d1 - s.w > beyond)) {
            if (d1 - 2.0f * slack <= -s.w)
                return Verdict::kUndecided;
            const uint32_t first = tables.point_first[k];
            in_front = points_in_front(p.plane, &tables.points[first], tables.point_first[k + 1] - first, epsilon, slack);
            if (in_front == Side::kFail || in_front == Side::kUndecided)
                return in_front == Side::kFail ? Verdict::kCannotSee : Verdict::kUndecided;
        }
    }
    if (behind == Side::kPass && in_front == Side::kPass)
        return Verdict::kMightSee;
    // 3. The coplanar exception: a portal facing back at p is rejected. Unit normals in floats
    // give the dot product within 1e-6.
    const float facing = p.plane.x * t_plane.x + p.plane.y * t_plane.y + p.plane.z * t_plane.z;
    if (facing < float(kCoplanarFacing) - 1e-5f)
        return Verdict::kCannotSee;
    return facing > float(kCoplanarFacing) + 1e-5f ? Verdict::kMightSee : Verdict::kUndecided;
}

} // namespace pvs::portal_vis
