// Portal vis in the plane, as glVIS does it for Doom's GL subsectors (../shared/formats/
// quake-doom-hepvs.md §4.5: "a 2D port of Quake vis"), for zones whose portals are all vertical
// (the column tree of an extruded 2-D map: without_height_nodes, bsp_tree_edit.h).
//
// Input. The same PortalSet and orientation as bake_portal_vis (portal_vis.h): the plane of a
// portal's points, normal into regions[0]. Each portal is projected to the plane z = 0: its
// segment is the two points farthest apart in x, y; its line's normal is the plane normal's
// x, y, normalised. Portals that are not vertical (|normal.z| > 0.01), or whose segment has no
// length, are skipped and counted (VisReport::portals_skipped).
// Each portal gives two directed portals, 2i in regions[0] leading into regions[1], 2i+1 the
// other way, the line's normal pointing into the region led to.
//
// Conservative. Clips keep every point exact arithmetic would keep, with a slack bounded by the
// round-off of the map's coordinates (segment_clip_2d.h: 3e-8 at Doom's largest); the one loss is
// a sight line narrower than 2e-6 (a segment with no point more than 1e-6 in front of a line is
// dropped; collinear portals along Doom's split lines are not walked along). glVIS's ON_EPSILON
// (0.1) lost sight lines up to 0.1 wide (two directed pairs of Freedoom 2 MAP10 that the reference
// proves with its 0.05 beam).
//
// Method::Fast (glVIS -fast): base vis. Portal p might see t when t has an endpoint in front of
// p's line and p has one behind t's line; mightsee is the flood from p's destination through
// such t. A region's row is the union of its portals' mightsee.
// Method::Full: glVIS's flow in 2-D, with the tolerances above and its rules, walked per region:
// the walks of a region's outgoing portals share the region's row, so a walk stops where a
// sibling already saw what it could add. The walk from directed portal p carries the source
// segment and the pass segment; a target t leaving the current leaf is clipped to the front of
// p's line, the source to the back of t's line, then the target by the separators source -> pass
// (level >= 0), the source by pass -> target (level >= 2). In 2-D a separator is a line through an
// endpoint of one segment and an endpoint of the other with the two other endpoints on opposite
// sides: such a line is the same whichever segment is called the source, so glVIS's tests 1 and 3
// add nothing to tests 0 and 2 (levels 1 and 3 equal 0 and 2; 4 is taken as 3). The separators
// of a frame's source and pass are found once and reused by every target whose clip leaves the
// source whole. A walk never re-enters a leaf on its own chain, and stops where its mightsee (the
// AND of the mightsee of every portal passed, and of the final row of the region each leads into
// once that row is final) adds nothing not yet in the row. Unlike glVIS there is no depth cap (its
// cap of 256 can cut a sight line).
//
// Target checks (as the 3-D flow's, portal_vis.h): on entering a leaf the row already holds, when
// at most 64 leaves of the mightsee are still unseen, each is checked - a line from the source
// through the pass that reaches it crosses a portal into it in front of the head's and the pass's
// lines and inside the frame's separators - and the walk goes on only if one passes.
//
// Dominated windows (beyond glVIS). The state a walk carries past portal t is the source interval
// (on p's segment), the pass interval (on t's segment) and the mightsee; the clips only shrink all
// three, so a walk arriving at t with intervals inside those of an earlier walk of the same source
// past t, and a mightsee inside its mightsee, can reach nothing the earlier one did not: it is
// skipped. Up to 8 windows are remembered per portal and walk. In the plane the two separators
// bound exactly the lines from the source through the pass, so the clips are monotone; the
// intervals must lie inside the earlier ones with no tolerance.
//
// Determinism, threads, progress, cancellation: as bake_portal_vis, with regions in place of
// directed portals. Regions are ranked by increasing mightsee (ties by index) and handed to the
// threads in rank order; a walk prunes with the final row of regions ranked more than 8 below its
// own (waiting for one still being walked) and with the mightsee otherwise - the rule of
// portal/prune_lag.h - so the result is a fixed function of the input and the level, whatever the
// thread count, and so are the work counters (VisReport::frames, clips, separators, separator
// candidates, target checks, dominated windows). Cancelling returns the finished regions' rows and
// the union of the others' portals' mightsee (conservative).
//
// Memory: a row of region_count bits per directed portal (its mightsee) and per region, and, per
// thread, one row per walk depth reached.
#pragma once

#include "visibility/portal/portal_vis.h"

namespace pvs {

Pvs bake_portal_vis_2d(const PortalSet& portals, uint32_t region_count, const VisParams& params,
                       VisReport* report = nullptr);

} // namespace pvs
