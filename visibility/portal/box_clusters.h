// Clusters of regions for clustered portal vis (cluster_vis.h) by merging neighbouring regions
// whose union fills its bounding box, for zones whose regions are boxes (every generated zone:
// wld/gen/kd_bsp.h makes one region per open axis-aligned box). The grouping in use (the
// benchmark's clustered bakes, `pvscope bake --clusters auto`): on generated zones it divides
// the regions by about 2.3 and the portals by 1.6, for +24-37 % mean visible (portal-full), and
// makes 5000 rooms bake in about a third of the CPU time and memory (docs/performance.md,
// "Scaling" and "Clusters"). Quake maps keep leaf-level vis: their leaf bounds are not their
// volumes, so the fill test below means nothing there (regions_are_boxes says no).
//
// Rule. Start with one cluster per region, its box Region::bounds and its volume that box's
// volume. Go through the portals in order, again and again until a pass merges nothing: two
// different clusters A and B joined by a portal merge when
//  - the union's bounding box U is no larger than BoxClusterOptions::max_extent on every axis
//    (0: no bound) and the merged cluster holds at most max_regions regions (0: no bound), and
//  - volume(A) + volume(B) >= min_fill * volume(U) (relative tolerance 1e-4).
// With min_fill = 1 (the default) and disjoint boxes, that is "the union is a box": clusters are
// boxes of open space that the portals connect, so convex. Lower min_fill lets clusters become
// room-sized L shapes and the like (not convex: looser vis, still conservative, cluster_vis.h).
// Regions whose bounds are not boxes of their volume (Quake leaves: their bounds are a box
// around a convex cell) still get clusters; the fill test is then only a heuristic.
//
// Portals naming a region out of range, or the same region twice, are ignored. Clusters are
// numbered in order of their lowest region id. Deterministic (the merge order is the portal
// order). Cost: O(passes × portals), passes are few (each pass merges or ends the loop, and
// at most 64 passes are made: later merges are left undone, which is allowed).
#pragma once

#include "visibility/portal/region_union.h"
#include "visibility/zone.h"

#include <cstdint>
#include <vector>

namespace pvs {

struct BoxClusterOptions {
    float min_fill = 1.0f;   // in (0, 1]
    float max_extent = 0.0f; // zone units per axis; 0 = no bound
    uint32_t max_regions = 0; // 0 = no bound
};

RegionClusters box_merge_clusters(const std::vector<Region>& regions, const PortalSet& portals,
                                  const BoxClusterOptions& options = {});

// Whether the regions look like the disjoint boxes box_merge_clusters is made for, judged from
// the portals (O(portals)): there is at least one portal, and for every portal between two
// regions in range, both regions' bounds are non-empty, they overlap by no more than
// `tolerance` on some axis (they touch, they do not interpenetrate), and every point of the
// portal lies on that axis's touching plane and inside both bounds (within `tolerance`).
// Generated zones pass; Quake maps do not (their leaves' bounds overlap across sloped portals).
bool regions_are_boxes(const std::vector<Region>& regions, const PortalSet& portals, float tolerance = 0.01f);

} // namespace pvs
