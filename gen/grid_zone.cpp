#include "gen/grid_zone.h"

#include "gen/gen_textures.h"
#include "gen/kd_bsp.h"

#include <utility>

namespace pvs::gen {

namespace {

constexpr float kTextureRepeat = 128.0f; // world units per texture repeat

uint32_t region_flags(Cell c)
{
    switch (c) {
    case Cell::Water: return kRegionWater;
    case Cell::Lava: return kRegionLava;
    case Cell::Slime: return kRegionSlime;
    case Cell::Pvp: return kRegionPvp;
    case Cell::ZoneLine: return kRegionZoneLine;
    default: return 0;
    }
}

bool is_liquid(Cell c) { return c == Cell::Water || c == Cell::Lava || c == Cell::Slime; }

Surface liquid_surface(Cell c)
{
    return c == Cell::Water ? Surface::Water : c == Cell::Lava ? Surface::Lava : Surface::Slime;
}

// What a region of content `inside` shows on a boundary cell whose neighbour is `outside`,
// seen from inside, on a side facing `normal_axis_sign` (the side's direction out of the box:
// -z is the floor, +z the ceiling). Nothing (-1) between open cells of compatible content.
int surface_for(Cell inside, Cell outside, int axis, int dir)
{
    if (outside == Cell::Solid) {
        if (is_liquid(inside))
            return int(liquid_surface(inside)); // the pool's sides and bottom
        if (inside == Cell::ZoneLine)
            return int(Surface::ZoneLine);
        if (axis == 2)
            return dir < 0 ? int(inside == Cell::Pvp ? Surface::Pvp : Surface::Floor) : int(Surface::Ceiling);
        return int(Surface::Wall);
    }
    if (is_liquid(outside) != is_liquid(inside))
        return int(liquid_surface(is_liquid(outside) ? outside : inside)); // a liquid surface
    if (outside == Cell::ZoneLine && inside != Cell::ZoneLine)
        return int(Surface::ZoneLine); // the shimmering doorway, seen from the corridor
    return -1;
}

struct MeshBuilder {
    const VoxelLevel& level;
    const GridAxes& axes;
    Zone& zone;
    std::vector<int> mask;

    glm::vec3 corner(int axis, int plane, int u, int v) const
    {
        glm::ivec3 c;
        c[axis] = plane;
        c[(axis + 1) % 3] = u;
        c[(axis + 2) % 3] = v;
        return axes.corner(c);
    }

    void quad(int axis, int dir, int plane, int u0, int v0, int u1, int v1, int surface)
    {
        glm::vec3 p[4] = {corner(axis, plane, u0, v0), corner(axis, plane, u1, v0), corner(axis, plane, u1, v1),
                          corner(axis, plane, u0, v1)};
        // (u, v, axis) is right-handed, so this order faces +axis; the face must look into the
        // box, which is -dir along the axis.
        if (dir > 0)
            std::swap(p[1], p[3]);
        const auto base = static_cast<uint32_t>(zone.mesh.positions.size());
        const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
        for (const glm::vec3& q : p) {
            zone.mesh.positions.push_back(q);
            zone.mesh.uvs.emplace_back(q[ua] / kTextureRepeat, q[va] / kTextureRepeat);
        }
        Face face;
        face.first_triangle = static_cast<uint32_t>(zone.mesh.indices.size() / 3);
        face.triangle_count = 2;
        face.material = uint32_t(surface);
        zone.mesh.indices.insert(zone.mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        zone.region_faces.push_back(static_cast<uint32_t>(zone.mesh.faces.size()));
        zone.mesh.faces.push_back(face);
    }

    // One side of a region's box: a mask of what each boundary cell shows, merged greedily
    // into rectangles of one surface.
    void side(const LeafBox& box, int axis, int dir)
    {
        const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
        const int nu = box.hi[ua] - box.lo[ua], nv = box.hi[va] - box.lo[va];
        const int plane = dir < 0 ? box.lo[axis] : box.hi[axis];
        const int outside_layer = dir < 0 ? box.lo[axis] - 1 : box.hi[axis];
        mask.assign(size_t(nu) * size_t(nv), -1);
        for (int v = 0; v < nv; ++v)
            for (int u = 0; u < nu; ++u) {
                glm::ivec3 c;
                c[axis] = outside_layer;
                c[ua] = box.lo[ua] + u;
                c[va] = box.lo[va] + v;
                mask[size_t(v) * size_t(nu) + size_t(u)] = surface_for(box.content, level.at(c.x, c.y, c.z), axis, dir);
            }
        for (int v = 0; v < nv; ++v)
            for (int u = 0; u < nu;) {
                const int s = mask[size_t(v) * size_t(nu) + size_t(u)];
                if (s < 0) {
                    ++u;
                    continue;
                }
                int w = 1;
                while (u + w < nu && mask[size_t(v) * size_t(nu) + size_t(u + w)] == s)
                    ++w;
                int h = 1;
                for (bool grow = true; grow && v + h < nv; h += grow ? 1 : 0)
                    for (int k = 0; k < w && grow; ++k)
                        grow = mask[size_t(v + h) * size_t(nu) + size_t(u + k)] == s;
                for (int dv = 0; dv < h; ++dv)
                    for (int k = 0; k < w; ++k)
                        mask[size_t(v + dv) * size_t(nu) + size_t(u + k)] = -1;
                quad(axis, dir, plane, box.lo[ua] + u, box.lo[va] + v, box.lo[ua] + u + w, box.lo[va] + v + h, s);
                u += w;
            }
    }
};

} // namespace

Zone build_grid_zone(const VoxelLevel& level, const GridAxes& axes, std::span<const uint32_t> labels)
{
    KdBsp bsp = build_kd_bsp(level, axes, labels);
    Zone zone;
    zone.tree = std::move(bsp.tree);
    zone.materials = make_gen_materials();

    Aabb zone_line_box;
    MeshBuilder mesh{level, axes, zone, {}};
    zone.regions.resize(bsp.region_leaf.size());
    zone.region_face_offsets.assign(bsp.region_leaf.size() + 1, 0);
    for (size_t r = 0; r < bsp.region_leaf.size(); ++r) {
        const LeafBox& box = bsp.leaves[bsp.region_leaf[r]];
        Region& region = zone.regions[r];
        region.bounds.grow(axes.corner(box.lo));
        region.bounds.grow(axes.corner(box.hi));
        region.flags = region_flags(box.content);
        if (box.content == Cell::ZoneLine) {
            region.zone_line = 0;
            zone_line_box.grow(region.bounds);
        }
        for (int axis = 0; axis < 3; ++axis)
            for (int dir : {-1, 1})
                mesh.side(box, axis, dir);
        zone.region_face_offsets[r + 1] = static_cast<uint32_t>(zone.region_faces.size());
    }
    if (!zone_line_box.empty())
        zone.zone_lines.push_back({"gen_next_zone", zone_line_box});
    return zone;
}

} // namespace pvs::gen
