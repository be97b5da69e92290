#include "visibility/eval/pvs_gap.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <vector>

namespace pvs {

PvsGap pvs_gap(const Pvs* pvs, const Pvs& reference)
{
    const uint32_t regions = reference.region_count(), rows = reference.row_count();
    if (pvs && (pvs->region_count() != regions || pvs->row_count() != rows))
        throw std::invalid_argument("the PVS has " + std::to_string(pvs->row_count()) + " rows of " +
                                    std::to_string(pvs->region_count()) + " regions and the reference " +
                                    std::to_string(rows) + " of " + std::to_string(regions));
    const size_t words = reference.words_per_row();
    std::vector<uint64_t> ours(words), theirs(words);
    if (!pvs)
        bits::fill(ours, regions); // none: every region, every row
    PvsGap gap;
    for (uint32_t r = 0; r < rows; ++r) {
        if (pvs)
            pvs->decode_row(r, ours);
        reference.decode_row(r, theirs);
        uint64_t row_missing = 0, row_excess = 0;
        for (size_t w = 0; w < words; ++w) {
            gap.bits += uint64_t(std::popcount(ours[w]));
            gap.reference_bits += uint64_t(std::popcount(theirs[w]));
            row_missing += uint64_t(std::popcount(theirs[w] & ~ours[w]));
            row_excess += uint64_t(std::popcount(ours[w] & ~theirs[w]));
        }
        gap.excess_bits += row_excess;
        gap.rows_excess_bits += row_excess ? 1 : 0;
        gap.rows_differing += row_missing || row_excess ? 1 : 0;
        for (size_t w = 0; w < words && row_missing && gap.missing_pairs.size() < kListedMissingPairs; ++w)
            for (uint64_t m = theirs[w] & ~ours[w]; m && gap.missing_pairs.size() < kListedMissingPairs; m &= m - 1)
                gap.missing_pairs.emplace_back(r, uint32_t(w * 64 + size_t(std::countr_zero(m))));
        gap.missing_bits += row_missing;
        gap.rows_missing_bits += row_missing ? 1 : 0;
    }
    gap.mean_visible = rows ? double(gap.bits) / rows : 0.0;
    return gap;
}

std::vector<CostlyPair> worst_excess_pairs(const Pvs* pvs, const Pvs& reference, std::span<const uint64_t> region_cost,
                                           size_t count)
{
    const uint32_t regions = reference.region_count(), rows = reference.row_count();
    if ((pvs && (pvs->region_count() != regions || pvs->row_count() != rows)) || region_cost.size() != regions)
        throw std::invalid_argument("worst_excess_pairs: the PVS, the reference and the costs disagree on the regions");
    const size_t words = reference.words_per_row();
    std::vector<uint64_t> ours(words), theirs(words);
    if (!pvs)
        bits::fill(ours, regions);
    // A heap of the `count` costliest so far, cheapest (then latest) on top.
    const auto cheaper = [](const CostlyPair& a, const CostlyPair& b) {
        return a.cost != b.cost ? a.cost > b.cost : std::pair(a.row, a.region) < std::pair(b.row, b.region);
    };
    std::vector<CostlyPair> heap;
    for (uint32_t r = 0; r < rows && count > 0; ++r) {
        if (pvs)
            pvs->decode_row(r, ours);
        reference.decode_row(r, theirs);
        for (size_t w = 0; w < words; ++w)
            for (uint64_t m = ours[w] & ~theirs[w]; m; m &= m - 1) {
                const uint32_t region = uint32_t(w * 64 + size_t(std::countr_zero(m)));
                const CostlyPair pair{r, region, region_cost[region]};
                if (heap.size() < count) {
                    heap.push_back(pair);
                    std::push_heap(heap.begin(), heap.end(), cheaper);
                } else if (pair.cost > heap.front().cost) {
                    std::pop_heap(heap.begin(), heap.end(), cheaper);
                    heap.back() = pair;
                    std::push_heap(heap.begin(), heap.end(), cheaper);
                }
            }
    }
    std::sort(heap.begin(), heap.end(), cheaper);
    return heap;
}

} // namespace pvs
