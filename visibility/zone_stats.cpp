#include "visibility/zone_stats.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <limits>

namespace pvs {

PvsDensity compute_pvs_density(const Pvs& pvs)
{
    PvsDensity d;
    d.present = true;
    d.rows = pvs.row_count();
    d.missing_rows = pvs.missing_row_count();
    d.memory_bytes = pvs.memory_bytes();
    d.dense = pvs.storage() == Pvs::Storage::Dense;
    if (d.rows == 0)
        return d;
    std::vector<uint64_t> row(pvs.words_per_row());
    std::vector<uint32_t> counts(d.rows);
    uint64_t total = 0;
    d.min_visible = std::numeric_limits<uint32_t>::max();
    for (uint32_t r = 0; r < d.rows; ++r) {
        pvs.decode_row(r, row);
        const auto visible = static_cast<uint32_t>(bits::count(row));
        counts[r] = visible;
        total += visible;
        d.min_visible = std::min(d.min_visible, visible);
        d.max_visible = std::max(d.max_visible, visible);
    }
    std::sort(counts.begin(), counts.end());
    const auto percentile = [&](uint32_t p) { // nearest rank
        const size_t rank = (size_t(p) * counts.size() + 99) / 100;
        return counts[std::max<size_t>(rank, 1) - 1];
    };
    d.p50_visible = percentile(50);
    d.p90_visible = percentile(90);
    d.p99_visible = percentile(99);
    d.mean_visible = static_cast<double>(total) / static_cast<double>(d.rows);
    d.mean_percent = pvs.region_count() ? 100.0 * d.mean_visible / pvs.region_count() : 0.0;
    return d;
}

TreeShape compute_tree_shape(const BspTree& tree)
{
    TreeShape s;
    s.nodes = static_cast<uint32_t>(tree.nodes.size());
    std::vector<uint8_t> leaf_seen(tree.leaf_region.size(), 0);
    uint64_t depth_sum = 0, leaf_refs = 0;
    struct Item {
        int32_t child;
        uint32_t depth;
    };
    std::vector<Item> stack{{tree.root, 0}};
    // Loaders guarantee an acyclic tree; the bound on pops guards the stats against a bad one.
    size_t budget = 2 * (tree.nodes.size() + tree.leaf_region.size()) + 1;
    while (!stack.empty() && budget-- > 0) {
        const Item item = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(item.child)) {
            const int32_t leaf = BspTree::leaf_index(item.child);
            if (size_t(leaf) >= tree.leaf_region.size())
                continue; // no tree at all (an OBJ zone), or a bad leaf reference
            s.max_depth = std::max(s.max_depth, item.depth);
            depth_sum += item.depth;
            ++leaf_refs;
            if (leaf_seen[leaf])
                continue;
            leaf_seen[leaf] = 1;
            ++s.leaves;
            const int32_t region = tree.leaf_region[leaf];
            if (region >= 0)
                ++s.region_leaves;
            else if (region == kLeafSolid)
                ++s.solid_leaves;
            else
                ++s.outside_leaves;
            continue;
        }
        if (size_t(item.child) >= tree.nodes.size())
            continue;
        const BspNode& node = tree.nodes[item.child];
        stack.push_back({node.children[0], item.depth + 1});
        stack.push_back({node.children[1], item.depth + 1});
    }
    s.mean_depth = leaf_refs ? static_cast<double>(depth_sum) / static_cast<double>(leaf_refs) : 0.0;
    return s;
}

ZoneStats compute_zone_stats(const Zone& zone)
{
    ZoneStats s;
    s.regions = static_cast<uint32_t>(zone.regions.size());
    s.faces = static_cast<uint32_t>(zone.mesh.faces.size());
    s.triangles = zone.mesh.triangle_count();
    s.vertices = static_cast<uint32_t>(zone.mesh.positions.size());
    s.materials = static_cast<uint32_t>(zone.materials.size());
    for (const Material& m : zone.materials)
        s.materials_with_pixels += m.has_pixels() ? 1 : 0;
    s.zone_lines = static_cast<uint32_t>(zone.zone_lines.size());
    s.portals = zone.portals ? static_cast<uint32_t>(zone.portals->portals.size()) : 0;
    for (const Region& r : zone.regions)
        for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
            s.flag_counts[bit] += (r.flags >> bit) & 1u;
    s.region_face_refs = zone.region_faces.size();
    s.tree = compute_tree_shape(zone.tree);
    if (zone.baked_pvs)
        s.pvs = compute_pvs_density(*zone.baked_pvs);
    s.bounds = zone.bounds();
    s.memory_bytes = zone.memory_bytes();
    return s;
}

} // namespace pvs
