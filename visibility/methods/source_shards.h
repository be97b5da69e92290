// Splitting a bake into shards: which sources (the rows a method computes one by one: a region's,
// a view cell's) shard K of N bakes, so that the shards cost about the same.
//
// The split is by a cost estimate per source (VisMethod::source_costs: for the raster baker the
// points a cell renders), not by id ranges: ids follow the tree or the grid, so a range is one
// part of the zone, and a zone's rock, sky or dense rooms would land on one shard. Sources are
// dealt greedily, the costliest first, each to the shard with the least cost so far (ties: the
// lowest shard); equal costs thus go round-robin. Deterministic: the same costs and N give the
// same split on every machine, so each shard computes its own part without talking to the others.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct ShardSpec {
    uint32_t index = 0; // K, in [0, count)
    uint32_t count = 1; // N >= 1
};

// For each source, its shard in [0, count). Costs below zero count as zero.
std::vector<uint32_t> shard_of_sources(std::span<const double> costs, uint32_t count);

// The sources of one shard, ascending.
std::vector<uint32_t> shard_sources(std::span<const double> costs, ShardSpec shard);

} // namespace pvs
