#include "visibility/eval/camera_set.h"

#include "visibility/reference/mesh_tracer.h"
#include "visibility/region_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <memory>
#include <random>

namespace pvs {

namespace {

// A camera point a player could occupy: in a region that is not sky (a sky volume is the
// inside of the sky brush, outside the playable space), with open space all around it out to
// beyond the near plane's corners, so the near plane never reaches through a wall.
bool good_viewpoint(const Zone& zone, const glm::vec3& p, float clearance)
{
    const PointLocation at = locate_point(zone.tree, p);
    if (!at.in_region() || (zone.regions[size_t(at.region)].flags & kRegionSky))
        return false;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                if (dx == 0 && dy == 0 && dz == 0)
                    continue;
                const glm::vec3 offset = glm::normalize(glm::vec3(dx, dy, dz)) * clearance;
                if (!locate_point(zone.tree, p + offset).in_region())
                    return false;
            }
    return true;
}

float clearance_for(const Camera& lens)
{
    const float half_h = lens.near_distance * std::tan(glm::radians(lens.fov_y_degrees) * 0.5f);
    const float half_w = half_h * std::max(lens.aspect, 1.0f);
    return 1.5f * std::sqrt(lens.near_distance * lens.near_distance + half_h * half_h + half_w * half_w);
}

Camera with_lens(const Camera& lens, const glm::vec3& position, float yaw, float pitch)
{
    Camera c = lens;
    c.position = position;
    c.yaw_degrees = yaw;
    c.pitch_degrees = pitch;
    return c;
}

// For zones without a tree (OBJ levels): a point in open space (mesh_tracer.h) with nothing
// nearer than `clearance` along the 26 directions of good_viewpoint.
bool good_mesh_viewpoint(const MeshTracer& tracer, const glm::vec3& p, float clearance)
{
    if (!tracer.in_open_space(p))
        return false;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz)
                if ((dx || dy || dz) &&
                    tracer.first_hit(p, glm::normalize(glm::vec3(dx, dy, dz)), clearance).hit)
                    return false;
    return true;
}

} // namespace

std::vector<Camera> random_cameras_in_regions(const Zone& zone, size_t count, uint64_t seed, const Camera& lens)
{
    std::vector<Camera> cameras;
    const Aabb box = zone.bounds();
    if (box.empty() || zone.region_count() == 0)
        return cameras;
    std::unique_ptr<MeshTracer> mesh; // zones without a tree place cameras by the mesh
    if (!zone.tree.exists())
        mesh = std::make_unique<MeshTracer>(zone);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z),
        yaw(0.0f, 360.0f), pitch(-60.0f, 60.0f);
    const float clearance = clearance_for(lens);
    cameras.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        for (int attempt = 0; attempt < 10000; ++attempt) {
            const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
            if (mesh ? good_mesh_viewpoint(*mesh, p, clearance) : good_viewpoint(zone, p, clearance)) {
                cameras.push_back(with_lens(lens, p, yaw(rng), pitch(rng)));
                break;
            }
        }
    }
    return cameras;
}

std::vector<Camera> cameras_visiting_every_region(const Zone& zone, uint64_t seed, const Camera& lens)
{
    std::vector<Camera> cameras;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), yaw(0.0f, 360.0f), pitch(-30.0f, 30.0f);
    const float clearance = clearance_for(lens);
    auto fits = [&](const glm::vec3& p, uint32_t r) {
        return locate_point(zone.tree, p).region == int32_t(r) && good_viewpoint(zone, p, clearance);
    };
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const Aabb& b = zone.regions[r].bounds;
        if (b.empty() || (zone.regions[r].flags & kRegionSky))
            continue;
        // The centre first (most regions are convex boxes or close to it), then random points.
        glm::vec3 p = b.center();
        for (int attempt = 0; attempt < 200 && !fits(p, r); ++attempt)
            p = b.min + (b.max - b.min) * glm::vec3(unit(rng), unit(rng), unit(rng));
        if (fits(p, r))
            cameras.push_back(with_lens(lens, p, yaw(rng), pitch(rng)));
    }
    return cameras;
}

} // namespace pvs

