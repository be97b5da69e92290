// Passages (portal_vis.h, "Passages"; after q3map's passage vis): for every directed portal a
// and every portal b leaving a's destination, the leaves a line through a and then b can reach.
//
// Contract. build_passages builds every pair's row with `threads` workers (a pure function of
// the graph, the level and the mightsee rows, whatever the threads), then narrows each
// portal's mightsee to its destination plus its passages' rows (narrow_mightsee). It returns
// false, with `out` empty and mightsee untouched, when there are no portals, when the rows
// would take more than `budget` bytes (decided by their total size alone, not by timing), or
// when cancelled. The rows are conservative: every leaf a line through a and b reaches is set.
// Passages::row(a, k) reads the row of a and the k-th portal leaving a's destination (the
// order of Graph::leaf_portals); the flow ANDs it into the child frame's mightsee.
#pragma once

#include "visibility/portal/portal_graph.h"
#include "visibility/portal/run_rows.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace pvs::portal_vis {

// A pair's row: for directed portal a and the k-th portal b leaving a's
// destination, the leaves a line through a and then b can reach. A row keeps only its words
// [lo, hi) (the others are zero): such a line reaches a few nearby leaves, and BSP leaf numbers
// follow the tree, so on e1m1 a row spans 5 of 19 words.
// Stored as a header word (lo in the low half, hi in the high half) followed by the words, so
// that reading a row touches one place.
struct PassageRow {
    uint32_t lo = 0, hi = 0;
    const uint64_t* words = nullptr; // word w of the row, for w in [lo, hi), is words[w - lo]

    bool test(uint32_t leaf) const
    {
        const uint32_t w = leaf >> 6;
        return w >= lo && w < hi && ((words[w - lo] >> (leaf & 63)) & 1u) != 0;
    }
};

// The rows of a portal's pairs lie one after another in a block of a pool that never moves
// (built in parallel, they are never copied into one growing array: that copy was a peak).
struct Passages {
    std::vector<size_t> first;          // n + 1 offsets: a's pairs are [first[a], first[a + 1])
    std::vector<const uint64_t*> block; // per portal: its pairs' rows
    std::vector<uint32_t> start;        // per pair: the index of its header in its portal's block
    std::vector<RowPool> pools;         // one per builder thread

    PassageRow row(uint32_t a, size_t k) const
    {
        const uint64_t* header = block[a] + start[first[a] + k];
        return {uint32_t(*header), uint32_t(*header >> 32), header + 1};
    }
    size_t pairs() const { return start.size(); }
    size_t bytes() const
    {
        size_t pooled = 0;
        for (const RowPool& pool : pools)
            pooled += pool.bytes();
        return first.capacity() * sizeof(size_t) + block.capacity() * sizeof(uint64_t*) +
               start.capacity() * sizeof(uint32_t) + pooled;
    }
};

// Every portal a's mightsee narrowed to its destination plus what its passages reach (a line
// from a into a leaf beyond its destination leaves the destination through some portal b):
// each row replaced by its narrowed copy, stored in `pool`.
void narrow_mightsee(const Graph& g, const Passages& passages, std::vector<RunRow>& mightsee, RowPool& pool);

// mightsee: every directed portal's row. On success it is narrowed, its new rows in `narrowed`
// (the old rows are no longer referenced).
bool build_passages(const Graph& g, int level, std::vector<RunRow>& mightsee, RowPool& narrowed, size_t budget,
                    unsigned threads, std::atomic<bool>& cancel, std::atomic<bool>& user_cancel,
                    const std::function<bool(double)>& progress, Passages& out);

} // namespace pvs::portal_vis
