// Base portal vis (§3.2; portal_vis.h, "Method::Fast"): each directed portal's mightsee, the
// flood from its destination through the portals it might see.
//
// Contract. base_portal_vis writes the row of g.words words at `mightsee` (every word written,
// nothing else touched) and returns its count of set bits (nummightsee). It reads only the
// graph, so any number of threads may run it on different portals at once; `stack` is the
// caller's scratch (reused across calls: no allocation once it has grown).
#pragma once

#include "visibility/portal/base_vis_tables.h"
#include "visibility/portal/portal_graph.h"

#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

// ericw's BasePortalThread tests, exactly, on the doubles: may directed portal p see directed
// portal t (p != t)? t's points are read only when its sphere does not decide.
bool portal_might_see(const Graph& g, const DirectedPortal& p, const DirectedPortal& t);

// p.mightsee: the flood from p's destination through the portals p might see. A portal is
// tested only when the flood meets it and its destination is not marked yet, which gives
// exactly ericw's SimpleFlood over the full portalsee set (a marked leaf is never re-entered).
// Each test is asked of the float tables first (base_vis_tables.h) and of portal_might_see only
// when they leave it undecided. Returns nummightsee.
uint32_t base_portal_vis(const Graph& g, const BaseVisTables& tables, uint32_t pi,
                         std::vector<uint32_t>& stack, uint64_t* mightsee);

} // namespace pvs::portal_vis
