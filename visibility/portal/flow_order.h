// The order of the portal flow and the rows it prunes with (portal_vis.h, "Determinism").
//
// Contract. rank_portals orders the directed portals by increasing nummightsee, ties by index:
// the order they are handed to the threads in. PruneRows::row(q, r) is the row the flow of the
// portal of rank r prunes with at q: q's finished visbits when rank(q) + kPruneLag < r (waiting
// for q when it is still being worked on), else q's mightsee; an empty row when q was aborted
// (cancelled bake). The rule depends on ranks only, never on timing, so the result does not
// depend on the thread count. It cannot deadlock: q was handed out earlier than the waiter, and
// q itself only waits for lower ranks.
#pragma once

#include "visibility/portal/portal_vis.h"
#include "visibility/portal/run_rows.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

// A directed portal's progress through the flow, published with release/acquire so that a
// portal seen as kDone has its visbits written.
enum PortalState : uint8_t { kNone = 0, kWorking = 1, kDone = 2, kAborted = 3 };

struct FlowOrder {
    std::vector<uint32_t> order; // rank -> directed portal
    std::vector<uint32_t> rank;  // directed portal -> rank
};

FlowOrder rank_portals(const std::vector<uint32_t>& nummightsee);

class PruneRows {
public:
    // visbits[q] is read only once state[q] is kDone (written before the release store).
    PruneRows(const uint32_t* rank, std::atomic<uint8_t>* state, const RunRow* mightsee, const RunRow* visbits)
        : rank_(rank), state_(state), mightsee_(mightsee), visbits_(visbits)
    {
    }

    // The row the portal of rank r prunes with at directed portal qi; waiting time is added to
    // waited_nanos. Inline: called once per flow step.
    RunRow row(uint32_t qi, uint32_t r, uint64_t& waited_nanos) const
    {
        if (rank_[qi] + kPruneLag >= r)
            return mightsee_[qi];
        uint8_t s = state_[qi].load(std::memory_order_acquire);
        if (s < kDone) {
            using Clock = std::chrono::steady_clock;
            const auto wait_start = Clock::now();
            while ((s = state_[qi].load(std::memory_order_acquire)) < kDone)
                state_[qi].wait(s, std::memory_order_acquire);
            waited_nanos +=
                uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - wait_start).count());
        }
        return s == kDone ? visbits_[qi] : RunRow{};
    }

    // Starts loading the row row(qi, r) would return, when it is there already (never waits).
    void prefetch(uint32_t qi, uint32_t r) const
    {
        const RunRow* rows = mightsee_;
        if (rank_[qi] + kPruneLag < r) {
            if (state_[qi].load(std::memory_order_relaxed) != kDone)
                return;
            rows = visbits_;
        }
        __builtin_prefetch(rows[qi].data);
    }

private:
    const uint32_t* rank_;
    std::atomic<uint8_t>* state_;
    const RunRow* mightsee_;
    const RunRow* visbits_;
};

} // namespace pvs::portal_vis
