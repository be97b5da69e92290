// The chain of portals along which a portal flow reached one region from another: what
// `pvscope why` and the inspector show as the reason a PVS bit is set.
//
// Contract. A ChainProbe names a pair (from, to) of regions. Given to a bake (VisParams::probe,
// portal_vis.h; the 2-D baker likewise), the flow of every directed portal leaving `from`
// records, the first time its walk enters `to`, the walk's chain at that moment: the regions
// entered in order and the portal crossed into each, with how much of that portal the flow was
// still looking through. The bake's result is unchanged (recording only copies, off the walk's
// hot path: one compare per region entered). Each directed portal writes only its own slot, so
// the threads of a bake need no lock. best() picks the shortest chain (ties: the lowest portal),
// the most readable explanation; a walk may reach `to` along several chains, and only its first
// is kept.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

namespace pvs {

struct ChainStep {
    uint32_t region = 0;     // the region entered
    uint32_t portal = 0;     // the portal crossed into it: an index into the bake's PortalSet
    double portal_size = 0;  // the portal's area (3-D flow) or width (2-D flow)
    double window_size = 0;  // the part of it the flow still saw through (same unit); the first
                             // two steps see the whole portal, the flow clips from the third on
    uint32_t separators = 0; // separating planes the flow clipped this step's window by (3-D:
                             // tests 0 and 1 of the frame before; 2-D: 0)
    // Those planes (3-D), each (normal, distance) with the window on its front: the ones the
    // window was clipped by and survived, so the ones that "kept it open".
    std::vector<glm::dvec4> separator_planes;
    std::vector<glm::dvec3> window; // that part's points (3-D: a polygon; 2-D: a segment at z 0)
};

struct FlowChain {
    uint32_t directed_portal = 0; // the flow's source: the directed portal leaving `from`
    std::vector<ChainStep> steps; // from the region after `from` to `to`
};

struct ChainProbe {
    uint32_t from = 0, to = 0;
    // Filled by the bake: one slot per directed portal (a slot stays empty when that portal does
    // not leave `from` or its walk never entered `to`).
    std::vector<std::optional<FlowChain>> found;

    const FlowChain* best() const
    {
        const FlowChain* pick = nullptr;
        for (const auto& chain : found)
            if (chain && (pick == nullptr || chain->steps.size() < pick->steps.size()))
                pick = &*chain;
        return pick;
    }
};

} // namespace pvs
