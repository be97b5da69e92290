// Bit rows kept as runs of nonzero words, for the rows a bake keeps per directed portal
// (mightsee, visbits; portal_vis.h, "Memory").
//
// Why. A directed portal's rows are sparse and local: BSP leaf numbers follow the tree, so the
// leaves a portal may see or sees sit in a few runs of words. On the generated 1500-room zone
// (198 words a row) a finished visbits row has 6.8 nonzero words in 1.8 runs and a narrowed
// mightsee 46 in 5; kept dense, the two rows of every portal were most of a big bake's memory.
// So a row is kept dense only while it is being built (a worker's scratch), and stored as runs
// once finished.
//
// Contract. encode_runs appends the runs of a dense row of `words` words to `out`: gaps of one
// zero word are kept inside a run (a gap costs what a run header costs), so an encoded row
// takes at most 2 + words + (runs + 1) words. A RunRow reads one: runs() runs, run i covering
// word indices [start(i), end(i)), strictly increasing and disjoint, its words at words(i);
// every word outside the runs is zero. RowPool stores encoded rows for one writer at a time
// (one pool per thread): a row, once appended, never moves until the pool is destroyed, so
// readers on other threads may keep its address (publish it with release/acquire).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace pvs::portal_vis {

// Layout: data[0] = run count R; data[1 + i] for i in [0, R] = start(i) | offset(i) << 32, where
// offset(i) is the index in data of run i's first word (the sentinel i = R holds the end of the
// last run's words), so run i has offset(i + 1) - offset(i) words.
struct RunRow {
    const uint64_t* data = nullptr;

    explicit operator bool() const { return data != nullptr; }
    uint32_t runs() const { return uint32_t(data[0]); }
    uint32_t start(uint32_t i) const { return uint32_t(data[1 + i]); }
    uint32_t end(uint32_t i) const { return start(i) + (offset(i + 1) - offset(i)); }
    const uint64_t* words(uint32_t i) const { return data + offset(i); }
    // The first run that ends after word w (runs() when none).
    uint32_t first_run_after(uint32_t w) const
    {
        uint32_t lo = 0, hi = runs();
        while (lo < hi) {
            const uint32_t mid = (lo + hi) / 2;
            if (end(mid) <= w)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    }
    bool test(uint32_t bit) const
    {
        const uint32_t w = bit >> 6;
        const uint32_t i = first_run_after(w);
        return i < runs() && start(i) <= w && ((words(i)[w - start(i)] >> (bit & 63)) & 1u) != 0;
    }
    // ORs the row into a dense row (of at least end(runs() - 1) words).
    void or_into(uint64_t* dense) const
    {
        for (uint32_t i = 0; i < runs(); ++i) {
            const uint64_t* src = words(i);
            for (uint32_t w = start(i); w < end(i); ++w)
                dense[w] |= src[w - start(i)];
        }
    }
    size_t size_words() const { return offset(runs()); }

private:
    uint32_t offset(uint32_t i) const { return uint32_t(data[1 + i] >> 32); }
};

// Appends the encoding of `dense` to `out` (cleared first).
void encode_runs(std::span<const uint64_t> dense, std::vector<uint64_t>& out);

class RowPool {
public:
    // A copy of an encoded row (encode_runs' output), at an address that stays valid.
    RunRow append(std::span<const uint64_t> encoded) { return RunRow{append_words(encoded)}; }
    // A copy of any words, at an address that stays valid (nullptr for none).
    const uint64_t* append_words(std::span<const uint64_t> words);
    // The words written so far, with the slack of every full chunk: the last chunk's unwritten
    // tail is never touched, so it takes no memory.
    size_t bytes() const { return (allocated_words_ - (capacity_ - used_)) * sizeof(uint64_t); }

private:
    static constexpr size_t kChunkWords = size_t{1} << 16; // 512 KB: few chunks, little slack

    std::vector<std::unique_ptr<uint64_t[]>> chunks_;
    size_t used_ = 0, capacity_ = 0; // words of the last chunk
    size_t allocated_words_ = 0;
};

} // namespace pvs::portal_vis
