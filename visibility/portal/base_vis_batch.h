// Base vis for a batch of up to 64 source portals at once: one flood whose marks are 64-bit
// masks of sources, one lane per source.
//
// Why. Flooded from one portal at a time (as base vis was until 2026-11-27), each flood on a big
// zone reads a fifth of the zone's tables: at 5000 generated rooms 126 000 floods entered 1.19
// billion leaves, and base vis's time was the loads of those leaves' slots, not the tests. The
// floods of portals that sit close together and face the same way cover mostly the same leaves,
// so a batch of them reads each leaf's slots once for all its lanes (there: 126 million entries
// of a leaf instead of 1.19 billion, 9 lanes tested on average where a portal is met). The tests
// stay one per source and tested portal: a leaf is entered with the lanes that reached it since
// it was last entered, and a portal is tested only for the lanes whose flood has not reached its
// destination yet.
//
// Contract. run() gives, for each source of the batch, its mightsee as base_vis.h defines it
// (a flood's reach does not depend on the order its leaves are entered in) and its count of set
// bits; each test is the float verdict of base_vis_tables.h, then portal_might_see where that is
// undecided, so the rows are exactly those of a flood through portal_might_see. A batch reads
// the graph and the tables only, so threads run batches at once, each with its own BaseVisBatch
// (its scratch: 16 bytes and a queue slot a leaf, and 64 dense rows; no allocation per run).
// base_vis_batch_order is only a matter of speed: any order gives the same rows.
#pragma once

#include "visibility/portal/base_vis_tables.h"
#include "visibility/portal/portal_graph.h"
#include "visibility/portal/source_lanes.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs::portal_vis {

constexpr uint32_t kBatchLanes = SourceLanes::kLanes;

// Every directed portal once, ordered so that runs of kBatchLanes flood much the same leaves:
// by the axis and sign of the normal's largest component, then by the leaf the portal leads into
// (the tree numbers leaves in space order), then by index.
std::vector<uint32_t> base_vis_batch_order(const Graph& g);

class BaseVisBatch {
public:
    explicit BaseVisBatch(const Graph& g);

    // The mightsee of each of `sources` (at most kBatchLanes directed portals).
    void run(const Graph& g, const BaseVisTables& tables, std::span<const uint32_t> sources);

    // After run(): source `lane`'s row (g.words words) and its count of set bits.
    std::span<const uint64_t> row(uint32_t lane) const { return {&rows_[lane * words_], words_}; }
    uint32_t count(uint32_t lane) const { return counts_[lane]; }

private:
    void flood(const Graph& g, const BaseVisTables& tables);
    void enter(uint32_t leaf, uint64_t lanes);
    void transpose_to_rows(uint32_t lanes);

    size_t words_ = 0;
    std::vector<uint64_t> reached_; // per leaf: the lanes whose flood has marked it
    std::vector<uint64_t> pending_; // per leaf: lanes that reached it since it was last entered
    std::vector<uint32_t> queue_;   // leaves with pending lanes, first in first out (a ring)
    uint32_t head_ = 0, tail_ = 0;
    std::vector<SourcePortal> sources_;
    SourceLanes lanes_; // sources_, four lanes to a vector
    std::vector<uint32_t> source_index_;
    std::vector<uint64_t> rows_; // kBatchLanes dense rows
    std::vector<uint32_t> counts_;
};

} // namespace pvs::portal_vis
