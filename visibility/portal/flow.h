// The portal flow (§3.3, §3.4; portal_vis.h, "Method::Full"): ericw's RecursiveLeafFlow for
// one directed portal at a time, on one worker thread.
//
// Contract. A FlowWorker belongs to one thread and is reused for many portals: run(pi, ...)
// fills vis() with the leaves directed portal pi sees, reading the graph, pi's mightsee, the
// passage rows (when given) and the rows PruneRows hands out (flow_order.h); it writes nothing
// shared. The walk is a loop over an explicit stack of frames (flow_frame.h), so deep chains
// cannot overflow a thread's stack; frames are allocated only when a walk goes deeper than any
// before it, nothing else is allocated inside the walk. Target checks (target_checks.cpp) and
// the passage floods (passages.cpp) are members because they clip with the worker's frames and
// scratch.
#pragma once

#include "visibility/portal/flow_chain.h"
#include "visibility/portal/flow_frame.h"
#include "visibility/portal/flow_order.h"
#include "visibility/portal/passages.h"
#include "visibility/portal/portal_graph.h"
#include "visibility/portal/run_rows.h"
#include "visibility/portal/window_memo.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace pvs::portal_vis {

// One worker thread's flow state: the stack of frames (grown only when a walk goes deeper than
// any before it), the visbits being built, which leaves are on the chain, clip scratch.
class FlowWorker {
public:
    FlowWorker(const Graph& g, int level)
        : g_(g), level_(level), vis_(g.words, 0), on_stack_(g.leaf_count, 0),
          dists_(point_capacity() + 1), sides_(point_capacity() + 1), b_side_(point_capacity()),
          ones_(g.words, ~uint64_t{0}), spread_(g.words, 0)
    {
        memo_.resize(g.portals.size());
    }

    // The flow of directed portal pi of rank `rank`, into vis(). prune_rows gives the set each
    // portal q may still reach (its visbits or its mightsee), or nullptr when the bake is
    // cancelled. Returns false when cancelled.
    bool run(uint32_t pi, uint32_t rank, const RunRow& head_mightsee, const PruneRows& prune_rows,
             const std::atomic<bool>& cancel)
    {
        begin_row();
        if (!walk(pi, rank, head_mightsee, prune_rows, cancel))
            return false;
        end_row();
        return true;
    }
    // A region's row (VisParams::Source::Region): begin_row(), then walk() for each of its
    // outgoing portals - they share vis(), so a walk stops where its siblings already saw what it
    // could add - then end_row(). `rank` is then the region's.
    void begin_row() { std::fill(vis_.begin(), vis_.end(), 0); }
    bool walk(uint32_t pi, uint32_t rank, const RunRow& head_mightsee, const PruneRows& prune_rows,
              const std::atomic<bool>& cancel);
    void end_row() { portal_visible_ += bits::count(vis_); }
    void mark_visible(uint32_t leaf) { bits::set(vis_, leaf); }

    std::span<const uint64_t> vis() const { return vis_; }
    void use_passages(const Passages* p) { passages_ = p; }
    void use_target_checks(bool on) { target_checks_ = on; }
    void use_symmetry(bool on) { symmetry_ = on; }
    void use_window_memo(bool on) { window_memo_ = on; }
    // Record, into probe->found[pi], the chain of each portal pi leaving probe->from the first
    // time its walk enters probe->to (flow_chain.h). found must hold a slot per directed portal.
    void watch(ChainProbe* probe) { probe_ = probe; }
    size_t target_checks() const { return target_check_count_; }
    size_t target_check_prunes() const { return target_check_prunes_; }
    // The passage row of directed portal ai and the k-th portal leaving its destination
    // (passages.cpp), into `out` (g.words words).
    // ma, mb: the mightsee rows of ai and of that portal, dense.
    void passage_row(uint32_t ai, uint32_t k, const uint64_t* ma, const uint64_t* mb, uint64_t* out);
    size_t leaf_recursions() const { return leaf_recursions_; }
    // Leaves the walks entered, and the leaves the finished walks saw (each directed portal's
    // visbits counted): no per-portal flow can enter fewer leaves than the second.
    size_t frames_entered() const { return frames_entered_; }
    size_t portal_visible() const { return portal_visible_; }
    size_t dominated_windows() const { return memo_.dominated(); }
    // Windings clipped (the flow's, the target checks' and the passage floods'), and separating
    // planes found: with frames_entered(), the work counters of the flow (deterministic).
    size_t clips() const { return clips_; }
    size_t separators() const { return separators_; }
    uint64_t wait_nanos() const { return wait_nanos_; } // waiting for older portals' visbits
    size_t bytes() const
    {
        return frames_.size() * (sizeof(Frame) + g_.words * sizeof(uint64_t) + 2 * point_capacity()) +
               vis_.size() * sizeof(uint64_t) + on_stack_.size() + dists_.size() * sizeof(double) + sides_.size() +
               b_side_.size();
    }

private:
    // The most points any winding of the walk can have: a portal's or a frame winding's.
    uint32_t point_capacity() const { return std::max(g_.max_points, kStackPoints); }

