// The portal flow (flow.h): the walk, entering a leaf, and the clips by the frame's cached
// separators (tests 0 and 1).
#include "visibility/portal/flow.h"

#include "visibility/bit_row.h"
#include "visibility/portal/separators.h"

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
    f.leaf = leaf;
    f.entry = entry;
    f.cursor = g_.leaf_first[leaf];
    f.end = g_.leaf_first[leaf + 1];
    f.separators[0].next_edge = f.separators[1].next_edge = 0;
    f.separators[0].count = f.separators[1].count = 0;
    on_stack_[leaf] = 1;
    bits::set(vis_, leaf);
    return true;
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
            }
            w = clip(w, cache.planes[k], f);
        }
    }
    return w;
}

bool FlowWorker::run(uint32_t pi, uint32_t rank, const uint64_t* head_mightsee, const PruneRows& prune_rows,
                     const std::atomic<bool>& cancel)
{
    const DirectedPortal& p = g_.portals[pi];
    const size_t words = g_.words;
    std::fill(vis_.begin(), vis_.end(), 0);

    Frame& head = frame(0);
    head.source = portal_winding(pi);
    head.pass = {};
    head.portalplane = p.plane;
    std::copy(head_mightsee, head_mightsee + words, head.mightsee.begin());
    head.lo = 0;
    head.hi = uint32_t(words);
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
        const uint32_t qi = g_.leaf_portals[f.cursor++];
        const DirectedPortal& q = g_.portals[qi];
        // The windings of the previous target are dead: its subtree is done.
        for (bool& used : f.slot_used)
            used = false;

        // Mightsee prune, then "nothing new": might = prev.mightsee & (q's visbits or mightsee).
        const uint32_t leaf_word = q.leaf >> 6;
        if (leaf_word < prev.lo || leaf_word >= prev.hi || !bits::test(prev.mightsee, q.leaf))
            continue;
        // Can't go out a coplanar face.
        if (normals_equal(prev.portalplane.normal, -q.plane.normal))
            continue;
        // The passage (the portal into this leaf, q): q's own leaf, then the words it spans.
        uint32_t lo = prev.lo, hi = prev.hi;
        const uint64_t* passage = ones_.data(); // indexed from lo
        if (passages_ != nullptr) {
            const PassageRow row = passages_->row(f.entry, f.cursor - 1 - g_.leaf_first[f.leaf]);
            if (!row.test(q.leaf))
                continue;
            lo = std::max(lo, row.lo);
            hi = std::min(hi, row.hi);
            passage = row.words + (lo - row.lo);
        }
        const uint64_t* test = prune_rows.row(qi, rank, wait_nanos_);
        if (test == nullptr) {
            cancelled = true;
            break;
        }
        {
            uint32_t w = lo;
            while (w < hi && (prev.mightsee[w] & test[w] & passage[w - lo] & ~vis_[w]) == 0)
                ++w;
            if (w >= hi)
                continue;
        }
        const auto narrow = [&] {
            for (uint32_t w = lo; w < hi; ++w)
                f.mightsee[w] = prev.mightsee[w] & test[w] & passage[w - lo];
            f.lo = lo;
            f.hi = hi;
        };

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
        const bool seen_before = bits::test(vis_, q.leaf);
        if (enter(q.leaf, qi) && seen_before && target_checks_ && !may_add_leaf(head))
            leave(); // nothing below could add a leaf
    }
    if (cancelled) {
        while (depth_ > 0)
            leave();
        return false;
    }
    return true;
}

} // namespace pvs::portal_vis
