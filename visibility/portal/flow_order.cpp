// The order of the portal flow (flow_order.h).
#include "visibility/portal/flow_order.h"

#include <algorithm>

namespace pvs::portal_vis {

FlowOrder rank_portals(const std::vector<uint32_t>& nummightsee)
{
    const auto n = uint32_t(nummightsee.size());
    FlowOrder o;
    o.order.resize(n);
    o.rank.resize(n);
    for (uint32_t i = 0; i < n; ++i)
        o.order[i] = i;
    std::stable_sort(o.order.begin(), o.order.end(),
                     [&](uint32_t a, uint32_t b) { return nummightsee[a] < nummightsee[b]; });
    for (uint32_t r = 0; r < n; ++r)
        o.rank[o.order[r]] = r;
    return o;
}

} // namespace pvs::portal_vis