    Frame& frame(size_t depth)
    {
        while (frames_.size() <= depth)
            frames_.push_back(std::make_unique<Frame>(g_.words, point_capacity()));
        return *frames_[depth];
    }

    WRef portal_winding(uint32_t pi) const
    {
        const DirectedPortal& p = g_.portals[pi];
        return WRef{&g_.points[p.first_point], p.point_count, p.origin, p.radius, nullptr, -1};
    }

    // clip_winding (flow_frame.h) with this worker's scratch.
    WRef clip(const WRef& in, const DPlane& split, Frame& f)
    {
        ++clips_;
        return clip_winding(in, split, f, dists_.data(), sides_.data());
    }

    // The words [from, to) of a passage row as a dense array p (p[w - from] = word w), valid
    // until the next call: the row itself when it is wide, else its words spread into spread_.
    const uint64_t* spread_passage(const PassageRow& row, uint32_t from, uint32_t to);
    // "Nothing new": whether prev.mightsee & test & passage has a bit not in vis_. test is zero
    // outside its runs, so only its runs from first_run on inside [lo, hi) are read; passage is
    // indexed from lo.
    bool adds_leaf(const Frame& prev, const RunRow& test, uint32_t first_run, uint32_t lo, uint32_t hi,
                   const uint64_t* passage) const;
    // f.mightsee = prev.mightsee & test & passage, written (and f.lo, f.hi set) over the words
    // of those runs only: every other word of the row is zero.
    static void narrow_mightsee_into(Frame& f, const Frame& prev, const RunRow& test, uint32_t first_run, uint32_t lo,
                                     uint32_t hi, const uint64_t* passage);

    // Enters `leaf` below the frame at depth_ (false when it is already on the chain).
    bool enter(uint32_t leaf, uint32_t entry);
    // The chain of the walk into `leaf` (through directed portal `entry`), below the frame at
    // depth_, into probe_->found[head portal].
    void record_chain(uint32_t leaf, uint32_t entry);
    // Leaves the frame at depth_.
    void leave()
    {
        on_stack_[frames_[depth_]->leaf] = 0;
        --depth_;
    }

    // `w` clipped by the planes of tests 0 and 1 (as far as level_ asks) of frame f, whose
    // previous frame is prev. The planes depend only on prev, so f finds them once, edge by
    // edge as windings need them (SeparatorCache), and every winding meets them in one order.
    WRef clip_to_frame_separators(WRef w, Frame& f, const Frame& prev, const DPlane& head_plane);

    // The target check of the frame just entered (portal_vis.h, "Target checks";
    // target_checks.cpp): false when no leaf the walk below it could add is reachable through
    // its source and pass. Removes the unreachable ones from its mightsee. Uses the frame's
    // windings as scratch.
    bool may_add_leaf(const Frame& head);
    // Whether a portal into `leaf` survives frame f's clips: in front of the head and of the
    // pass, and inside the planes of tests 0 and 1.
    bool leaf_reachable(uint32_t leaf, Frame& f, const Frame& prev, const Frame& head);

    const Graph& g_;
    int level_;
    std::vector<std::unique_ptr<Frame>> frames_;
    std::vector<uint64_t> vis_;
    std::vector<uint8_t> on_stack_;
    std::vector<double> dists_;
    std::vector<uint8_t> sides_;
    std::vector<int8_t> b_side_; // tests 2 and 3: sides_to_plane of B
    std::vector<DPlane> passage_planes_;
    std::vector<uint32_t> passage_stack_;
    size_t depth_ = 0;
    size_t leaf_recursions_ = 0;
    size_t frames_entered_ = 0;
    size_t portal_visible_ = 0;
    size_t clips_ = 0;
    size_t separators_ = 0;
    uint64_t wait_nanos_ = 0;
    const Passages* passages_ = nullptr;
    std::vector<uint64_t> ones_;
    std::vector<uint64_t> spread_; // a narrow passage row's words, spread out (spread_passage)
    bool target_checks_ = false;
    WindowMemo memo_; // dominated windows (window_memo.h)
    bool symmetry_ = true;
    bool window_memo_ = true;
    ChainProbe* probe_ = nullptr;
    bool watching_ = false; // this walk's portal leaves probe_->from and has not entered probe_->to yet
    uint32_t head_portal_ = 0;
    size_t target_check_count_ = 0;
    size_t target_check_prunes_ = 0;
};

} // namespace pvs::portal_vis
