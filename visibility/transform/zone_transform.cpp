#include "visibility/transform/zone_transform.h"

#include "visibility/reference/sample_sequence.h"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <cmath>
#include <utility>

namespace pvs {

namespace {

// Rotation and mirror as exact maps of float vectors (no matrix products: no rounding).
glm::vec3 turn(const ZoneTransform& t, glm::vec3 v)
{
    switch (t.kind) {
    case ZoneTransform::Kind::Rotate:
        for (int k = 0; k < (t.quarter_turns % 4 + 4) % 4; ++k)
            v = glm::vec3(-v.y, v.x, v.z);
        return v;
    case ZoneTransform::Kind::Mirror: return {-v.x, v.y, v.z};
    default: return v;
    }
}

// A deterministic jitter in [-amount, amount] for item i's component c.
float jitter(const ZoneTransform& t, uint64_t stream, uint64_t i, int c)
{
    const double u = sampling::hash_unit(sampling::sample_key(t.seed, stream, i, 0), uint64_t(c));
    return float((2.0 * u - 1.0) * t.amount);
}

glm::vec3 move_point(const ZoneTransform& t, glm::vec3 p, uint64_t stream, uint64_t i)
{
    switch (t.kind) {
    case ZoneTransform::Kind::Translate: return glm::vec3(glm::dvec3(p) + t.offset);
    case ZoneTransform::Kind::Jitter:
        return p + glm::vec3(jitter(t, stream, i, 0), jitter(t, stream, i, 1), jitter(t, stream, i, 2));
    default: return turn(t, p);
    }
}

Aabb move_box(const ZoneTransform& t, const Aabb& box)
{
    if (box.empty())
        return box;
    if (t.kind == ZoneTransform::Kind::Jitter)
        return box; // bounds are a hint; a jitter of 1e-3 leaves them good enough
    Aabb out;
    for (int corner = 0; corner < 8; ++corner)
        out.grow(move_point(t, {corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                corner & 4 ? box.max.z : box.min.z},
                            0, 0));
    return out;
}

void move_tree(const ZoneTransform& t, BspTree& tree)
{
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        BspNode& node = tree.nodes[i];
        switch (t.kind) {
        case ZoneTransform::Kind::Translate:
            node.dist = float(double(node.dist) + glm::dot(glm::dvec3(node.normal), t.offset));
            break;
        case ZoneTransform::Kind::Jitter: node.dist += jitter(t, 1, i, 0); break;
        default: node.normal = turn(t, node.normal); break;
        }
    }
}

} // namespace

Zone transform_zone(const Zone& zone, const ZoneTransform& t)
{
    Zone out = zone;
    move_tree(t, out.tree);
    for (Region& r : out.regions)
        r.bounds = move_box(t, r.bounds);
    for (ZoneLine& line : out.zone_lines)
        line.bounds = move_box(t, line.bounds);
    for (AreaPortal& portal : out.area_portals)
        portal.bounds = move_box(t, portal.bounds);
    for (size_t i = 0; i < out.mesh.positions.size(); ++i)
        out.mesh.positions[i] = move_point(t, out.mesh.positions[i], 2, i);
    if (t.kind == ZoneTransform::Kind::Mirror) // keep counter-clockwise from the front
        for (size_t k = 0; k + 2 < out.mesh.indices.size(); k += 3)
            std::swap(out.mesh.indices[k + 1], out.mesh.indices[k + 2]);
    if (out.portals) {
        for (size_t i = 0; i < out.portals->points.size(); ++i)
            out.portals->points[i] = move_point(t, out.portals->points[i], 3, i);
        if (t.kind == ZoneTransform::Kind::Mirror) // a portal's winding gives its facing
            for (Portal& p : out.portals->portals) {
                auto first = out.portals->points.begin() + std::ptrdiff_t(p.first_point);
                std::reverse(first, first + std::ptrdiff_t(p.point_count));
            }
    }
    out.source.notes.push_back("transformed: " + t.name);
    return out;
}

std::vector<ZoneTransform> stability_transforms()
{
    std::vector<ZoneTransform> list;
    for (int k : {4, 8, 12, 14, 16}) {
        ZoneTransform t;
        t.kind = ZoneTransform::Kind::Translate;
        t.name = "translate 2^" + std::to_string(k);
        t.offset = glm::dvec3(std::ldexp(1.0, k));
        t.exact = true;
        list.push_back(t);
    }
    for (int q : {1, 2, 3}) {
        ZoneTransform t;
        t.kind = ZoneTransform::Kind::Rotate;
        t.name = "rotate " + std::to_string(90 * q);
        t.quarter_turns = q;
        t.exact = true;
        list.push_back(t);
    }
    ZoneTransform mirror;
    mirror.kind = ZoneTransform::Kind::Mirror;
    mirror.name = "mirror x";
    mirror.exact = true;
    list.push_back(mirror);
    ZoneTransform jitter_all;
    jitter_all.kind = ZoneTransform::Kind::Jitter;
    jitter_all.name = "jitter 0.001";
    jitter_all.amount = 1e-3;
    list.push_back(jitter_all);
    return list;
}

} // namespace pvs