namespace pvs {

namespace {

struct PortalGraph {
    std::vector<std::vector<std::pair<uint32_t, glm::vec3>>> links; // region -> (neighbour, portal centre)
    std::vector<glm::vec3> middle;                                  // region -> mean of its portal centres
};

PortalGraph portal_graph(const Zone& zone, const PortalSet& portals)
{
    const size_t regions = zone.region_count();
    PortalGraph g;
    g.links.resize(regions);
    g.middle.assign(regions, glm::vec3(0.0f));
    std::vector<uint32_t> count(regions, 0);
    for (const Portal& p : portals.portals) {
        if (p.point_count == 0 || p.regions[0] < 0 || p.regions[1] < 0 || size_t(p.regions[0]) >= regions ||
            size_t(p.regions[1]) >= regions || size_t(p.first_point) + p.point_count > portals.points.size())
            continue;
        glm::vec3 centre(0.0f);
        for (uint32_t i = 0; i < p.point_count; ++i)
            centre += portals.points[p.first_point + i];
        centre /= float(p.point_count);
        for (int side = 0; side < 2; ++side) {
            const auto r = uint32_t(p.regions[side]);
            g.links[r].emplace_back(uint32_t(p.regions[1 - side]), centre);
            g.middle[r] += centre;
            ++count[r];
        }
    }
    for (size_t r = 0; r < regions; ++r) {
        if (count[r] > 0)
            g.middle[r] /= float(count[r]);
        // The bounds' centre when it lies in the region (a dead end's only portal centre is on
        // its boundary, where a point may belong to the neighbour): both are in the convex
        // region, so the legs between them stay in it.
        const glm::vec3 centre = zone.regions[r].bounds.center();
        if (locate_point(zone.tree, centre).region == int32_t(r))
            g.middle[r] = centre;
    }
    return g;
}

// The tour's corner points: depth first, out through each portal and back the same way.
std::vector<glm::vec3> tour_points(const Zone& zone, PortalGraph& g, std::mt19937_64& rng)
{
    std::vector<uint32_t> starts;
    for (uint32_t r = 0; r < g.links.size(); ++r)
        if (!g.links[r].empty() && !(zone.regions[r].flags & kRegionSky))
            starts.push_back(r);
    if (starts.empty())
        return {};
    for (auto& list : g.links)
        std::shuffle(list.begin(), list.end(), rng);
    const uint32_t start = starts[std::uniform_int_distribution<size_t>(0, starts.size() - 1)(rng)];
    std::vector<uint8_t> seen(g.links.size(), 0);
    struct Frame {
        uint32_t region;
        size_t next = 0;
        glm::vec3 entry; // the portal centre it was entered through
    };
    std::vector<Frame> stack{{start, 0, g.middle[start]}};
    std::vector<glm::vec3> points{g.middle[start]};
    seen[start] = 1;
    while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next == g.links[f.region].size()) {
            const glm::vec3 entry = f.entry;
            stack.pop_back();
            if (!stack.empty()) { // back out the way it came
                points.push_back(entry);
                points.push_back(g.middle[stack.back().region]);
            }
            continue;
        }
        const auto [to, centre] = g.links[f.region][f.next++];
        if (seen[to] || (zone.regions[to].flags & kRegionSky))
            continue;
        seen[to] = 1;
        points.push_back(centre);
        points.push_back(g.middle[to]);
        stack.push_back({to, 0, centre});
    }
    return points;
}

} // namespace

std::vector<Camera> cameras_along_portals(const Zone& zone, const PortalSet& portals, float step, size_t max_cameras,
                                          uint64_t seed, const Camera& lens)
{
    std::vector<Camera> cameras;
    if (!(step > 0.0f) || max_cameras == 0)
        return cameras;
    std::mt19937_64 rng(seed);
    PortalGraph graph = portal_graph(zone, portals);
    const std::vector<glm::vec3> points = tour_points(zone, graph, rng);
    float carried = 0.0f; // distance along the current leg where the next camera goes
    float yaw = 0.0f;
    for (size_t i = 1; i < points.size() && cameras.size() < max_cameras; ++i) {
        const glm::vec3 d = points[i] - points[i - 1];
        const float length = glm::length(d);
        if (length <= 0.0f)
            continue;
        if (std::abs(d.x) + std::abs(d.y) > 1e-3f * length)
            yaw = glm::degrees(std::atan2(d.y, d.x)); // a vertical leg keeps the last heading
        for (; carried < length && cameras.size() < max_cameras; carried += step) {
            Camera c = lens;
            c.position = points[i - 1] + d * (carried / length);
            c.yaw_degrees = yaw;
            c.pitch_degrees = 0.0f;
            cameras.push_back(c);
        }
        carried -= length;
    }
    return cameras;
}

} // namespace pvs
