#include "visibility/geometry/split_faces.h"

#include "visibility/geometry/bsp_volume.h"

#include <glm/geometric.hpp>

namespace pvs {

namespace {

// Barycentric weights of p in triangle (a, b, c); p lies in the triangle's plane.
glm::vec3 barycentric(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& p)
{
    const glm::vec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const float d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const float d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const float denominator = d00 * d11 - d01 * d01;
    if (denominator == 0.0f)
        return {1.0f, 0.0f, 0.0f};
    const float v = (d11 * d20 - d01 * d21) / denominator;
    const float w = (d00 * d21 - d01 * d20) / denominator;
    return {1.0f - v - w, v, w};
}

struct MeshWriter {
    Mesh& mesh;

    void add_piece(const Winding& piece, const glm::vec3 (&corner)[3], const glm::vec2 (&uv)[3], uint32_t material)
    {
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (const glm::vec3& p : piece.points) {
            const glm::vec3 w = barycentric(corner[0], corner[1], corner[2], p);
            mesh.positions.push_back(p);
            mesh.uvs.push_back(w.x * uv[0] + w.y * uv[1] + w.z * uv[2]);
        }
        Face face;
        face.first_triangle = static_cast<uint32_t>(mesh.indices.size() / 3);
        face.triangle_count = static_cast<uint32_t>(piece.size() - 2);
        face.material = material;
        for (uint32_t k = 1; k + 1 < piece.size(); ++k)
            mesh.indices.insert(mesh.indices.end(), {base, base + k, base + k + 1});
        mesh.faces.push_back(face);
    }
};

} // namespace

Zone clip_faces_to_region_cells(const Zone& zone, float epsilon)
{
    Zone out;
    out.source = zone.source;
    out.regions = zone.regions;
    out.tree = zone.tree;
    out.materials = zone.materials;
    out.zone_lines = zone.zone_lines;
    out.baked_pvs = zone.baked_pvs;
    out.portals = zone.portals;
    out.source.notes.push_back("faces clipped to the BSP cells of the regions that list them");

    std::vector<int32_t> region_leaf(zone.region_count(), -1);
    for (size_t leaf = 0; leaf < zone.tree.leaf_region.size(); ++leaf) {
        const int32_t r = zone.tree.leaf_region[leaf];
        if (r >= 0 && region_leaf[size_t(r)] < 0)
            region_leaf[size_t(r)] = int32_t(leaf);
    }

    MeshWriter writer{out.mesh};
    const Mesh& mesh = zone.mesh;
    out.region_face_offsets.assign(zone.region_count() + 1, 0);
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const std::vector<Plane> planes =
            region_leaf[r] >= 0 ? leaf_bounding_planes(zone.tree, region_leaf[r]) : std::vector<Plane>{};
        for (uint32_t f : zone.faces_of_region(r)) {
            const Face& face = mesh.faces[f];
            for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
                glm::vec3 corner[3];
                glm::vec2 uv[3];
                for (int k = 0; k < 3; ++k) {
                    const uint32_t index = mesh.indices[3 * size_t(t) + size_t(k)];
                    corner[k] = mesh.positions[index];
                    uv[k] = index < mesh.uvs.size() ? mesh.uvs[index] : glm::vec2(0.0f);
                }
                Winding piece = clip_to_planes(Winding{corner[0], corner[1], corner[2]}, planes, epsilon);
                piece.remove_degenerate_points(1e-4f);
                if (piece.size() < 3 || piece.area() <= 1e-6f)
                    continue;
                out.region_faces.push_back(static_cast<uint32_t>(out.mesh.faces.size()));
                writer.add_piece(piece, corner, uv, face.material);
            }
        }
        out.region_face_offsets[r + 1] = static_cast<uint32_t>(out.region_faces.size());
    }
    return out;
}

} // namespace pvs
