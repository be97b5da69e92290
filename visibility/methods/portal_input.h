// The portals a portal bake (portal-fast, portal-full) runs on, and where they came from: built
// from the zone's tree (zone_portal_input), or a portal file's that the caller read and hands in
// through MethodSettings::portals. When `clusters` is set the portals join clusters of regions
// (a PRT2 / PRT1-AM file's, or box clusters), and the bake runs over the clusters.
//
// Library code: no output. What a user should hear (a leak, a zone without portals, the clusters
// chosen) is returned as `notes`, one line each, starting "warning:" or "note:" or naming what
// was found; the command prints them.
#pragma once

#include "visibility/portal/portalize.h"
#include "visibility/portal/region_union.h"
#include "visibility/zone.h"

#include <optional>
#include <string>
#include <vector>

namespace pvs {

struct MethodSettings;

struct PortalInput {
    PortalSet portals;
    std::string source = "tree";            // "tree" or the portal file's path
    std::optional<PortalStats> stats;       // built from the tree: what the build met (leaks)
    std::optional<RegionClusters> clusters; // set: `portals` join these clusters
    size_t portals_inside_clusters = 0;     // box clusters: region portals dropped inside one cluster
    double seconds = 0.0;                   // building them (wall clock; 0 for a file's)
    std::vector<std::string> notes;
};

// The portals portal-fast and portal-full bake on when none are given: built from the zone's
// tree with settings.sky, or for a map extruded from 2-D without settings.heights its column
// portals (the 2-D baker's). With settings.box_clusters, and regions that are boxes, the portals
// are grouped into box clusters (box_clusters.h); else a note says the zone is baked per region.
// Throws std::invalid_argument for a zone without a tree (an OBJ level).
PortalInput zone_portal_input(const Zone& zone, const MethodSettings& settings);

// True when the zone's portals go to the 2-D baker (bake_portal_vis_2d): a map extruded from 2-D
// (BspTree::first_height_node), its heights ignored.
bool zone_uses_2d_vis(const Zone& zone, const MethodSettings& settings);

} // namespace pvs
