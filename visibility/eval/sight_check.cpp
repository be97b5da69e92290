#include "visibility/eval/sight_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/geometric.hpp>

namespace pvs {

SightCheck::SightCheck(const Zone& zone, SkyPortals sky) : zone_(&zone), tracer_(zone.tree, zone.regions, sky)
{
    const Mesh& mesh = zone.mesh;
    planes_.resize(mesh.faces.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            if (3 * size_t(t) + 2 >= mesh.indices.size())
                break;
            const glm::dvec3 a(mesh.positions[mesh.indices[3 * size_t(t)]]);
            const glm::dvec3 b(mesh.positions[mesh.indices[3 * size_t(t) + 1]]);
            const glm::dvec3 c(mesh.positions[mesh.indices[3 * size_t(t) + 2]]);
            const glm::dvec3 n = glm::cross(b - a, c - a);
            const double length = glm::length(n);
            if (length > 1e-9) {
                planes_[f] = {n / length, glm::dot(n / length, a), true};
                break;
            }
        }
    }
    if (!zone.tree.exists() && !mesh.faces.empty()) {
        mesh_ = std::make_unique<MeshTracer>(zone);
        face_region_.assign(mesh.faces.size(), -1);
        for (auto r = uint32_t(zone.region_count()); r-- > 0;) // the lowest region listing a face wins
            for (uint32_t f : zone.faces_of_region(r))
                if (f < face_region_.size())
                    face_region_[f] = int32_t(r);
    }
}

SightCheck::~SightCheck() = default;

SightResult SightCheck::face_along_mesh_ray(const glm::dvec3& eye, const glm::dvec3& direction, uint32_t face) const
{
    SightResult result;
    const MeshTracer::Hit hit =
        mesh_->first_hit(glm::vec3(eye), glm::vec3(direction), std::numeric_limits<float>::infinity());
    if (!hit.hit)
        return result;
    result.hit_distance = double(hit.t);
    if (hit.face != face || !hit.front) {
        result.sight = Sight::Blocked;
        return result;
    }
    result.sight = Sight::Open;
    result.end_region = face < face_region_.size() ? face_region_[face] : -1;
    return result;
}

SightResult SightCheck::face_along_ray(const glm::dvec3& eye, const glm::dvec3& direction, uint32_t face,
                                       TreeTracer::Scratch& scratch) const
{
    if (mesh_)
        return face_along_mesh_ray(eye, direction, face);
    SightResult result;
    if (!tracer_.has_tree() || face >= planes_.size() || !planes_[face].valid)
        return result;
    const FacePlane& plane = planes_[face];
    const double facing = glm::dot(plane.normal, direction);
    const double t_hit = (plane.dist - glm::dot(plane.normal, eye)) / facing;
    if (!(facing < 0.0) || !(t_hit > 0.0) || !std::isfinite(t_hit))
        return result;
    const double backoff = std::min({kSightBackoff / -facing, kSightBackoffMax, 0.5 * t_hit});
    const double length = t_hit - backoff;
    const TraceEnd end = tracer_.trace(eye, direction, length, scratch, [](int32_t, double, double) {});
    result.hit_distance = t_hit;
    result.sight = end.blocked ? Sight::Blocked : Sight::Open;
    result.end_region = end.blocked ? -1 : end.last_region;
    if (end.blocked && end.refused_region >= 0 && end.last_region >= 0 &&
        !face_closes(eye, direction, end.t, end.last_region, end.refused_region, face))
        result.sight = Sight::Unfaced;
    if (result.sight == Sight::Open && !region_lists(end.last_region, face))
        follow_to_the_face(eye, direction, t_hit, -facing, face, scratch, result);
    if (result.sight == Sight::Open && !tracer_.open_beam(eye, direction, length, kSightMargin, scratch))
        result.sight = Sight::Grazing;
    return result;
}

bool SightCheck::region_lists(int32_t region, uint32_t face) const
{
    if (region < 0 || size_t(region) >= zone_->region_count())
        return false;
    const std::span<const uint32_t> faces = zone_->faces_of_region(uint32_t(region));
    return std::find(faces.begin(), faces.end(), face) != faces.end();
}

