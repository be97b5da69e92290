// A sight line from a view cell to an object (grid_witness.h).
#include "visibility/reference/grid_witness.h"

#include "visibility/reference/sample_sequence.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

namespace pvs {
namespace {

using sampling::hash_unit;
using sampling::sample_key;

struct Triangle {
    glm::vec3 a, b, c;
};

// The object's triangles and their cumulative areas.
void object_triangles(const Zone& zone, uint32_t object, std::vector<Triangle>& triangles, std::vector<double>& cumulative)
{
    const Mesh& mesh = zone.mesh;
    double total = 0.0;
    for (uint32_t face : zone.faces_of_region(object)) {
        if (face >= mesh.faces.size())
            continue;
        const Face& f = mesh.faces[face];
        for (uint32_t t = f.first_triangle; t < f.first_triangle + f.triangle_count; ++t) {
            if (size_t(t) * 3 + 2 >= mesh.indices.size())
                break;
            const uint32_t i0 = mesh.indices[size_t(t) * 3], i1 = mesh.indices[size_t(t) * 3 + 1],
                           i2 = mesh.indices[size_t(t) * 3 + 2];
            if (std::max({i0, i1, i2}) >= mesh.positions.size())
                continue;
            const Triangle tri{mesh.positions[i0], mesh.positions[i1], mesh.positions[i2]};
            total += 0.5 * double(glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a)));
            triangles.push_back(tri);
            cumulative.push_back(total);
        }
    }
}

} // namespace

std::optional<SightWitness> find_grid_sight_line(const Zone& zone, const MeshTracer& tracer, uint32_t cell,
                                                 uint32_t object, uint64_t budget, uint64_t seed, uint64_t* tries)
{
    if (tries)
        *tries = 0;
    if (!zone.view_grid || cell >= zone.view_grid->cell_count() || object >= zone.region_count())
        return std::nullopt;
    std::vector<Triangle> triangles;
    std::vector<double> cumulative;
    object_triangles(zone, object, triangles, cumulative);
    if (triangles.empty() || !(cumulative.back() > 0.0))
        return std::nullopt;
    const std::span<const uint32_t> faces = zone.faces_of_region(object);
    const Aabb box = zone.view_grid->cell_bounds(cell);
    const Aabb world = zone.bounds();
    const float reach = glm::length(world.max - world.min) * 2.0f + 1.0f;
    for (uint64_t i = 0; i < budget; ++i) {
        if (tries)
            *tries = i + 1;
        const uint64_t key = sample_key(seed, cell, object, i);
        const glm::vec3 eye = box.min + (box.max - box.min) * glm::vec3(float(hash_unit(key, 0)), float(hash_unit(key, 1)),
                                                                         float(hash_unit(key, 2)));
        const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), hash_unit(key, 3) * cumulative.back());
        const Triangle& tri = triangles[size_t(std::min<ptrdiff_t>(at - cumulative.begin(), ptrdiff_t(triangles.size()) - 1))];
        float s = float(hash_unit(key, 4)), t = float(hash_unit(key, 5));
        if (s + t > 1.0f) {
            s = 1.0f - s;
            t = 1.0f - t;
        }
        const glm::vec3 target = tri.a + s * (tri.b - tri.a) + t * (tri.c - tri.a);
        const glm::vec3 along = target - eye;
        const float length = glm::length(along);
        if (!(length > 1e-4f))
            continue;
        const glm::vec3 direction = along / length;
        const MeshTracer::Hit hit = tracer.first_hit(eye, direction, reach);
        if (!hit.hit || !hit.front || std::find(faces.begin(), faces.end(), hit.face) == faces.end())
            continue;
        if (!tracer.in_open_space(eye)) // the costlier test last
            continue;
        return SightWitness{glm::dvec3(eye), glm::dvec3(eye + hit.t * direction), i + 1};
    }
    return std::nullopt;
}

} // namespace pvs
