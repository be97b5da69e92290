// The determinism rule both portal flows share (the 3-D flow: portal_vis.h, "Determinism"; the
// 2-D flow of Doom's subsectors: portal_vis_2d.h).
//
// Contract. Directed portals are ranked once and handed to the workers in rank order. The walk
// of the portal of rank r prunes at portal q with q's final row exactly when rank(q) + lag < r,
// otherwise with q's first (mightsee) row. The rule depends on ranks only, never on timing, so
// the result does not depend on the thread count. When q's final row is needed before it is
// written, the walk waits for it (an atomic wait, no spinning): q was handed out earlier than the
// waiter and itself only waits for lower ranks, so this cannot deadlock. Every handed-out portal
// ends as Done (final row written before the release store) or Aborted (cancel, exception: its
// waiters go on with what the flow says for that case); FlowTicket makes sure of it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace pvs::portal_vis {

// A directed portal's progress through the flow, published with release/acquire.
enum PortalState : uint8_t { kNone = 0, kWorking = 1, kDone = 2, kAborted = 3 };

class PruneLag {
public:
    PruneLag(const uint32_t* rank, const std::atomic<uint8_t>* state, uint32_t lag)
        : rank_(rank), state_(state), lag_(lag)
    {
    }

    // Whether the walk of rank r prunes at q with q's final row.
    bool uses_final(uint32_t q, uint32_t r) const { return rank_[q] + lag_ < r; }

    // Whether q's final row is written (no wait, no ordering: for prefetches).
    bool final_written(uint32_t q) const { return state_[q].load(std::memory_order_relaxed) == kDone; }

    // Waits until q is Done or Aborted; true when Done (its final row is then visible to this
    // thread). The time waited is added to waited_nanos.
    bool await_final(uint32_t q, uint64_t& waited_nanos) const
    {
        uint8_t s = state_[q].load(std::memory_order_acquire);
        if (s < kDone) {
            using Clock = std::chrono::steady_clock;
            const auto wait_start = Clock::now();
            while ((s = state_[q].load(std::memory_order_acquire)) < kDone)
                state_[q].wait(s, std::memory_order_acquire);
            waited_nanos +=
                uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - wait_start).count());
        }
        return s == kDone;
    }

private:
    const uint32_t* rank_;
    const std::atomic<uint8_t>* state_;
    uint32_t lag_;
};

// One portal's walk, from hand-out to its final state: Working on construction, Done by done()
// (after the final row is written), Aborted when destroyed without done() - a cancel or an
// exception - so that no waiter waits forever.
class FlowTicket {
public:
    explicit FlowTicket(std::atomic<uint8_t>& state) : state_(state) { state_.store(kWorking, std::memory_order_relaxed); }
    FlowTicket(const FlowTicket&) = delete;
    FlowTicket& operator=(const FlowTicket&) = delete;
    ~FlowTicket() { publish(kAborted); }

    void done() { publish(kDone); }

private:
    std::atomic<uint8_t>& state_;
    bool published_ = false;

    void publish(PortalState s)
    {
        if (published_)
            return;
        published_ = true;
        state_.store(s, std::memory_order_release);
        state_.notify_all();
    }
};

} // namespace pvs::portal_vis
