// Clusters of regions for clustered portal vis (cluster_vis.h), formed from any zone's BSP tree.
// Measured (docs/performance.md, "Clusters"): generic and loss-free for sight lines
// inside a cluster, but it finds almost nothing on the generated zones and the Quake maps (a
// tree makes a leaf as soon as a cell holds one content, so an all-open subtree needs mixed
// open contents, such as air over water). box_clusters.h is the grouping in use.
//
// Rule. A cluster is a maximal subtree whose leaves are all open and of one medium: every leaf
// is a region (not kLeafSolid, not kLeafOutside, not a region id out of range) and either all
// of them are sky or none is (portalize.h §2.6: air and liquids see through each other, sky
// only sees sky). A node's cell is convex, so such a cluster is a convex cell of open space
// with no wall inside it: grouping its regions loses nothing a wall would have hidden from one
// of them; the price is only that each region now sees what any point of the cell sees.
// ClusterOptions::max_regions bounds a cluster: a subtree with more regions than that is split
// into its children's clusters (0: no bound). An open leaf whose subtrees above all hold
// something closed is a cluster of its own.
//
// Regions reached from several leaves (EverQuest trees may list one region in several leaves)
// join every cluster one of their leaves is in: those clusters merge (union-find), and the
// merged cluster may not be convex, which cluster_vis.h allows (only looser). A region no leaf
// the root reaches names gets a cluster of its own.
//
// Numbering: clusters are numbered in order of their lowest region id, so the identity is what
// a tree gives when no two open leaves can be grouped. Deterministic. The tree walk has no
// recursion (an explicit stack) and visits each node once; a tree whose walk would meet a node
// twice (a cycle or a shared child) is walked as far as it is a tree (nodes already seen are
// ignored), so bad trees cannot hang it.
#pragma once

#include "visibility/portal/region_union.h"
#include "visibility/zone.h"

#include <cstdint>
#include <vector>

namespace pvs {

struct ClusterOptions {
    uint32_t max_regions = 0; // most regions per cluster; 0 = no bound
    // Let a cluster's subtree hold solid and outside leaves too (walls inside the cell): the
    // cluster is then the open part of a convex cell, which may be several rooms. Use with
    // max_regions, or the root is one cluster.
    bool allow_walls = false;
};

// Clusters of tree's regions (region ids index `regions`, flags decide the medium), as above.
RegionClusters bsp_subtree_clusters(const BspTree& tree, const std::vector<Region>& regions,
                                    const ClusterOptions& options = {});

} // namespace pvs
