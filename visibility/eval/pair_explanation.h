// Why region A's PVS row holds region B, or why it does not: the answer behind `pvscope why`
// and the inspector's pair view.
//
// Contract. explain_pair looks at one ordered pair (A, B) of a zone with a BSP tree:
//  - in_pvs: whether the given PVS (any method's, or the file's) holds B in A's row;
//  - witness: a sight line from inside A to inside B, searched for this pair alone and proved
//    by the reference's rule (pair_witness.h); its absence after the budget is "no sight line
//    found", not a proof that none exists (as the reference itself, a lower bound);
//  - chain: the portal chain along which pvscope's portal flow (portal-full, the method's own
//    portals and level: the 2-D flow on a map extruded from 2-D, as the method does) reached B
//    from A (flow_chain.h), or none when the flow does not hold the pair. The chain explains
//    portal-full's bit; for another PVS it is what the clipped flow finds for the same pair.
//  - witness_regions / flow_cut: the regions along the witness, and the first of them the flow's
//    row of A lacks (a missing bit's "cut here");
//  - a camera standing at the witness's eye and looking along it, so `pvscope render --camera`
//    and the inspector show the view;
//  - verdict: Sees (a sight line exists and the PVS holds B), Overdraw (the PVS holds B, no sight
//    line was found: the chain says where the flow could not close), WouldPop (a sight line
//    exists, the PVS lacks B), Hidden (neither), Unexplained (the PVS holds B with no sight line
//    and no chain of the flow: a bit set by hand or by another tool's looser rule).
// A == B is Sees whenever the row holds A.
// Grid zones (an OBJ level with a .hepvs grid): A is a view cell (a PVS row), B an object; the
// witness is the mesh reference's (grid_witness.h: an eye in the cell in open space whose ray
// meets B's front first), and there is no portal flow, so no chain and no Unexplained.
// Throws std::invalid_argument for a zone with neither a tree nor a grid, or an id out of range
// (the message names it and the count); std::runtime_error when Embree cannot trace a grid
// zone's mesh. Library code: no output.
#pragma once

#include "visibility/methods/vis_method.h"
#include "visibility/portal/flow_chain.h"
#include "visibility/pvs.h"
#include "visibility/reference/pair_witness.h"
#include "visibility/zone.h"

#include <cstdint>
#include <optional>
#include <string>

namespace pvs {

enum class PairVerdict : uint8_t { Sees, Overdraw, WouldPop, Hidden, Unexplained };
const char* pair_verdict_name(PairVerdict verdict); // "sees", "overdraw", "would-pop", ...

struct ExplainOptions {
    MethodSettings flow;       // the portal flow's settings (sky, level, heights, threads)
    uint64_t witness_budget = 200000;
    uint64_t seed = 1;
    bool want_chain = true;    // false: no flow is run (the witness only)
    // The PVS explained is portal-full's own with these settings: the flow run for the chain is
    // that PVS, so the `pvs` argument is ignored and no second bake is needed (needs want_chain).
    bool explain_the_flow = false;
};

struct WitnessCamera {
    glm::dvec3 eye{0.0};
    double yaw_degrees = 0.0, pitch_degrees = 0.0; // as Camera: yaw 0 = +x, 90 = +y; pitch up
};

struct PairExplanation {
    uint32_t a = 0, b = 0;
    bool has_pvs = false;
    bool in_pvs = false;
    std::optional<SightWitness> witness;
    uint64_t witness_tries = 0;
    std::optional<WitnessCamera> camera; // with the witness
    std::optional<FlowChain> chain;
    bool chain_2d = false;   // the chain is the 2-D flow's (widths, not areas)
    bool grid = false;       // a grid zone: a is a view cell, b an object (no flow, no chain)
    bool flow_run = false;   // the portal flow ran (ExplainOptions::want_chain, a zone with a tree)
    bool flow_holds = false; // the flow's row of A holds B (it then has a chain)
    PortalSet portals;       // the portals the chain's steps index
    // The regions the witness passes through, in order from A to B, and (when the flow lacks a
    // region of them) the index of the first one portal-full's row of A lacks: where its chain
    // along the sight line was cut. For a missing bit, "the flow reached this far".
    std::vector<uint32_t> witness_regions;
    std::optional<size_t> flow_cut;
    PairVerdict verdict = PairVerdict::Hidden;
    std::string summary;     // one line in plain words
};

PairExplanation explain_pair(const Zone& zone, const Pvs* pvs, uint32_t a, uint32_t b, const ExplainOptions& options);

// The camera at `from` looking at `to`.
WitnessCamera camera_looking(const glm::dvec3& from, const glm::dvec3& to);

} // namespace pvs
