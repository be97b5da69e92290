// Passages (portal_vis.h, "Passages"; after q3map's passage vis): for every directed portal a
// and every portal b leaving a's destination, the leaves a line through a and then b can reach.
//
// Contract. build_passages builds every pair's row with `threads` workers (a pure function of
// the graph, the level and the mightsee rows, whatever the threads), then narrows each
// portal's mightsee to its destination plus its passages' rows (narrow_mightsee). It returns
// false, with `out` empty and mightsee untouched, when there are no portals, when the rows
// would take more than `budget` bytes (decided by their total size alone, not by timing; the
// rows of every 64th portal, built first, turn passages down when they extrapolate to more than
// twice the budget), or when cancelled. The rows are conservative: every leaf a line through a and b reaches is set.
// Passages::row(a, k) reads the row of a and the k-th portal leaving a's destination (the
// order of Graph::leaf_portals); the flow ANDs it into the child frame's mightsee.
#pragma once

#include "visibility/bit_row.h"
#include "visibility/portal/portal_graph.h"
#include "visibility/portal/run_rows.h"

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace pvs::portal_vis {

// A pair's row: for directed portal a and the k-th portal b leaving a's
// destination, the leaves a line through a and then b can reach. A row keeps only its words
// [lo, hi) (the others are zero): such a line reaches a few nearby leaves, and BSP leaf numbers
// follow the tree, so on e1m1 a row spans 5 of 19 words.
// Stored as one header word, so that reading a row touches one place, then its words:
//  - a narrow row (span of at most kPassageMaskSpan words, lo below 2^24: every row of the Quake
//    maps, whose widest spans 19) keeps only its nonzero words: the header holds lo in bits
//    0-23 and in bits 24-62 a mask of which of the words lo, lo + 1, ... are stored. Half the
//    words of a span are zero on e1m1 (177 001 of 345 873), so this takes the rows from 3.5 to
//    2.2 MB there;
//  - a wide row keeps every word of [lo, hi): bit 63 set, lo in bits 0-30, hi in bits 31-61.
inline constexpr uint32_t kPassageMaskSpan = 39;
inline constexpr uint64_t kPassageWide = uint64_t{1} << 63;

struct PassageRow {
    uint32_t lo = 0, hi = 0;
    bool wide = false;
    uint64_t mask = 0;               // narrow: bit j set when word lo + j is stored
    const uint64_t* words = nullptr; // wide: word w at words[w - lo]; narrow: the stored words in order

    static PassageRow decode(const uint64_t* header)
    {
        PassageRow r;
        r.words = header + 1;
        if ((*header & kPassageWide) != 0) {
            r.wide = true;
            r.lo = uint32_t(*header & 0x7fffffffu);
            r.hi = uint32_t((*header >> 31) & 0x7fffffffu);
        } else {
            r.lo = uint32_t(*header & 0xffffffu);
            r.mask = (*header >> 24) & ((uint64_t{1} << kPassageMaskSpan) - 1);
            r.hi = r.lo + uint32_t(std::bit_width(r.mask));
        }
        return r;
    }
    bool empty() const { return lo == hi; }
    // A narrow row's words inside [from, to), a range inside [lo, hi): bit i of present(from, to)
    // is set when word from + i is stored, and the stored words, in order, start at
    // stored_from(from).
    uint64_t present(uint32_t from, uint32_t to) const
    {
        const uint32_t count = to - from;
        const uint64_t in_range = mask >> (from - lo);
        return count < 64 ? in_range & ((uint64_t{1} << count) - 1) : in_range;
    }
    const uint64_t* stored_from(uint32_t from) const
    {
        return words + bits::popcount(mask & ((uint64_t{1} << (from - lo)) - 1));
    }
    // ORs the row into a dense row.
    void or_into(uint64_t* dense) const
    {
        if (wide) {
            for (uint32_t w = lo; w < hi; ++w)
                dense[w] |= words[w - lo];
            return;
        }
        const uint64_t* stored = words;
        for (uint64_t m = mask; m != 0; m &= m - 1)
            dense[lo + uint32_t(std::countr_zero(m))] |= *stored++;
    }
};

// Appends the encoding of the dense row `dense` (all its words) to `out`.
void encode_passage_row(std::span<const uint64_t> dense, std::vector<uint64_t>& out);

// The rows of a portal's pairs lie one after another in a block of a pool that never moves
// (built in parallel, they are never copied into one growing array: that copy was a peak).
struct Passages {
    std::vector<size_t> first;          // n + 1 offsets: a's pairs are [first[a], first[a + 1])
    std::vector<const uint64_t*> block; // per portal: its pairs' rows
    std::vector<uint32_t> start;        // per pair: the index of its header in its portal's block
    std::vector<RowPool> pools;         // one per builder thread

    PassageRow row(uint32_t a, size_t k) const { return PassageRow::decode(block[a] + start[first[a] + k]); }
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
