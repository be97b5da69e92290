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
// Conservative. The flow's tolerances are set so that it keeps every sight line wider than
// 2e-6 units (portal_vis_2d.cpp: kOnLine = 1e-6, kSlack = 1e-3, kMinSeparator = 0.1): a segment
// is in front of a line when a point of it is more than kOnLine in front (lines through a
// segment with none further in front form a window under 2 kOnLine wide: nothing for the
// collinear portals along Doom's split lines), a clip keeps the part up to kSlack behind its
// line, a separator is used only when the source is surely behind it and the pass surely in
// front (else it is skipped, which clips less), and a portal with any width is kept. glVIS's
// ON_EPSILON (0.1) instead dropped a target with no point more than 0.1 in front of a
// separator, which loses sight lines up to 0.1 wide (two directed pairs of Freedoom 2 MAP10
// that the reference proves with its 0.05 beam). The rows cost a few bits more than glVIS's
// (docs/doom.md).
//
// Method::Fast (glVIS -fast): base vis. Portal p might see t when t has an endpoint in front of
// p's line and p has one behind t's line; mightsee is the flood from p's destination through
// such t.
// Method::Full: glVIS's flow in 2-D, with the tolerances above and its rules. The walk
// from directed portal p carries the source segment and the pass segment; a target t leaving
// the current leaf is clipped to the front of p's line, the source to the back of t's line
// (the back of the target), then the target by the separators source -> pass (level >= 0, and
// mirrored pass -> source at level >= 1), the source by pass -> target (level >= 2, mirrored
// at level >= 3). In 2-D a separator is a line through an endpoint of one segment and an
// endpoint of the other with the two other endpoints strictly on opposite sides: a sight line
// from the first segment through the second stays on the second's side of it. Such a line is
// the same whichever segment is called the source and keeps the same side, so in the plane
// tests 1 and 3 add nothing to tests 0 and 2 (levels 1 and 3 equal 0 and 2; 4 is taken as 3).
// Clips keep points up to kSlack behind, return a segment with no point further behind
// unchanged, and drop one with no point more than kOnLine in front. A walk never re-enters a leaf on its own chain, and
// stops where its mightsee (the AND of the mightsee or final vis of every portal passed) adds
// nothing not yet visible to a leaf already visible, as vis does. Unlike glVIS there is no
// depth cap (its cap of 256 can cut a sight line).
//
// Dominated windows (beyond glVIS). The state a walk carries past portal t is the source
// interval (on p's segment), the pass interval (on t's segment) and the mightsee; the clips
// only ever shrink all three, so a walk arriving at t with intervals inside those of an earlier
// walk of the same source past t, and a mightsee inside its mightsee, can reach nothing the
// earlier one did not: it is skipped. Up to 8 windows are remembered per portal and walk. On
// Doom maps, whose tiny subsectors reach one portal by thousands of chains, this removes most
// of the work (MAP10: 873 000 steps to 123 000 for its slowest portal). In the plane the two
// separators bound exactly the lines from the source through the pass, so the clips are
// monotone (a smaller source and pass give a smaller window) and the skip loses nothing, except
// where a separator was skipped as unsure (geometry degenerate to within kSlack); the intervals
// must lie inside the earlier ones with no tolerance (tests/wld/test_doom_vis.cpp checks the
// reference on real maps).
//
// Determinism, threads, progress, cancellation: as bake_portal_vis. The directed portals are
// ranked by increasing mightsee count (ties by index) and handed to the threads in rank order;
// a walk prunes with the final vis of portals ranked more than 8 below its own (waiting for one
// still being walked) and with the mightsee of the others - the rule of portal/prune_lag.h, which
// the 3-D flow shares with a lag of 32 - so the result is a fixed function of the input and the
// level, whatever the thread count. Cancelling returns
// the finished portals' vis and the unfinished ones' mightsee (conservative).
//
// Memory: two rows of region_count bits per directed portal and, per thread, one row per walk
// depth reached.
#pragma once

#include "visibility/portal/portal_vis.h"

namespace pvs {

Pvs bake_portal_vis_2d(const PortalSet& portals, uint32_t region_count, const VisParams& params,
                       VisReport* report = nullptr);

} // namespace pvs
