// Base portal vis (§3.2; portal_vis.h, "Method::Fast"): each directed portal's mightsee, the
// flood from its destination through the portals it might see.
//
// Contract. base_portal_vis writes the row of g.words words at `mightsee` (every word written,
// nothing else touched) and returns its count of set bits (nummightsee). It reads only the
// graph, so any number of threads may run it on different portals at once; `stack` is the
// caller's scratch (reused across calls: no allocation once it has grown).
#pragma once

#include "visibility/portal/portal_graph.h"

#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

// What the tests read of a tested portal before its points, one cache line per entry of
// Graph::leaf_portals, in that order. Why: the flood tests the portals leaving each leaf it
// enters, and with the portals scattered over Graph::portals the first load of each was a cache
// miss: a quarter of base vis's time on the 1500-room zone (perf). In leaf order, a leaf's
// portals are one run of lines. The values are the graph's own, so every test computes exactly
// what it computed from the graph.
struct alignas(64) TestedPortal {
    DPlane plane;
    Vec origin{0.0};
    double radius = 0.0;
};
static_assert(sizeof(TestedPortal) == 64, "one cache line per tested portal");

// The table for base vis (8 MB at 5000 rooms: build it for base vis and free it after).
std::vector<TestedPortal> tested_portals(const Graph& g);

// ericw's BasePortalThread tests: may directed portal p see directed portal t (p != t)? `tested`
// is t's entry of tested_portals; t's points are read only when its sphere does not decide.
bool portal_might_see(const Graph& g, const DirectedPortal& p, const TestedPortal& tested, const DirectedPortal& t);

// p.mightsee: the flood from p's destination through the portals p might see. A portal is
// tested only when the flood meets it and its destination is not marked yet, which gives
// exactly ericw's SimpleFlood over the full portalsee set (a marked leaf is never re-entered).
// Returns nummightsee.
uint32_t base_portal_vis(const Graph& g, const std::vector<TestedPortal>& tested, uint32_t pi,
                         std::vector<uint32_t>& stack, uint64_t* mightsee);

} // namespace pvs::portal_vis
