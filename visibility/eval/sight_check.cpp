#include "visibility/eval/sight_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/geometric.hpp>

namespace pvs {

SightCheck::SightCheck(const Zone& zone, SkyPortals sky) : tracer_(zone.tree, zone.regions, sky)
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
    if (result.sight == Sight::Open && !tracer_.open_beam(eye, direction, length, kSightMargin, scratch))
        result.sight = Sight::Grazing;
    return result;
}

} // namespace pvs
