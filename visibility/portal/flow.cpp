// The portal flow (flow.h): the walk, entering a leaf, and the clips by the frame's cached
// separators (tests 0 and 1).
#include "visibility/portal/flow.h"

#include "visibility/bit_row.h"
#include "visibility/portal/separators.h"

#include <algorithm>
#include <bit>

namespace pvs::portal_vis {
namespace {

constexpr uint32_t kCancelCheckSteps = 1024; // flow steps between looks at the cancel flag

} // namespace

bool FlowWorker::enter(uint32_t leaf, uint32_t entry)
{
    if (on_stack_[leaf]) {
        ++leaf_recursions_;
        return false;
    }
    Frame& f = frame(depth_ + 1);
    ++depth_;
    ++frames_entered_;
    f.leaf = leaf;
    f.entry = entry;
    f.cursor = g_.leaf_first[leaf];
    f.end = g_.leaf_first[leaf + 1];
    f.separators[0].next_edge = f.separators[1].next_edge = 0;
    f.separators[0].count = f.separators[1].count = 0;
    on_stack_[leaf] = 1;
    bits::set(vis_, leaf);
    if (watching_ && leaf == probe_->to)
        record_chain(leaf, entry);
    return true;
}

void FlowWorker::record_chain(uint32_t leaf, uint32_t entry)
{
    // The frames 1..depth_ hold the chain's regions (the new one's frame is at depth_ too: enter
    // has pushed it); frame k - 1 holds the window the walk saw region k's portal through.
    FlowChain chain;
    chain.directed_portal = head_portal_;
    for (size_t k = 1; k <= depth_; ++k) {
        const Frame& f = *frames_[k];
        const uint32_t into = k == depth_ ? entry : f.entry;
        ChainStep step;
        step.region = k == depth_ ? leaf : f.leaf;
        step.portal = g_.input_portal[into >> 1];
        const WRef whole = portal_winding(into);
        const WRef seen = k == 1 ? whole : frames_[k - 1]->pass;
        step.portal_size = winding_area(whole);
        step.window_size = winding_area(seen);
        step.window.assign(seen.points, seen.points + seen.count);
        if (k >= 3)
            for (const SeparatorCache& cache : frames_[k - 1]->separators) {
                step.separators += cache.count;
                for (uint32_t i = 0; i < cache.count; ++i)
                    step.separator_planes.emplace_back(cache.planes[i].normal, cache.planes[i].dist);
            }
        chain.steps.push_back(std::move(step));
    }
    probe_->found[head_portal_] = std::move(chain);
    watching_ = false;
}

WRef FlowWorker::clip_to_frame_separators(WRef w, Frame& f, const Frame& prev, const DPlane& head_plane)
{
    for (int t = 0; t < 2 && w && level_ > t; ++t) {
        SeparatorCache& cache = f.separators[t];
        const WRef& a = t == 0 ? prev.source : prev.pass;
        const DPlane& a_plane = t == 0 ? head_plane : prev.portalplane;
        const WRef& b = t == 0 ? prev.pass : prev.source;
        for (uint32_t k = 0; w; ++k) {
            if (k == cache.count) {
                // More planes are needed: the next edges of A (at most kMaxSeparators kept:
                // fewer planes clip less, so the result stays conservative).
                if (cache.next_edge == 0)
                    sides_to_plane(b, a_plane, cache.b_side.data());
                bool found = false;
                while (!found && cache.next_edge < a.count && cache.count < kMaxSeparators)
                    found = edge_separator(a, b, cache.b_side.data(), cache.next_edge++, t == 1,
                                           cache.planes[cache.count]);
                if (!found)
                    break; // no edge left
                ++cache.count;
                ++separators_;
            }
            w = clip(w, cache.planes[k], f);
        }
    }
    return w;
}

const uint64_t* FlowWorker::spread_passage(const PassageRow& row, uint32_t from, uint32_t to)
{
    if (row.wide)
        return row.words + (from - row.lo);
    // Zero the range, then place the stored words (half of a span's words on e1m1). Keeping
    // spread_ zero between calls and clearing only the last row's words measured more
    // instructions than this (callgrind, e1m1).
    const uint64_t* stored = row.stored_from(from);
    const uint64_t present = row.present(from, to);
    const uint32_t count = to - from;
    if (present == (count < 64 ? (uint64_t{1} << count) - 1 : ~uint64_t{0}))
        return stored; // every word of the range is stored: they are consecutive already
    std::fill(spread_.begin(), spread_.begin() + count, uint64_t{0});
    for (uint64_t m = present; m != 0; m &= m - 1)
        spread_[uint32_t(std::countr_zero(m))] = *stored++;
    return spread_.data();
}

bool FlowWorker::adds_leaf(const Frame& prev, const RunRow& test, uint32_t first_run, uint32_t lo, uint32_t hi,
                           const uint64_t* passage) const
{
    for (uint32_t i = first_run; i < test.runs() && test.start(i) < hi; ++i) {
        const uint32_t start = test.start(i), end = std::min(hi, test.end(i));
        const uint64_t* t = test.words(i);
        for (uint32_t w = std::max(lo, start); w < end; ++w)
            if ((prev.mightsee[w] & t[w - start] & passage[w - lo] & ~vis_[w]) != 0)
                return true;
    }
    return false;
}

void FlowWorker::narrow_mightsee_into(Frame& f, const Frame& prev, const RunRow& test, uint32_t first_run,
                                      uint32_t lo, uint32_t hi, const uint64_t* passage)
{
    uint32_t w = std::max(lo, test.start(first_run));
    f.lo = w;
    for (uint32_t i = first_run; i < test.runs() && test.start(i) < hi; ++i) {
        const uint32_t start = test.start(i), end = std::min(hi, test.end(i));
        const uint64_t* t = test.words(i);
        for (; w < start; ++w)
            f.mightsee[w] = 0; // between two runs
        for (; w < end; ++w)
            f.mightsee[w] = prev.mightsee[w] & t[w - start] & passage[w - lo];
    }
    f.hi = w;
}

bool FlowWorker::walk(uint32_t pi, uint32_t rank, const RunRow& head_mightsee, const PruneRows& prune_rows,
                      const std::atomic<bool>& cancel)
{
    const DirectedPortal& p = g_.portals[pi];

    Frame& head = frame(0);
    head.source = portal_winding(pi);
    head.pass = {};
    head.portalplane = p.plane;
    head_portal_ = pi;
    watching_ = probe_ != nullptr && p.owner == probe_->from;
    // Dense while the walk reads it, written over the words its runs span only.
    const uint32_t runs = head_mightsee.runs();
    head.lo = runs == 0 ? 0 : head_mightsee.start(0);
    head.hi = runs == 0 ? 0 : head_mightsee.end(runs - 1);
    std::fill(head.mightsee.begin() + head.lo, head.mightsee.begin() + head.hi, 0);
    head_mightsee.or_into(head.mightsee.data());
    depth_ = 0;
    enter(p.leaf, pi);

    uint32_t steps = 0;
    bool cancelled = false;
    while (depth_ > 0) {
        Frame& f = *frames_[depth_];
        const Frame& prev = *frames_[depth_ - 1];
        if (f.cursor == f.end) {
            leave();
            continue;
        }
        if (++steps == kCancelCheckSteps) {
            steps = 0;
            if (cancel.load(std::memory_order_relaxed)) {
                cancelled = true;
                break;
            }
        }
        // The target's leaf from the compact array: most targets stop at the mightsee prune, and
        // loading each one's DirectedPortal for it was a cache miss (a quarter of this loop's
        // time at 5000 rooms, perf).
        const uint32_t q_leaf = g_.leaf_portal_dest[f.cursor];
        const uint32_t qi = g_.leaf_portals[f.cursor++];
        // The windings of the previous target are dead: its subtree is done.
        for (bool& used : f.slot_used)
            used = false;

        // Mightsee prune, then "nothing new": might = prev.mightsee & (q's visbits or mightsee).
        if (!prev.may_see(q_leaf))
            continue;
        // Symmetry: a line from the source's leaf through q, reversed, leaves q's leaf through
        // q's twin and reaches the source's leaf. When the twin's row (its visbits once final,
        // else its mightsee, by the same rule as every prune row) lacks that leaf, no line from
        // it passes q: the walk does not go on through q.
        if (symmetry_) {
            const RunRow back = prune_rows.row(qi ^ 1u, rank, wait_nanos_);
            if (!back) {
                cancelled = true;
                break;
            }
            if (!back.test(p.owner))
                continue;
        }
        const DirectedPortal& q = g_.portals[qi];
        // The next target's row is read a step from now if it passes the same prune: start
        // loading it (its first load was a third of this loop's time at 5000 rooms, perf).
        if (f.cursor < f.end && prev.may_see(g_.leaf_portal_dest[f.cursor]))
            prune_rows.prefetch(g_.leaf_portals[f.cursor], rank);
        // Can't go out a coplanar face.
        if (normals_equal(prev.portalplane.normal, -q.plane.normal))
            continue;
        // The passage (the portal into this leaf, q): q's own leaf, then the words it spans.
        uint32_t lo = prev.lo, hi = prev.hi;
        const uint64_t* passage = ones_.data(); // indexed from lo
        if (passages_ != nullptr) {
            // The row of (f.entry, q): q leaves the leaf f.entry entered. A passage row holds its
            // second portal's leaf unless it is empty (passage_row), so "q's leaf is in the row"
            // is "the row is not empty", without reading its words.
            const PassageRow row = passages_->row(f.entry, f.cursor - 1 - g_.leaf_first[f.leaf]);
            if (row.empty())
                continue;
            lo = std::max(lo, row.lo); // both ranges hold q's leaf's word: not empty
            hi = std::min(hi, row.hi);
            passage = spread_passage(row, lo, hi);
        }
        const RunRow test = prune_rows.row(qi, rank, wait_nanos_);
        if (!test) {
            cancelled = true;
            break;
        }
        const uint32_t first_run = test.first_run_after(lo);
        if (!adds_leaf(prev, test, first_run, lo, hi, passage))
            continue;
        const auto narrow = [&] { narrow_mightsee_into(f, prev, test, first_run, lo, hi, passage); };

        // The part of the target in front of the source portal.
        WRef pass = clip(portal_winding(qi), head.portalplane, f);
        if (!pass)
            continue;
        if (!prev.pass) {
            // The second leaf: only coplanarity can block it.
            f.source = prev.source;
            f.pass = pass;
            f.portalplane = q.plane;
            narrow();
            enter(q.leaf, qi);
            continue;
        }
        // The part of the target in front of the pass portal, and of the source behind the target.
        pass = clip(pass, prev.portalplane, f);
        if (!pass)
            continue;
        WRef source = clip(prev.source, q.plane.flipped(), f);
        if (!source)
            continue;

        // Test 0: source -> pass separators clip the target. Test 1: pass -> source, mirrored.
        pass = clip_to_frame_separators(pass, f, prev, head.portalplane);
        if (!pass)
            continue;
        // Test 2: target -> pass separators clip the source. Test 3: pass -> target, mirrored.
        const auto clip_source = [&](const DPlane& sep) {
            ++separators_;
            source = clip(source, sep, f);
            return bool(source);
        };
        if (level_ > 2)
            for_each_separator(pass, q.plane, prev.pass, false, b_side_.data(), clip_source);
        if (level_ > 3 && source)
            for_each_separator(prev.pass, prev.portalplane, pass, true, b_side_.data(), clip_source);
        if (!source)
            continue;

        f.source = source;
        f.pass = pass;
        f.portalplane = q.plane;
        narrow();
        if (window_memo_ && memo_.dominated_or_remember(qi, source, head.portalplane.normal, pass, q.plane.normal, f.mightsee.data(),
                                        f.lo, f.hi))
            continue; // an earlier walk past q held this one (window_memo.h)
        const bool seen_before = bits::test(vis_, q.leaf);
        if (enter(q.leaf, qi) && seen_before && target_checks_ && !may_add_leaf(head))
            leave(); // nothing below could add a leaf
    }
    memo_.clear();
    if (cancelled) {
        while (depth_ > 0)
            leave();
        return false;
    }
    return true;
}

} // namespace pvs::portal_vis
