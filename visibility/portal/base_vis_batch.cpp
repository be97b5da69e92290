// Base vis in batches (base_vis_batch.h).
#include "visibility/portal/base_vis_batch.h"

#include "visibility/bit_row.h"
#include "visibility/portal/base_vis.h"

#include <algorithm>
#include <bit>
#include <glm/common.hpp>
#include <tuple>

namespace pvs::portal_vis {
namespace {

// The 64 x 64 bit matrix a (row r = a[r], column c = bit c) transposed in place: swaps the
// off-diagonal blocks of 32, then of 16 inside each, down to single bits (6 rounds of 32 swaps).
void transpose64(uint64_t* a)
{
    uint64_t mask = 0x00000000ffffffffu;
    for (uint32_t j = 32; j != 0; j >>= 1, mask ^= mask << j) {
        for (uint32_t k = 0; k < 64; k = ((k | j) + 1) & ~j) {
            const uint64_t t = ((a[k] >> j) ^ a[k | j]) & mask;
            a[k] ^= t << j;
            a[k | j] ^= t;
        }
    }
}

// 0..5: the axis of the normal's largest component, twice, plus one when it is negative.
uint32_t facing_bin(const DPlane& plane)
{
    const Vec a = glm::abs(plane.normal);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return uint32_t(axis) * 2 + (plane.normal[axis] < 0.0 ? 1u : 0u);
}

} // namespace

std::vector<uint32_t> base_vis_batch_order(const Graph& g)
{
    const uint32_t n = uint32_t(g.portals.size());
    std::vector<uint64_t> keys(n);
    for (uint32_t i = 0; i < n; ++i)
        keys[i] = uint64_t(facing_bin(g.portals[i].plane)) << 32 | g.portals[i].leaf;
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return std::tie(keys[a], a) < std::tie(keys[b], b); });
    return order;
}

BaseVisBatch::BaseVisBatch(const Graph& g)
    : words_(g.words), reached_(g.leaf_count, 0), pending_(g.leaf_count, 0), queue_(size_t{g.leaf_count} + 1),
      rows_(kBatchLanes * g.words, 0), counts_(kBatchLanes, 0)
{
    sources_.reserve(kBatchLanes);
    source_index_.reserve(kBatchLanes);
}

void BaseVisBatch::enter(uint32_t leaf, uint64_t lanes)
{
    reached_[leaf] |= lanes;
    if (pending_[leaf] == 0) { // not queued: queue it (each leaf is queued at most once, so the
                               // ring of leaf_count + 1 never fills: head == tail means empty)
        queue_[tail_] = leaf;
        tail_ = tail_ + 1 == queue_.size() ? 0 : tail_ + 1;
    }
    pending_[leaf] |= lanes;
}

void BaseVisBatch::run(const Graph& g, const BaseVisTables& tables, std::span<const uint32_t> sources)
{
    const uint32_t lanes = uint32_t(std::min<size_t>(sources.size(), kBatchLanes));
    sources_.clear();
    source_index_.assign(sources.begin(), sources.begin() + lanes);
    head_ = tail_ = 0;
    for (uint32_t lane = 0; lane < lanes; ++lane) {
        sources_.emplace_back(g, tables, source_index_[lane]);
        lanes_.set(lane, sources_.back());
        enter(g.portals[source_index_[lane]].leaf, uint64_t{1} << lane); // p leads there: marked
    }
    flood(g, tables);
    transpose_to_rows(lanes);
}

// Leaves are entered in queue order with the lanes pending on them; for each portal leaving the
// leaf, the lanes that have not reached its destination are tested, each on its own source: the
// spheres four lanes at a time (source_lanes.h), the rest one lane at a time.
void BaseVisBatch::flood(const Graph& g, const BaseVisTables& tables)
{
    while (head_ != tail_) {
        const uint32_t leaf = queue_[head_];
        head_ = head_ + 1 == queue_.size() ? 0 : head_ + 1;
        const uint64_t entering = pending_[leaf];
        pending_[leaf] = 0;
        const FloodSlot* header = &tables.slots[tables.leaf_slot[leaf]];
        const uint32_t first_entry = header->slot;
        const uint64_t front = lanes_.lanes_in_front(tables, header->sphere, entering);
        for (uint32_t j = 0; j < header->leaf; ++j) {
            const FloodSlot& t = header[1 + j];
            const uint64_t untested = entering & ~reached_[t.leaf];
            if (untested == 0)
                continue;
            const size_t k = first_entry + j;
            const SphereVerdicts v = lanes_.sphere_verdicts(tables, t, untested, front);
            uint64_t pass = v.might_see, near = untested & ~(v.might_see | v.cannot_see);
            while (near != 0) {
                const uint32_t lane = uint32_t(std::countr_zero(near));
                const uint64_t bit = uint64_t{1} << lane;
                near &= near - 1;
                const Verdict verdict = verdict_near_planes(tables, sources_[lane], t, k, (front & bit) != 0);
                if (verdict == Verdict::kMightSee ||
                    (verdict == Verdict::kUndecided &&
                     portal_might_see(g, g.portals[source_index_[lane]], g.portals[g.leaf_portals[k]])))
                    pass |= bit;
            }
            if (pass != 0)
                enter(t.leaf, pass);
        }
    }
}

// reached_ (a lane mask per leaf) into one dense row per lane, 64 leaves at a time; reached_ is
// left all zero for the next batch.
void BaseVisBatch::transpose_to_rows(uint32_t lanes)
{
    const size_t leaf_count = reached_.size();
    uint64_t block[64];
    std::fill(counts_.begin(), counts_.end(), 0);
    for (size_t w = 0; w < words_; ++w) {
        const size_t first = w * 64, count = std::min<size_t>(64, leaf_count - first);
        uint64_t any = 0;
        for (size_t i = 0; i < count; ++i) {
            block[i] = reached_[first + i];
            any |= block[i];
            reached_[first + i] = 0;
        }
        if (any == 0) {
            for (uint32_t lane = 0; lane < lanes; ++lane)
                rows_[lane * words_ + w] = 0;
            continue;
        }
        std::fill(block + count, block + 64, 0);
        transpose64(block);
        for (uint32_t lane = 0; lane < lanes; ++lane) {
            rows_[lane * words_ + w] = block[lane];
            counts_[lane] += bits::popcount(block[lane]);
        }
    }
}

} // namespace pvs::portal_vis
