#include "visibility/zone.h"

#include <stdexcept>

namespace pvs {

const char* region_flag_name(uint32_t flag)
{
    switch (flag) {
    case kRegionWater: return "water";
    case kRegionLava: return "lava";
    case kRegionSlime: return "slime";
    case kRegionIce: return "ice";
    case kRegionVWater: return "vwater";
    case kRegionPvp: return "pvp";
    case kRegionZoneLine: return "zone_line";
    case kRegionSky: return "sky";
    default: return "?";
    }
}

void set_material_rgba(Material& material, uint32_t width, uint32_t height, std::span<const uint8_t> rgba)
{
    if (!rgba.empty() && rgba.size() != uint64_t{width} * height * 4)
        throw std::invalid_argument("material '" + material.name + "': " + std::to_string(rgba.size()) +
                                    " bytes of RGBA for " + std::to_string(width) + "x" + std::to_string(height));
    material.width = width;
    material.height = height;
    material.pixels.assign_rgba(rgba);
}

std::vector<uint8_t> material_rgba(const Material& material)
{
    std::vector<uint8_t> rgba;
    material.pixels.decode_rgba(rgba);
    return rgba;
}

int32_t node_reached_twice(const BspTree& tree)
{
    std::vector<uint8_t> seen(tree.nodes.size(), 0);
    std::vector<int32_t> stack{tree.root};
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(child))
            continue;
        if (seen[size_t(child)]++)
            return child;
        stack.push_back(tree.nodes[size_t(child)].children[0]);
        stack.push_back(tree.nodes[size_t(child)].children[1]);
    }
    return -1;
}

Aabb Zone::bounds() const
{
    Aabb box;
    for (const glm::vec3& p : mesh.positions)
        box.grow(p);
    for (const Region& r : regions)
        if (!r.bounds.empty())
            box.grow(r.bounds);
    return box;
}

namespace {
template <class T>
size_t heap_bytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}
size_t heap_bytes(const std::string& s) { return s.capacity() > 15 ? s.capacity() + 1 : 0; }
} // namespace

size_t Zone::memory_bytes() const
{
    size_t total = sizeof(Zone);
    total += heap_bytes(regions) + heap_bytes(tree.nodes) + heap_bytes(tree.leaf_region);
    total += heap_bytes(mesh.positions) + heap_bytes(mesh.uvs) + heap_bytes(mesh.indices) + heap_bytes(mesh.faces);
    total += heap_bytes(materials);
    for (const Material& m : materials)
        total += heap_bytes(m.name) + m.pixels.memory_bytes();
    total += heap_bytes(region_face_offsets) + heap_bytes(region_faces);
    total += heap_bytes(zone_lines);
    for (const ZoneLine& z : zone_lines)
        total += heap_bytes(z.target);
    total += heap_bytes(region_names);
    for (const std::string& name : region_names)
        total += heap_bytes(name);
    total += heap_bytes(region_areas) + heap_bytes(area_portals);
    if (baked_pvs)
        total += baked_pvs->memory_bytes();
    if (portals)
        total += heap_bytes(portals->portals) + heap_bytes(portals->points);
    total += heap_bytes(source.counts) + heap_bytes(source.notes);
    return total;
}

void Zone::shrink_to_fit()
{
    regions.shrink_to_fit();
    tree.nodes.shrink_to_fit();
    tree.leaf_region.shrink_to_fit();
    mesh.positions.shrink_to_fit();
    mesh.uvs.shrink_to_fit();
    mesh.indices.shrink_to_fit();
    mesh.faces.shrink_to_fit();
    materials.shrink_to_fit();
    for (Material& m : materials)
        m.pixels.shrink_to_fit();
    region_face_offsets.shrink_to_fit();
    region_faces.shrink_to_fit();
    zone_lines.shrink_to_fit();
    region_names.shrink_to_fit();
    region_areas.shrink_to_fit();
    area_portals.shrink_to_fit();
}

std::vector<uint8_t> translucent_face_mask(const Zone& zone)
{
    std::vector<uint8_t> mask;
    for (size_t f = 0; f < zone.mesh.faces.size(); ++f) {
        const uint32_t material = zone.mesh.faces[f].material;
        if (material < zone.materials.size() && (zone.materials[material].flags & kMaterialTranslucent)) {
            mask.resize(zone.mesh.faces.size(), 0);
            mask[f] = 1;
        }
    }
    return mask;
}

} // namespace pvs
