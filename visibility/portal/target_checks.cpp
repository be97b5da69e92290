// Target checks (portal_vis.h, "Target checks"; after ericw's, §3.6, restricted): before the
// flow walks on from a leaf the portal already sees, whether any leaf the walk could still add
// is reachable through the frame's source and pass.
//
// Contract (FlowWorker::may_add_leaf, flow.h). Called right after entering a leaf already in
// vis(); when at most kTargetCheckLeaves leaves of the child's mightsee are unseen, a portal
// into each is clipped by the head's plane, the pass's plane and the frame's test-0/1
// separators; the leaves none of whose portals survives are removed from that mightsee, and
// false means none survived (the caller leaves the frame). In exact arithmetic this removes
// nothing visible. Uses the frame's windings as scratch; allocates nothing.
#include "visibility/portal/flow.h"

#include "visibility/bit_row.h"

#include <bit>

namespace pvs::portal_vis {
namespace {

constexpr uint32_t kTargetCheckLeaves = 64; // most unseen leaves worth checking

} // namespace

bool FlowWorker::may_add_leaf(const Frame& head)
{
    Frame& f = *frames_[depth_];
    Frame& prev = *frames_[depth_ - 1]; // the source, pass and plane f was entered with, f's mightsee
    // Checking more than kTargetCheckLeaves leaves would cost more than the walk it might
    // save: count them only that far.
    uint32_t unseen = 0;
    for (uint32_t w = prev.lo; w < prev.hi; ++w) {
        unseen += bits::popcount(prev.mightsee[w] & ~vis_[w]);
        if (unseen > kTargetCheckLeaves)
            return true;
    }
    ++target_check_count_;
    bool any_reachable = false;
    for (uint32_t w = prev.lo; w < prev.hi; ++w) {
        for (uint64_t left = prev.mightsee[w] & ~vis_[w]; left != 0; left &= left - 1) {
            const uint32_t leaf = w * 64 + uint32_t(std::countr_zero(left));
            if (leaf_reachable(leaf, f, prev, head))
                any_reachable = true;
            else
                prev.mightsee[w] &= ~(uint64_t{1} << (leaf & 63)); // no walk below reaches it
        }
    }
    target_check_prunes_ += !any_reachable;
    return any_reachable;
}

bool FlowWorker::leaf_reachable(uint32_t leaf, Frame& f, const Frame& prev, const Frame& head)
{
    // The whole region more than ON_EPSILON behind a plane its portals are clipped by: every
    // point of them is classified behind it, so none would survive (the same answer, no clip).
    const Vec& centre = g_.leaf_centre[leaf];
    const double reach = -g_.leaf_radius[leaf] - kOnEpsilon;
    if (head.portalplane.distance(centre) < reach || prev.portalplane.distance(centre) < reach)
        return false;
    for (int t = 0; t < 2 && level_ > t; ++t)
        for (uint32_t i = 0; i < f.separators[t].count; ++i)
            if (f.separators[t].planes[i].distance(centre) < reach)
                return false;
    for (uint32_t k = g_.leaf_first[leaf]; k < g_.leaf_first[leaf + 1]; ++k) {
        const uint32_t into = g_.leaf_portals[k] ^ 1u; // the twin of a portal out of `leaf` leads in
        for (bool& used : f.slot_used)
            used = false;
        WRef w = clip(portal_winding(into), head.portalplane, f);
        w = clip(w, prev.portalplane, f);
        if (clip_to_frame_separators(w, f, prev, head.portalplane))
            return true;
    }
    return false;
}

} // namespace pvs::portal_vis
