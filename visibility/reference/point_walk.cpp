#include "visibility/reference/point_walk.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {

namespace {

// How far (zone units) the eye must be on a region's side of a portal to look through it. An eye
// in the portal's plane (on a coplanar neighbour of its own portal: a ramp cut into pieces) sees
// nothing through it, but the planes of coplanar portals, fitted to float points, disagree by
// about 1e-3 a hundred units away (e1m1's ramp by region 225): an eye that near a plane is on
// both sides at once, and the walk went round the ramp's three regions for ever. A line from an
// eye this close to a portal's plane grazes the plane and fails the beam test anyway.
constexpr double kEyeEpsilon = 0.01;
// How far outside a cone plane a clipped point may be and still count as inside it.
constexpr double kClipEpsilon = 1e-9;
// Scratch::sight_of of a stamped region that has no sight (the two sides of the eye's portal).
constexpr uint32_t kNoSight = ~uint32_t{0};

// Twice the area vector of a polygon (Newell's method).
glm::dvec3 area_vector(std::span<const glm::dvec3> points)
{
    glm::dvec3 sum(0.0);
    for (size_t i = 0, n = points.size(); i < n; ++i)
        sum += glm::cross(points[i], points[(i + 1) % n]);
    return sum;
}

glm::dvec3 mean(std::span<const glm::dvec3> points)
{
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points)
        sum += p;
    return sum / double(points.size());
}

// `in` clipped to the half-space dot(normal, x - eye) >= -kClipEpsilon, into `out` (cleared).
void clip_to_plane(const std::vector<glm::dvec3>& in, const glm::dvec3& eye, const glm::dvec3& normal,
                   std::vector<glm::dvec3>& out)
{
    out.clear();
    const size_t n = in.size();
    if (n == 0)
        return;
    double d_prev = glm::dot(normal, in[n - 1] - eye);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& prev = in[(i + n - 1) % n];
        const glm::dvec3& cur = in[i];
        const double d_cur = glm::dot(normal, cur - eye);
        const bool prev_in = d_prev >= -kClipEpsilon, cur_in = d_cur >= -kClipEpsilon;
        if (prev_in != cur_in) // the edge crosses the plane: add the crossing
            out.push_back(prev + (d_prev / (d_prev - d_cur)) * (cur - prev));
        if (cur_in)
            out.push_back(cur);
        d_prev = d_cur;
    }
}

} // namespace

PortalWalker::PortalWalker(const PortalSet& set, const PortalSampler& links, uint32_t region_count)
    : links_(&links), regions_(region_count)
{
    const size_t count = set.portals.size();
    planes_.assign(count, glm::dvec4(0.0));
    point_first_.assign(count + 1, 0);
    front_region_.assign(count, -1);
    back_region_.assign(count, -1);
    for (size_t i = 0; i < count; ++i) {
        const Portal& p = set.portals[i];
        const size_t first = points_.size();
        if (size_t(p.first_point) + p.point_count <= set.points.size())
            for (uint32_t k = 0; k < p.point_count; ++k)
                points_.push_back(glm::dvec3(set.points[p.first_point + k]));
        point_first_[i + 1] = uint32_t(points_.size());
        front_region_[i] = p.regions[0];
        back_region_[i] = p.regions[1];
        const std::span<const glm::dvec3> corners(points_.data() + first, points_.size() - first);
        const glm::dvec3 area = area_vector(corners);
        const double length = glm::length(area);
        if (corners.size() >= 3 && length > 0.0 && std::isfinite(length)) {
            // Clockwise seen from the front (portalize.h): the area vector points to the back.
            const glm::dvec3 normal = -area / length;
            planes_[i] = glm::dvec4(normal, glm::dot(normal, mean(corners)));
        }
    }
}

glm::dvec3 PortalWalker::boundary_point(uint32_t portal, double u, double inset) const
{
    const std::span<const glm::dvec3> corners(points_.data() + point_first_[portal],
                                              point_first_[portal + 1] - point_first_[portal]);
    double perimeter = 0.0;
    for (size_t i = 0; i < corners.size(); ++i)
        perimeter += glm::length(corners[(i + 1) % corners.size()] - corners[i]);
    double at = u * perimeter;
    glm::dvec3 point = corners[0];
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a = corners[i], b = corners[(i + 1) % corners.size()];
        const double length = glm::length(b - a);
        if (at <= length || i + 1 == corners.size()) {
            point = a + (length > 0.0 ? std::min(1.0, at / length) : 0.0) * (b - a);
            break;
        }
        at -= length;
    }
    const glm::dvec3 to_centre = mean(corners) - point;
    const double distance = glm::length(to_centre);
    return distance > 0.0 ? point + std::min(inset, 0.5 * distance) / distance * to_centre : point;
}

