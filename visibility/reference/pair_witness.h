// A sight line between two given regions: the sampled reference (reference_vis.h) asked about
// one pair, as `pvscope why` needs it.
//
// Contract. find_sight_line tries up to `budget` lines and returns the first that proves the
// pair by the reference's own rule (line_witness.h): a segment whose ends lie in A and in B by
// the tree (TreeTracer::region_at, in double), whose trace from one end to the other is open
// (tree_trace.h: no solid, outside or opaque leaf on the way) and which is open as a beam of
// kBeamMargin. The ends are the middles of the line's runs through A and B, so they lie inside
// the regions, not on their boundary. No line is claimed that the reference would not count.
//
// Where the lines come from, in turn (all deterministic in `seed`, a, b and the try's index):
//   - two points drawn in the regions' volumes (region_sampler.h), joined;
//   - a point of a polygon in `near_a` and a point of a polygon in `near_b` (polygons chosen with
//     probability by area), the line through both traced both ways out to `reach`: every line
//     from A to B crosses a portal of A and a portal of B, so given those portals this samples
//     every sight line the pair has, and given a flow's windows (flow_chain.h) it samples where
//     the flow says the sight lines are.
// Without polygons, only the first kind. Thread-safe: const inputs, own scratch.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/reference/tree_trace.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <vector>

namespace pvs {

struct SightWitness {
    glm::dvec3 from{0.0}, to{0.0}; // strictly inside A and B
    uint64_t tries = 0;            // lines tried, this one included
};

struct WitnessSearch {
    uint64_t budget = 200000; // lines tried at most
    uint64_t seed = 1;
    double reach = 1e5;       // how far a line through two polygon points is traced each way
    Aabb world;               // when not empty: lines end where they leave it (zone_portal_world)
    std::span<const std::vector<glm::dvec3>> near_a; // convex polygons A's sight lines cross
    std::span<const std::vector<glm::dvec3>> near_b; // the same for B
};

// The first line proving A sees B, or nothing when none was found in the budget (`tries`, when
// given, receives the lines tried). A == B: a line inside A.
std::optional<SightWitness> find_sight_line(const TreeTracer& tracer, const RegionSampler& sampler, uint32_t a,
                                            uint32_t b, const WitnessSearch& search, uint64_t* tries = nullptr);

// Whether the segment from `from` to `to` proves that region a sees region b (the rule above).
bool proves_sight(const TreeTracer& tracer, const glm::dvec3& from, const glm::dvec3& to, uint32_t a, uint32_t b,
                  TreeTracer::Scratch& scratch);

} // namespace pvs
