// Portal vis over clusters of regions (../shared/formats/quake-doom-hepvs.md §2.2 PRT2, §3.1,
// §3.5, §3.8 item 9): the portals between regions become portals between the clusters holding
// them, bake_portal_vis (portal_vis.h) runs at cluster level, and the cluster rows are expanded
// back to regions: region r sees region s exactly when cluster(r) sees cluster(s). This is what
// ericw-tools' vis does with detail clusters (PRT2); here the grouping is any map a caller gives
// (box_clusters.h forms them for zones whose regions are boxes; RegionClusters is in
// region_union.h).
//
// Why the result is conservative for ANY grouping (every region pair the leaf-level flow finds
// visible, and every pair a real sight line joins, is visible here):
//  - A real sight line from a point of region r to a point of region s crosses a sequence of
//    region portals. Drop the portals inside one cluster (both sides in the same cluster: they
//    are not cluster portals) and cut out every loop (where the line leaves a cluster and later
//    re-enters it, drop the part in between): what is left is a sequence of cluster portals
//    through distinct clusters, from cluster(r) to cluster(s), and the same line passes through
//    every portal of it in order. The flow explores exactly such chains (it never re-enters a
//    cluster already on its chain), and each of its tests (mightsee flood, clipping the target
//    by the source's and pass's planes, the separating planes of test levels 0-4) only removes
//    parts that no line through the portals of the chain can cross, and the real line does
//    cross them: so it keeps cluster(s) in the row of the portal it left cluster(r) through.
//  - A region's row is its cluster's row, the union over all portals leaving the cluster: any
//    line from the region is a line from the cluster.
//  - Nothing above uses the convexity of a cluster: a non-convex cluster only makes the
//    result looser (its portals see through it as if its inside were empty space).
// The identity grouping (cluster_of_region[r] = r) gives bake_portal_vis's rows exactly.
// Quality (mean visible per region) depends on the grouping: the coarser, the looser.
//
// Input. `region_portals` as for bake_portal_vis (PRT1 orientation), with region ids in
// [0, cluster_of_region.size()). cluster_of_region[r] is region r's cluster in
// [0, cluster_count); a cluster with no region is allowed (its row is unused). Portals whose
// two sides lie in one cluster are dropped (ClusterReport::portals_inside_clusters); portals
// with a negative region id are passed on as unusable, so bake_portal_vis skips and counts them
// (VisReport::portals_skipped), as it would at region level. Throws std::invalid_argument (the
// message names the region or portal and the bad value) when the map does not fit the input: a
// cluster id out of range, cluster_count 0 with regions present, or a portal naming a region at
// or past cluster_of_region.size() (the map is too short for these portals).
//
// Output. A Pvs of cluster_of_region.size() rows. Rows are expanded cluster by cluster: each
// cluster's regions are kept as (word, mask) pairs, so a row is the word-wise OR of the pairs of
// the clusters it sees (a handful of words per cluster when its region ids are close together),
// and the rows of a cluster's regions are one row: the expansion runs once per run of
// consecutive regions of one cluster, and Pvs::build stores identical rows once.
//
// Params and report. `params` go to the cluster-level bake unchanged (method, level, threads,
// progress, cancellation: a cancelled bake gives bake_portal_vis's conservative cluster rows,
// expanded). `report`, when given, is bake_portal_vis's report of the cluster-level bake, except
// seconds (the whole call), mean_visible (per region of the result) and peak_bytes_estimate
// (the larger of the cluster bake's and the expansion's, plus the cluster portals' copy).
// `cluster_report`, when given, gets the cluster figures. Both are overwritten.
//
// Cost. The cluster-level bake, plus O(points) to copy the portals, O(regions) for the map,
// and per run of consecutive regions of one cluster the OR of the visible clusters' pairs.
// Measured on generated zones (docs/performance.md, "Scaling"): at 5000 rooms the expansion
// takes 0.3 s of a 31-s portal-full bake, and 2.2 s of a 27-s portal-fast one, whose rows are
// half full (ClusterReport::expand_seconds, which includes Pvs::build compressing the rows).
#pragma once

#include "visibility/portal/portal_vis.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace pvs {

struct ClusterReport {
    uint32_t regions = 0;
    uint32_t clusters = 0;                // cluster_count as given
    size_t region_portals = 0;            // region_portals.portals.size()
    size_t cluster_portals = 0;           // portals handed to the cluster-level bake
    size_t portals_inside_clusters = 0;   // dropped: both sides in one cluster
    double cluster_mean_visible = 0.0;    // mean visible clusters per cluster row
    double expand_seconds = 0.0;          // expanding cluster rows to region rows (wall clock)
};

// The PVS of cluster_of_region.size() regions from their portals, baked over clusters (above):
// cluster_portal_set, then bake_cluster_portal_vis.
Pvs bake_clustered_portal_vis(const PortalSet& region_portals, std::span<const uint32_t> cluster_of_region,
                              uint32_t cluster_count, const VisParams& params, VisReport* report = nullptr,
                              ClusterReport* cluster_report = nullptr);

// The portals between clusters: region_portals with each side renamed to its cluster (negative
// sides kept, for bake_portal_vis to skip), the portals inside one cluster dropped (their count
// in *portals_inside_clusters when given), points copied unchanged. Validates as above.
PortalSet cluster_portal_set(const PortalSet& region_portals, std::span<const uint32_t> cluster_of_region,
                             uint32_t cluster_count, size_t* portals_inside_clusters = nullptr);

// The region PVS from portals that already name clusters (a PRT2 or PRT1-AM file, §2.2-§2.3, or
// cluster_portal_set's result): bake_portal_vis over cluster_count clusters, rows expanded to
// the cluster_of_region.size() regions (§3.5 step 2). Validates the map as above (the portals'
// cluster ids are bake_portal_vis's to check: out of range, skipped and counted). Reports as
// above; ClusterReport::region_portals and portals_inside_clusters stay 0.
Pvs bake_cluster_portal_vis(const PortalSet& cluster_portals, std::span<const uint32_t> cluster_of_region,
                            uint32_t cluster_count, const VisParams& params, VisReport* report = nullptr,
                            ClusterReport* cluster_report = nullptr);

} // namespace pvs
