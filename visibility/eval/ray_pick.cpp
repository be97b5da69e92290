#include "visibility/eval/ray_pick.h"

#include <glm/geometric.hpp>
#include <limits>

namespace pvs {

RayHit first_face_hit(const Zone& zone, const glm::vec3& origin, const glm::vec3& direction)
{
    RayHit best;
    best.distance = std::numeric_limits<float>::max();
    const Mesh& mesh = zone.mesh;
    for (uint32_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            const glm::vec3& a = mesh.positions[mesh.indices[3 * size_t(t)]];
            const glm::vec3& b = mesh.positions[mesh.indices[3 * size_t(t) + 1]];
            const glm::vec3& c = mesh.positions[mesh.indices[3 * size_t(t) + 2]];
            const glm::vec3 e1 = b - a, e2 = c - a;
            const glm::vec3 p = glm::cross(direction, e2);
            const float det = glm::dot(e1, p);
            if (det <= 1e-12f) // back-facing or parallel (front faces have det > 0 for a ray into them)
                continue;
            const glm::vec3 s = origin - a;
            const float u = glm::dot(s, p) / det;
            if (u < 0.0f || u > 1.0f)
                continue;
            const glm::vec3 q = glm::cross(s, e1);
            const float v = glm::dot(direction, q) / det;
            if (v < 0.0f || u + v > 1.0f)
                continue;
            const float distance = glm::dot(e2, q) / det;
            if (distance > 0.0f && distance < best.distance) {
                best.distance = distance;
                best.face = int32_t(f);
            }
        }
    }
    if (best.face < 0)
        best.distance = 0.0f;
    return best;
}

} // namespace pvs
