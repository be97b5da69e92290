// Dominated windows of the 3-D portal flow (flow.h), as the 2-D flow has them
// (portal_vis_2d.h, "Dominated windows").
//
// The state a walk carries past portal q is the source (a part of the head portal's winding),
// the pass (a part of q's winding) and the mightsee. Every line the walk below can follow passes
// through that source and that pass, and the walk's tests only ever remove lines; so a walk that
// arrives at q with a source inside an earlier walk's source, a pass inside its pass (each a
// convex polygon in its portal's plane) and a mightsee inside its mightsee follows only lines the
// earlier walk followed, and can add no region a conservative flow from the earlier window would
// not have: it is skipped. Per walk (one head portal), up to kWindowsPerPortal windows are kept
// per portal, the first ones met.
//
// Soundness. The earlier walk's result is an upper bound of the regions its lines reach, so the
// skip keeps the flow an upper bound of the true visibility (not bit for bit the flow without it:
// ericw's separators are not monotone in their windows, so the later walk might have kept a few
// regions its lines do not reach). "Inside" allows a vertex kInsideTolerance (1e-6 units) beyond
// an edge: clips of one winding leave their points on its edges up to round-off; a line this
// allows through that the earlier walk did not follow passes within 1e-6 of its window, far below
// the reference's beam margin (0.05), so no sight line the reference can prove is lost.
//
// Memory: the kept polygons' points and mightsee words in flat arrays, reused from walk to walk;
// nothing is allocated once they have grown to the largest walk's needs.
#pragma once

#include "visibility/portal/flow_frame.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs::portal_vis {

inline constexpr uint32_t kWindowsPerPortal = 8;
inline constexpr double kInsideTolerance = 1e-6;

// Whether every point of `inner` lies inside the convex polygon `outer` (both in the plane with
// normal `normal`), within kInsideTolerance. False for a degenerate outer.
bool polygon_inside(const Vec* inner, uint32_t inner_count, const Vec* outer, uint32_t outer_count, const Vec& normal);

class WindowMemo {
public:
    // Before the first walk: one list per directed portal.
    void resize(size_t portals)
    {
        first_.assign(portals, kNone);
        count_.assign(portals, 0);
    }
    // Whether an earlier window of this walk at portal q holds (source, pass, mightsee words
    // [lo, hi)); when none does and q has room, this one is kept.
    bool dominated_or_remember(uint32_t q, const WRef& source, const Vec& source_normal, const WRef& pass,
                               const Vec& pass_normal, const uint64_t* mightsee, uint32_t lo, uint32_t hi);
    // After a walk: forget its windows.
    void clear();
    size_t dominated() const { return dominated_; }

private:
    static constexpr uint32_t kNone = UINT32_MAX;
    struct Window {
        uint32_t source_at, source_count, pass_at, pass_count;
        size_t words_at;
        uint32_t lo, hi;
        uint32_t next;
    };
    bool holds(const Window& w, const WRef& source, const Vec& source_normal, const WRef& pass, const Vec& pass_normal,
               const uint64_t* mightsee, uint32_t lo, uint32_t hi) const;

    std::vector<uint32_t> first_; // per directed portal: its newest window, or kNone
    std::vector<uint8_t> count_;
    std::vector<uint32_t> touched_;
    std::vector<Window> windows_;
    std::vector<Vec> points_;
    std::vector<uint64_t> words_;
    size_t dominated_ = 0;
};

} // namespace pvs::portal_vis
