// The frontier of a visibility relation: the pairs of regions worth a targeted search next.
//
// A sight line from A to B (B not A) crosses a chain of regions, each visible from A, and enters
// B from the last of them, X, through a portal of B. So every region A sees but is not yet known
// to see lies behind a portal of a region A is known to see: the frontier. Searching the frontier
// (reference_vis.h samples lines through a portal of A and the frontier portal of B), finding
// some pairs, and taking the frontier again reaches every pair a line can join, however far, and
// it never needs a PVS from any baker to tell it where to look.
//
// frontier_pairs gives each unordered pair once, as (a, b) with a < b, when b is behind a portal
// of a region a sees or a behind a portal of a region b sees, and a does not see b yet: ascending
// by a, then b. `rows` is the relation (regions x words_per_row words, row-major).
#pragma once

#include "visibility/reference/portal_sampler.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct FrontierPair {
    uint32_t a, b;
};

std::vector<FrontierPair> frontier_pairs(std::span<const uint64_t> rows, uint32_t regions, const PortalSampler& portals);

// The portals of `to` whose other side `from` sees in `rows` (the ways in, from `from`'s side),
// appended to `out` (cleared first).
void frontier_portals(std::span<const uint64_t> rows, uint32_t regions, const PortalSampler& portals, uint32_t from,
                      uint32_t to, std::vector<uint32_t>& out);

} // namespace pvs