// The backoff can stop a line short of a boundary it crosses just before the face: near the
// face's edge, where the face lies on the far side of a corner. Traced on to the face's plane:
// across a boundary the content rule closes and no face does, the pixel is Unfaced; ending in a
// region that lists the face, that region is where the line ends. Else as the short trace said.
// A boundary within kUnfacedMargin of the face's plane may be the face's own (a water surface
// the region in front does not list): it counts for nothing.
void SightCheck::follow_to_the_face(const glm::dvec3& eye, const glm::dvec3& direction, double t_hit,
                                    double cos_incidence, uint32_t face, TreeTracer::Scratch& scratch,
                                    SightResult& result) const
{
    const TraceEnd end = tracer_.trace(eye, direction, t_hit, scratch, [](int32_t, double, double) {});
    if (end.blocked) {
        const bool off_the_face = (t_hit - end.t) * cos_incidence > kUnfacedMargin;
        if (off_the_face && end.refused_region >= 0 && end.last_region >= 0 &&
            !face_closes(eye, direction, end.t, end.last_region, end.refused_region, face)) {
            result.sight = Sight::Unfaced;
            result.end_region = -1;
        }
        return;
    }
    if (region_lists(end.last_region, face))
        result.end_region = end.last_region;
}

bool SightCheck::face_closes(const glm::dvec3& eye, const glm::dvec3& direction, double t, int32_t region_a,
                             int32_t region_b, uint32_t seen_face) const
{
    for (const int32_t region : {region_a, region_b}) {
        if (size_t(region) >= zone_->region_count())
            continue;
        for (const uint32_t f : zone_->faces_of_region(uint32_t(region))) {
            if (f >= zone_->mesh.faces.size() || f == seen_face)
                continue;
            const Face& face = zone_->mesh.faces[f];
            for (uint32_t triangle = face.first_triangle; triangle < face.first_triangle + face.triangle_count;
                 ++triangle)
                if (ray_crosses_triangle(triangle, eye, direction, t))
                    return true;
        }
    }
    return false;
}

// The ray meets the triangle's plane within kUnfacedMargin of t (along the ray), at a point on
// the inner side of each edge's line moved out by the margin (a little more than the margin near
// the corners: it errs towards "closed"). A face across the line's way, not one beside it: a wall
// the crossing point lies near but the ray runs along does not close the boundary.
bool SightCheck::ray_crosses_triangle(uint32_t triangle, const glm::dvec3& eye, const glm::dvec3& direction,
                                      double t) const
{
    const Mesh& mesh = zone_->mesh;
    if (3 * size_t(triangle) + 2 >= mesh.indices.size())
        return false;
    glm::dvec3 corner[3];
    for (int i = 0; i < 3; ++i) {
        const uint32_t index = mesh.indices[3 * size_t(triangle) + size_t(i)];
        if (index >= mesh.positions.size())
            return false;
        corner[i] = glm::dvec3(mesh.positions[index]);
    }
    const glm::dvec3 normal = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
    const double area2 = glm::length(normal);
    if (!(area2 > 1e-9))
        return false;
    const glm::dvec3 n = normal / area2;
    const double facing = glm::dot(n, direction);
    if (facing == 0.0)
        return false;
    const double t_plane = glm::dot(n, corner[0] - eye) / facing;
    if (!(std::abs(t_plane - t) <= kUnfacedMargin))
        return false;
    const glm::dvec3 point = eye + t_plane * direction;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3& a = corner[i];
        const glm::dvec3 edge = corner[(i + 1) % 3] - a;
        const double length = glm::length(edge);
        if (!(length > 1e-9))
            continue;
        const glm::dvec3 inward = glm::cross(n, edge) / length; // counter-clockwise about n: inward
        if (glm::dot(inward, point - a) < -kUnfacedMargin)
            return false;
    }
    return true;
}

} // namespace pvs
