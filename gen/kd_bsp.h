// A BSP tree for a voxel level: axis-aligned split planes on cell boundaries, chosen where the
// most neighbouring cells differ (room walls, floors, liquid surfaces), until every leaf is a box
// of one content. Open boxes become regions (convex, one content, so one set of flags); solid
// boxes become outside leaves, as EverQuest's region-less leaves are.
//
// Front is the high side of each plane; a point exactly on a plane goes front
// (TieRule::OnPlaneGoesFront, the EverQuest rule), which matches cell index = floor(coordinate).
#pragma once

#include "visibility/zone.h"
#include "gen/grid_axes.h"
#include "gen/voxel_level.h"

#include <span>

#include <vector>

namespace pvs::gen {

struct LeafBox {
    glm::ivec3 lo, hi; // cells lo <= c < hi
    Cell content;
};

struct KdBsp {
    BspTree tree;
    std::vector<LeafBox> leaves;     // parallel to tree.leaf_region
    std::vector<uint32_t> region_leaf; // region id -> leaf index
};

// axes: where the cell boundaries lie (grid_axes.h). labels (optional, one per cell as
// level.cells): cells of one content but different labels are kept apart as if their contents
// differed, so that each labelled box of a stability case becomes its own leaves.
KdBsp build_kd_bsp(const VoxelLevel& level, const GridAxes& axes, std::span<const uint32_t> labels = {});

} // namespace pvs::gen
