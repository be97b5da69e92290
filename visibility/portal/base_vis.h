// Base portal vis's test (§3.2; portal_vis.h, "Method::Fast"): may one directed portal see
// another. A portal's mightsee is the flood from its destination through the portals it might
// see, a marked leaf never re-entered, which gives exactly ericw's SimpleFlood over the full
// portalsee set; base_vis_batch.h runs those floods, 64 sources at a time, asking each test of
// the float tables first (base_vis_tables.h) and of portal_might_see only when they leave it
// undecided.
//
// Contract. portal_might_see reads only the graph: any number of threads may call it.
#pragma once

#include "visibility/portal/portal_graph.h"

#include <cstdint>

namespace pvs::portal_vis {

// ericw's BasePortalThread tests, exactly, on the doubles: may directed portal p see directed
// portal t (p != t)? t's points are read only when its sphere does not decide.
bool portal_might_see(const Graph& g, const DirectedPortal& p, const DirectedPortal& t);

} // namespace pvs::portal_vis