void PortalWalker::walk(const glm::dvec3& eye, uint32_t portal, uint32_t from, Scratch& scratch) const
{
    scratch.sights.clear();
    scratch.sight_area.clear();
    scratch.pool.clear();
    scratch.cones.clear();
    scratch.windows = 0;
    scratch.truncated = false;
    if (scratch.stamp.size() != regions_) {
        scratch.stamp.assign(regions_, 0);
        scratch.sight_of.assign(regions_, 0);
        scratch.walk = 0;
    }
    if (++scratch.walk == 0) { // the stamps wrapped: start again
        std::fill(scratch.stamp.begin(), scratch.stamp.end(), 0);
        scratch.walk = 1;
    }
    const int32_t into = front_region_[portal] == int32_t(from) ? back_region_[portal] : front_region_[portal];
    if (into < 0 || uint32_t(into) >= regions_ || from >= regions_)
        return;
    // Neither side of the eye's own portal is listed (nor reached again: the regions are convex).
    scratch.stamp[from] = scratch.stamp[size_t(into)] = scratch.walk;
    scratch.sight_of[from] = scratch.sight_of[size_t(into)] = kNoSight;
    enter(eye, uint32_t(into), portal, 0, 0, 0, scratch);
}

void PortalWalker::enter(const glm::dvec3& eye, uint32_t region, uint32_t came_through, size_t window_first,
                         size_t window_count, uint32_t depth, Scratch& scratch) const
{
    // The cone over the window: one plane through the eye per edge, normal inward. The first
    // region (no window) has the whole half-space beyond the eye's portal in view, which every
    // portal of it with the eye on the region's side lies in.
    const size_t cone_first = scratch.cones.size();
    if (window_count) {
        const std::span<const glm::dvec3> window(scratch.pool.data() + window_first, window_count);
        const glm::dvec3 inside = mean(window) - eye;
        for (size_t i = 0; i < window_count; ++i) {
            glm::dvec3 normal = glm::cross(window[i] - eye, window[(i + 1) % window_count] - eye);
            const double length = glm::length(normal);
            if (!(length > 0.0) || !std::isfinite(length))
                continue; // a degenerate edge: leaving its plane out only widens the cone
            normal /= length;
            scratch.cones.push_back(glm::dot(normal, inside) < 0.0 ? -normal : normal);
        }
    }
    const size_t cone_end = scratch.cones.size();

    for (const PortalSampler::Link& link : links_->links(region)) {
        if (link.portal == came_through)
            continue;
        const glm::dvec4 plane = planes_[link.portal];
        double side = glm::dot(glm::dvec3(plane), eye) - plane.w;
        if (front_region_[link.portal] != int32_t(region))
            side = -side;
        if (!(side > kEyeEpsilon))
            continue;
        if (++scratch.windows > kMaxWindowsPerWalk) {
            scratch.truncated = true;
            break;
        }
        std::vector<glm::dvec3>* cur = &scratch.clip[0];
        std::vector<glm::dvec3>* next = &scratch.clip[1];
        cur->assign(points_.begin() + point_first_[link.portal], points_.begin() + point_first_[link.portal + 1]);
        for (size_t c = cone_first; c < cone_end && cur->size() >= 3; ++c) {
            clip_to_plane(*cur, eye, scratch.cones[c], *next);
            std::swap(cur, next);
        }
        if (cur->size() < 3 || cur->size() > kMaxWindowPoints)
            continue;
        const double area = 0.5 * glm::length(area_vector(*cur));
        if (!(area >= kMinWindowArea))
            continue;
        const uint32_t behind = link.other;
        if (scratch.stamp[behind] != scratch.walk) {
            scratch.stamp[behind] = scratch.walk;
            scratch.sight_of[behind] = uint32_t(scratch.sights.size());
            scratch.sights.push_back({behind, mean(*cur)});
            scratch.sight_area.push_back(area);
        } else if (scratch.sight_of[behind] != kNoSight && area > scratch.sight_area[scratch.sight_of[behind]]) {
            scratch.sights[scratch.sight_of[behind]].aim = mean(*cur);
            scratch.sight_area[scratch.sight_of[behind]] = area;
        }
        if (depth + 1 >= kMaxDepth) {
            scratch.truncated = true;
            continue;
        }
        const size_t next_first = scratch.pool.size();
        scratch.pool.insert(scratch.pool.end(), cur->begin(), cur->end());
        enter(eye, behind, link.portal, next_first, scratch.pool.size() - next_first, depth + 1, scratch);
        scratch.pool.resize(next_first);
        if (scratch.truncated && scratch.windows > kMaxWindowsPerWalk)
            break;
    }
    scratch.cones.resize(cone_first);
}

} // namespace pvs
