#include "visibility/methods/portal_input.h"

#include "visibility/bsp_tree_edit.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"

#include <chrono>
#include <stdexcept>

namespace pvs {

namespace {

PortalSet build_method_portals(const Zone& zone, const MethodSettings& s, PortalStats* stats)
{
    if (!zone.tree.exists() || zone.view_grid)
        throw std::invalid_argument("portal vis needs a BSP tree, and " + zone.source.path +
                                    " has none (an OBJ level: its cells are a grid)");
    PortalOptions options;
    options.sky = s.sky;
    if (zone_uses_2d_vis(zone, s)) {
        // A 2-D method (glVIS): every region a column as high as the world, so sight passes
        // over and under every step and door. The portals are those of the column tree.
        return build_portals(without_height_nodes(zone.tree), zone.regions, zone_portal_world(zone), options, stats);
    }
    return build_zone_portals(zone, options, stats);
}

// Box clusters when the regions are boxes (generated zones): the portals between clusters.
void group_into_box_clusters(const Zone& zone, PortalInput& in)
{
    if (!regions_are_boxes(zone.regions, in.portals)) {
        in.notes.push_back("note: --clusters auto: the regions of " + zone.source.path +
                           " are not boxes; baked per region");
        return;
    }
    in.clusters = box_merge_clusters(zone.regions, in.portals);
    in.portals = cluster_portal_set(in.portals, in.clusters->cluster_of_region, in.clusters->cluster_count,
                                    &in.portals_inside_clusters);
    in.notes.push_back("clusters: " + std::to_string(zone.region_count()) + " regions in " +
                       std::to_string(in.clusters->cluster_count) + " box clusters");
}

} // namespace

bool zone_uses_2d_vis(const Zone& zone, const MethodSettings& settings)
{
    return zone.tree.has_height_nodes() && !settings.heights;
}

PortalInput zone_portal_input(const Zone& zone, const MethodSettings& settings)
{
    const auto start = std::chrono::steady_clock::now();
    PortalInput in;
    // A column tree's every leaf reaches the world box's floor and ceiling: no leak to report.
    if (!zone_uses_2d_vis(zone, settings))
        in.stats.emplace();
    in.portals = build_method_portals(zone, settings, in.stats ? &*in.stats : nullptr);
    // Only the world box: an EverQuest zone's walls are region-less (outside) leaves, so leaves
    // next to them are normal there.
    if (const size_t open = in.stats ? in.stats->leaves_touching_world.size() : 0; open > 0)
        in.notes.push_back("warning: " + zone.source.path + " leaks: " + std::to_string(open) +
                           " open leaves touch the world box; no portal leads outside, the PVS covers the open "
                           "leaves only");
    if (settings.box_clusters)
        group_into_box_clusters(zone, in);
    in.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return in;
}

} // namespace pvs
