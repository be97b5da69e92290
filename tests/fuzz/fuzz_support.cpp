#include "tests/fuzz/fuzz_support.h"

namespace pvs::fuzz {

void check_zone(const Zone& zone)
{
    const size_t regions = zone.region_count();
    const Mesh& mesh = zone.mesh;
    fuzz_check(mesh.indices.size() % 3 == 0, "mesh indices come in triangles");
    for (uint32_t i : mesh.indices)
        fuzz_check(i < mesh.positions.size(), "mesh index inside the positions");
    fuzz_check(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size(), "one uv per position");
    for (const Face& f : mesh.faces) {
        fuzz_check(uint64_t(f.first_triangle) + f.triangle_count <= mesh.triangle_count(), "face triangles inside the mesh");
        fuzz_check(f.material < zone.materials.size() || zone.materials.empty(), "face material exists");
    }
    fuzz_check(zone.region_face_offsets.size() == regions + 1, "one face offset per region + 1");
    for (size_t r = 0; r < regions; ++r)
        fuzz_check(zone.region_face_offsets[r] <= zone.region_face_offsets[r + 1], "face offsets ascend");
    fuzz_check(zone.region_face_offsets.back() == zone.region_faces.size(), "face offsets end at the list's end");
    for (uint32_t f : zone.region_faces)
        fuzz_check(f < mesh.faces.size(), "region face exists");
    for (const Region& r : zone.regions)
        fuzz_check(r.zone_line < int32_t(zone.zone_lines.size()), "region zone line exists");
    const BspTree& tree = zone.tree;
    for (int32_t region : tree.leaf_region)
        fuzz_check(region < int32_t(regions) && region >= kLeafOutside, "leaf region exists");
    auto child_ok = [&](int32_t c) {
        return c >= 0 ? size_t(c) < tree.nodes.size() : size_t(BspTree::leaf_index(c)) < tree.leaf_region.size();
    };
    if (tree.exists()) {
        fuzz_check(child_ok(tree.root), "tree root exists");
        for (const BspNode& n : tree.nodes)
            fuzz_check(child_ok(n.children[0]) && child_ok(n.children[1]), "node children exist");
    }
    if (zone.baked_pvs) {
        const Pvs& pvs = *zone.baked_pvs;
        if (zone.view_grid)
            fuzz_check(pvs.region_count() == regions && pvs.row_count() == zone.view_grid->cell_count(),
                       "one grid PVS row per cell, over the regions");
        else
            fuzz_check(pvs.region_count() == regions && pvs.row_count() == regions, "one PVS row per region");
    }
    if (zone.portals) {
        for (const Portal& p : zone.portals->portals)
            fuzz_check(uint64_t(p.first_point) + p.point_count <= zone.portals->points.size(), "portal points exist");
    }
    fuzz_check(zone.region_names.empty() || zone.region_names.size() == regions, "one name per region");
}

} // namespace pvs::fuzz
