// The ground of a zone as a heightfield: the occluder that open ground has and that portal vis
// does not see as one (to portal vis, a hill is the absence of air cells).
//
// The grid covers the union of the regions' boxes (region_boxes.h: volumes, not geometry) with
// columns of one size. A column's height is
// the top of the solid that fills it, without a gap, from the regions' lowest z: the box
// (column footprint) x [floor, height] has no point of any region in its interior. Overhangs,
// bridges and roofs (solid above open space) are not part of it, and a column whose ground is
// sloped counts only up to its lowest point, so the heightfield holds less solid than the zone:
// a method that treats it as the only occluder stays conservative.
//
// How a column is measured: candidate heights are the regions' box bottoms (the ground under an
// open cell is where a region starts), and the largest candidate whose box is solid is the
// height (solidity falls as the box grows, so a binary search). "Solid" is decided by walking
// the BSP tree with the box: a box strictly on one side of a plane (touching it counts as on
// one side, axis-aligned planes exactly; others with a relative tolerance that sends a doubtful
// box down both children) goes to that child only, and the box is solid when every leaf it
// reaches is solid, outside or corrupt (what blocks a sight line in reference/tree_trace.h).
//
// Cells: `cell` zone units a side when given, else the smallest x and y extent of a region's
// box, and never more than kMaxHeightfieldColumns (+ 1 for round-off) a side (the cell grows instead). Throws
// std::invalid_argument for a zone without a tree or without a region with a box.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

inline constexpr uint32_t kMaxHeightfieldColumns = 1024;

struct Heightfield {
    double origin_x = 0.0, origin_y = 0.0; // the corner of column (0, 0)
    double cell_x = 1.0, cell_y = 1.0;     // column size
    uint32_t columns_x = 0, columns_y = 0;
    double floor = 0.0;                    // the regions' lowest z: every column is solid from here
    std::vector<double> top;               // per column (x + y * columns_x): solid up to here (>= floor)

    size_t column_count() const { return top.size(); }
    double height(uint32_t x, uint32_t y) const { return top[size_t(x) + size_t(y) * columns_x]; }
};

// `region_boxes`: one box per region that holds its volume (region_volume_boxes), empty for a
// region without one.
Heightfield zone_heightfield(const BspTree& tree, std::span<const Aabb> region_boxes, double cell = 0.0);

// Whether the interior of `box` holds no point of a region (every leaf the box reaches is solid,
// outside or corrupt), as described above. Exposed for tests.
bool box_interior_is_solid(const BspTree& tree, const Aabb& box);

} // namespace pvs
