// The terrain method: a PVS from the ground alone, for open zones where hills, not walls, hide
// one place from another (portal vis there must flow through every air cell and does not finish;
// docs/outdoor.md has the figures).
//
// The occluder is the zone's heightfield (terrain_heightfield.h): columns solid from the floor
// up to their height, less solid than the zone has, so what it hides is hidden. A region counts
// as its box: its footprint (the columns its box covers) and its top z. Lines from a region's
// points run below the line from the same footprint point at the box top, and under a
// heightfield a lower line is blocked wherever a higher one is: so only lines from tops to tops
// matter. Region boxes are their volumes' (region_boxes.h) in the world portals and the reference
// take them in (zone_portal_world: the zone's bounds and a margin; a region open to the sky
// reaches above the zone's top).
//
// The sweep (one per source: footprint R, top z_a). For a column C, S(C) is a lower bound of
// the slope (rise over horizontal run from R) that any unblocked line from R at z_a needs to
// reach C. Columns with no whole column or row between them and R need nothing: S = -inf.
// Otherwise a line to C crosses a strip next to C (horizon_parents.h) through the inside of a
// strip cell P at a point y, so its part up to y is an unblocked line to P (slope >= S(P)), and
// it passes over P's height there: slope >= (height(P) - z_a) / |y - p|, bounded below over p
// in R and y in P by the rectangles' largest distance (height above z_a) or smallest one
// (below: -inf when they touch). Hence, per strip,
//     bound = min over strip cells P of max(S(P), slope bound of P)
// (a cell that only touches the hull, where a line can run along its side, contributes
// max(S(partner), its slope bound): such a line is in the solid only when below it and the
// inside cell across the edge, and runs along that cell's side too), and S(C) is the largest of
// C's strips' bounds, computed in order of the gap to R.
// Outside the grid there is no region: solid, and no line goes there.
// Region B in column C with top z_b is hidden from R when even the steepest line to it is below
// S(C): (z_b - z_a) / distance < S(C), the distance taken as the smallest (z_b above z_a) or the
// largest (below) between R and C; a line exactly at the bound grazes and counts as visible. B
// is hidden when that holds for every column of its footprint.
//
// The test is one-sided (from A's top). The PVS keeps A -> B only when neither side hides the
// other (bits::and_with_transpose), which makes it symmetric and tighter. Conservative: an upper
// bound of the true PVS for any zone with a tree (on indoor maps it hides little: their floors
// are not solid to the world's bottom). Regions without a volume in that world see and are seen
// by everything.
//
// Cost: one sweep of the grid per distinct (footprint, top), a few parents a strip, then one
// test per pair; memory: the n x n bit matrix (n = regions), the grid, and one parent table per
// footprint size (see horizon_parents.h). Results do not depend on the thread count.
#pragma once

#include "visibility/pvs.h"
#include "visibility/terrain/terrain_heightfield.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace pvs {

struct TerrainVisParams {
    double cell = 0.0;   // heightfield column size (0: from the regions, terrain_heightfield.h)
    unsigned threads = 0; // 0 = all cores
    std::function<bool(double fraction)> progress; // false cancels
    size_t table_budget_bytes = size_t(512) << 20;  // parent tables' memory before the grid coarsens
};

struct TerrainVisReport {
    double seconds = 0.0;
    double heightfield_seconds = 0.0;
    uint32_t columns_x = 0, columns_y = 0;
    double cell_x = 0.0, cell_y = 0.0;
    size_t sources = 0;          // sweeps: distinct (footprint, top)
    size_t footprint_sizes = 0;  // parent tables
    size_t regions_without_box = 0;
    double mean_visible = 0.0;
    unsigned threads = 0;
    bool cancelled = false;
    size_t peak_bytes_estimate = 0;
};

// A source sweeps from its footprint grown to powers of two columns (a superset: conservative), so
// few parent tables serve a zone of regions of many sizes; when the tables would still take more
// than the budget (TerrainVisParams::table_budget_bytes), the grid is made again with columns twice as wide (a coarser
// heightfield: looser, still conservative) until they fit. Throws std::invalid_argument for a zone
// without a tree or a region box (zone_heightfield).
Pvs bake_terrain_vis(const Zone& zone, const TerrainVisParams& params, TerrainVisReport* report = nullptr);

} // namespace pvs
