#include "visibility/eval/portal_crossings.h"

#include "visibility/reference/tree_trace.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {

namespace {

struct PortalFrame {
    glm::dvec3 centre{0.0}, normal{0.0};
};

// Centre and unit normal into regions[0]; false for a polygon with no area.
bool portal_frame(const PortalSet& set, const Portal& portal, PortalFrame& frame)
{
    if (portal.point_count < 3 || size_t(portal.first_point) + portal.point_count > set.points.size())
        return false;
    const glm::vec3* points = set.points.data() + portal.first_point;
    glm::dvec3 sum(0.0), newell(0.0);
    for (uint32_t i = 0; i < portal.point_count; ++i) {
        const glm::dvec3 a(points[i]), b(points[(i + 1) % portal.point_count]);
        sum += a;
        newell += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const double length = glm::length(newell);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    frame.centre = sum / double(portal.point_count);
    frame.normal = -newell / length; // clockwise from the front: Newell's normal points back
    return true;
}

} // namespace

CrossingReport trace_portal_crossings(const Zone& zone, const PortalSet& portals, SkyPortals sky, double half_length)
{
    CrossingReport report;
    report.portals = portals.portals.size();
    const TreeTracer tracer(zone.tree, zone.regions, sky);
    if (!tracer.has_tree())
        return report;
    TreeTracer::Scratch scratch;
    const int32_t region_count = int32_t(zone.regions.size());
    for (uint32_t i = 0; i < portals.portals.size(); ++i) {
        const Portal& portal = portals.portals[i];
        const int32_t front = portal.regions[0], back = portal.regions[1];
        PortalFrame frame;
        if (front < 0 || back < 0 || front >= region_count || back >= region_count || !portal_frame(portals, portal, frame)) {
            ++report.unplaced;
            continue;
        }
        if (!tracer.passes(back, front)) {
            ++report.opaque;
            continue;
        }
        double h = half_length;
        bool placed = false;
        for (int halving = 0; halving <= 8 && !placed; ++halving, h *= 0.5)
            placed = tracer.region_at(frame.centre - h * frame.normal) == back &&
                     tracer.region_at(frame.centre + h * frame.normal) == front;
        if (!placed) {
            ++report.unplaced;
            continue;
        }
        h *= 2.0; // the loop halved once more after placing
        const glm::dvec3 from = frame.centre - h * frame.normal;
        const glm::dvec3 direction = 2.0 * h * frame.normal;
        const TraceEnd end = tracer.trace(from, direction, 1.0, scratch, [](int32_t, double, double) {});
        ++report.traced;
        if (end.blocked) {
            BlockedCrossing b;
            b.portal = i;
            b.regions[0] = front;
            b.regions[1] = back;
            b.centre = frame.centre;
            b.normal = frame.normal;
            b.blocked_at = from + end.t * direction;
            b.half_length = h;
            report.blocked.push_back(b);
        }
    }
    return report;
}

} // namespace pvs
