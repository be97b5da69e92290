// The portal graph (portal_graph.h).
#include "visibility/portal/portal_graph.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <limits>
#include <cmath>

namespace pvs::portal_vis {
namespace {

void set_sphere(const Graph& g, DirectedPortal& p)
{
    Vec sum(0.0);
    for (uint32_t i = 0; i < p.point_count; ++i)
        sum += g.points[p.first_point + i];
    p.origin = sum / double(p.point_count);
    double r2 = 0.0;
    for (uint32_t i = 0; i < p.point_count; ++i) {
        const Vec d = g.points[p.first_point + i] - p.origin;
        r2 = std::max(r2, glm::dot(d, d));
    }
    p.radius = std::sqrt(r2);
}

} // namespace

Graph build_graph(const PortalSet& set, uint32_t region_count)
{
    Graph g;
    g.leaf_count = region_count;
    g.words = bits::words_for(region_count);
    // At most two directed portals per input portal and two copies of its points: reserved so
    // that growing the arrays never holds an old and a new copy at once.
    g.portals.reserve(2 * set.portals.size());
    size_t point_total = 0;
    for (const Portal& in : set.portals)
        point_total += in.point_count;
    g.points.reserve(std::min(2 * point_total, 2 * set.points.size()));
    std::vector<Vec> pts;
    for (uint32_t input = 0; input < uint32_t(set.portals.size()); ++input) {
        const Portal& in = set.portals[input];
        const bool regions_ok = in.regions[0] >= 0 && in.regions[1] >= 0 &&
                                uint32_t(in.regions[0]) < region_count && uint32_t(in.regions[1]) < region_count &&
                                in.regions[0] != in.regions[1];
        const bool range_ok = in.point_count >= 3 && in.first_point <= set.points.size() &&
                              in.point_count <= set.points.size() - in.first_point;
        if (!regions_ok || !range_ok) {
            ++g.skipped;
            continue;
        }
        pts.clear();
        bool finite = true;
        for (uint32_t i = 0; i < in.point_count; ++i) {
            const glm::vec3& p = set.points[in.first_point + i];
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            pts.emplace_back(p);
        }
        // The plane of the first three points, normal into regions[0] (§2.5); Newell's normal of
        // all points (the same orientation: id's points are clockwise seen from the normal's
        // side) when those three are colinear.
        Vec n = glm::cross(pts[0] - pts[1], pts[2] - pts[1]);
        double len = glm::length(n);
        if (!(len > 1e-9)) {
            Vec ccw(0.0);
            for (size_t i = 0; i < pts.size(); ++i)
                ccw += glm::cross(pts[i], pts[(i + 1) % pts.size()]);
            n = -ccw;
            len = glm::length(n);
        }
        if (!finite || !(len > 1e-9) || !std::isfinite(len)) {
            ++g.skipped;
            continue;
        }
        n /= len;
        const DPlane plane{n, glm::dot(n, pts[0])};

        const uint32_t first = uint32_t(g.points.size());
        const uint32_t count = uint32_t(pts.size());
        g.points.insert(g.points.end(), pts.begin(), pts.end());             // forward: as given
        g.points.insert(g.points.end(), pts.rbegin(), pts.rend());           // backward: reversed
        const uint32_t r0 = uint32_t(in.regions[0]), r1 = uint32_t(in.regions[1]);
        DirectedPortal forward{plane.flipped(), Vec(0.0), 0.0, first, count, r1, r0};
        DirectedPortal backward{plane, Vec(0.0), 0.0, first + count, count, r0, r1};
        set_sphere(g, forward);
        set_sphere(g, backward);
        g.portals.push_back(forward);
        g.portals.push_back(backward);
        g.input_portal.push_back(input);
        g.max_points = std::max(g.max_points, count);
        ++g.used;
    }
    // Portals leaving each region, in directed-index order (as ericw's leaf lists).
    g.leaf_first.assign(size_t{region_count} + 1, 0);
    for (const DirectedPortal& p : g.portals)
        ++g.leaf_first[p.owner + 1];
    for (uint32_t r = 0; r < region_count; ++r)
        g.leaf_first[r + 1] += g.leaf_first[r];
    g.leaf_portals.resize(g.portals.size());
    std::vector<uint32_t> fill(g.leaf_first.begin(), g.leaf_first.end() - 1);
    for (uint32_t i = 0; i < uint32_t(g.portals.size()); ++i)
        g.leaf_portals[fill[g.portals[i].owner]++] = i;
    g.leaf_portal_dest.resize(g.leaf_portals.size());
    for (size_t k = 0; k < g.leaf_portals.size(); ++k)
        g.leaf_portal_dest[k] = g.portals[g.leaf_portals[k]].leaf;
    // Each region's sphere: about the centre of its portals' points' box, out to the farthest.
    g.leaf_centre.assign(region_count, Vec(0.0));
    g.leaf_radius.assign(region_count, 0.0);
    for (uint32_t r = 0; r < region_count; ++r) {
        Vec lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k) {
            const DirectedPortal& p = g.portals[g.leaf_portals[k]];
            for (uint32_t i = 0; i < p.point_count; ++i) {
                lo = glm::min(lo, g.points[p.first_point + i]);
                hi = glm::max(hi, g.points[p.first_point + i]);
            }
        }
        if (g.leaf_first[r] == g.leaf_first[r + 1])
            continue;
        const Vec centre = (lo + hi) * 0.5;
        double radius = 0.0;
        for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k) {
            const DirectedPortal& p = g.portals[g.leaf_portals[k]];
            for (uint32_t i = 0; i < p.point_count; ++i)
                radius = std::max(radius, glm::length(g.points[p.first_point + i] - centre));
        }
        g.leaf_centre[r] = centre;
        g.leaf_radius[r] = radius * (1.0 + 1e-12) + 1e-9; // round-off: never too small
    }
    return g;
}

} // namespace pvs::portal_vis
