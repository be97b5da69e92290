// What a user wants to know first about a loaded zone: counts, flags, PVS density, tree shape,
// bounds and memory. Computed from the model alone (no file knowledge), so every format and
// the inspector's zone panel share it. `pvscope info` prints it.
#pragma once

#include "visibility/zone.h"

#include <array>
#include <cstdint>

namespace pvs {

struct PvsDensity {
    bool present = false;
    uint32_t rows = 0;
    uint32_t missing_rows = 0; // rows the file did not have (decoded as all visible)
    double mean_visible = 0;   // mean set bits per row
    uint32_t min_visible = 0;
    uint32_t max_visible = 0;
    // Percentiles of the visible count per row (nearest rank: the smallest count with at least
    // p % of the rows at or below it).
    uint32_t p50_visible = 0, p90_visible = 0, p99_visible = 0;
    double mean_percent = 0;   // mean_visible as a percentage of the region count
    size_t memory_bytes = 0;
    bool dense = false;
};

struct TreeShape {
    uint32_t nodes = 0;
    uint32_t leaves = 0;         // leaves reachable from the root, counted once each
    uint32_t region_leaves = 0;
    uint32_t solid_leaves = 0;   // distinct solid leaves reachable (Quake shares one)
    uint32_t outside_leaves = 0;
    uint32_t max_depth = 0;      // nodes on the longest root-to-leaf path
    double mean_depth = 0;       // mean over reachable leaf references
};

struct ZoneStats {
    uint32_t regions = 0;
    uint32_t faces = 0;
    uint64_t triangles = 0;
    uint32_t vertices = 0;
    uint32_t materials = 0;
    uint32_t materials_with_pixels = 0;
    uint32_t zone_lines = 0;
    uint32_t portals = 0;
    std::array<uint32_t, kRegionFlagCount> flag_counts{}; // regions carrying flag bit i
    uint64_t region_face_refs = 0;                         // total length of all region face lists
    TreeShape tree;
    PvsDensity pvs;
    Aabb bounds;
    size_t memory_bytes = 0;
};

ZoneStats compute_zone_stats(const Zone& zone);
PvsDensity compute_pvs_density(const Pvs& pvs);
TreeShape compute_tree_shape(const BspTree& tree);

} // namespace pvs
