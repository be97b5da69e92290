// The order of the portal flow and the rows it prunes with (portal_vis.h, "Determinism").
//
// Contract. rank_portals orders the directed portals by increasing nummightsee, ties by index:
// the order they are handed to the threads in. PruneRows::row(q, r) is the row the flow of the
// portal of rank r prunes with at q, by the rule of prune_lag.h with kPruneLag: q's finished
// visbits when rank(q) + kPruneLag < r (waiting for q when it is still being worked on), else
// q's mightsee; an empty row when q was aborted (cancelled bake).
#pragma once

#include "visibility/portal/portal_vis.h"
#include "visibility/portal/prune_lag.h"
#include "visibility/portal/run_rows.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

struct FlowOrder {
    std::vector<uint32_t> order; // rank -> directed portal
    std::vector<uint32_t> rank;  // directed portal -> rank
};

FlowOrder rank_portals(const std::vector<uint32_t>& nummightsee);

class PruneRows {
public:
    // visbits[q] is read only once state[q] is kDone (written before the release store).
    // Per portal (item_of == nullptr): rank, state and visbits are per directed portal. Per region
    // (VisParams::Source::Region): they are per region, and the final row used at directed portal
    // qi is that of the region it leads into, item_of[qi] (every leaf a line through qi reaches is
    // seen from there).
    PruneRows(const uint32_t* rank, std::atomic<uint8_t>* state, const RunRow* mightsee, const RunRow* visbits,
              const uint32_t* item_of = nullptr)
        : lag_(rank, state, kPruneLag), mightsee_(mightsee), visbits_(visbits), item_of_(item_of)
    {
    }

    // The row the walk of rank r prunes with at directed portal qi; waiting time is added to
    // waited_nanos. Inline: called once per flow step.
    RunRow row(uint32_t qi, uint32_t r, uint64_t& waited_nanos) const
    {
        const uint32_t q = item_of_ ? item_of_[qi] : qi;
        if (!lag_.uses_final(q, r))
            return mightsee_[qi];
        return lag_.await_final(q, waited_nanos) ? visbits_[q] : RunRow{};
    }

    // Starts loading the row row(qi, r) would return, when it is there already (never waits).
    void prefetch(uint32_t qi, uint32_t r) const
    {
        const uint32_t q = item_of_ ? item_of_[qi] : qi;
        if (!lag_.uses_final(q, r)) {
            __builtin_prefetch(mightsee_[qi].data);
            return;
        }
        if (lag_.final_written(q))
            __builtin_prefetch(visbits_[q].data);
    }

private:
    PruneLag lag_;
    const RunRow* mightsee_;
    const RunRow* visbits_;
    const uint32_t* item_of_;
};

} // namespace pvs::portal_vis
