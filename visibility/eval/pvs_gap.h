// How far a PVS is from a reference, bit by bit: the two sides of the gap compare reports.
//   missing bits  pairs (A, B) the reference has and the PVS lacks: sight lines the PVS would
//                 pop (a conservative PVS against a lower-bound reference must have none);
//   excess bits   pairs the PVS has beyond the reference: an upper bound of the overdraw it causes
//                 (against a sampled reference, also the true pairs the sampling has not found).
// A null PVS is "none": every row full. A missing row (Pvs::row_missing) is full, as culling
// reads it. Both PVSs must have the same rows and regions (std::invalid_argument otherwise); a
// grid zone's rows are its view cells.
#pragma once

#include "visibility/pvs.h"

#include <cstdint>
#include <utility>
#include <span>
#include <vector>

namespace pvs {

struct PvsGap {
    uint64_t bits = 0;           // set bits of the PVS
    uint64_t reference_bits = 0; // set bits of the reference
    uint64_t missing_bits = 0;
    uint64_t excess_bits = 0;
    uint32_t rows_missing_bits = 0; // rows with at least one missing bit
    uint32_t rows_excess_bits = 0;  // rows with at least one excess bit
    uint32_t rows_differing = 0;    // rows with either
    double mean_visible = 0.0;      // bits / rows
    // The first kListedMissingPairs missing pairs (row, region), in row order: what a user opens
    // to see why (compare's JSON, the inspector's Compare panel).
    std::vector<std::pair<uint32_t, uint32_t>> missing_pairs;
};

inline constexpr size_t kListedMissingPairs = 64;
inline constexpr size_t kListedWorstPairs = 32; // worst_excess_pairs for compare and the inspector

PvsGap pvs_gap(const Pvs* pvs, const Pvs& reference);

// The excess pairs (row, region) that cost the most: the `count` with the largest
// region_cost[region] (what drawing the region for nothing costs, e.g. its triangles), the
// largest first, ties in row then region order. region_cost must hold one entry per region;
// same preconditions as pvs_gap. A null PVS is every region.
struct CostlyPair {
    uint32_t row = 0, region = 0;
    uint64_t cost = 0;
};
std::vector<CostlyPair> worst_excess_pairs(const Pvs* pvs, const Pvs& reference, std::span<const uint64_t> region_cost,
                                           size_t count);

} // namespace pvs
