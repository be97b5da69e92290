// The split of a bake's sources into shards (source_shards.h): every source in exactly one shard,
// the same split every time, and loads within one source's cost of each other (the greedy deal's
// bound: a shard receives a source only while it is the least loaded).
#include "visibility/methods/source_shards.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace pvs::test {
namespace {

TEST(SourceShards, EverySourceOnceAndLoadsWithinTheLargestCost)
{
    std::mt19937_64 random(7);
    for (uint32_t shards : {1u, 2u, 3u, 7u, 40u}) {
        std::vector<double> costs(500);
        for (double& c : costs)
            c = double(random() % 1000);
        std::vector<uint32_t> seen(costs.size(), 0);
        std::vector<double> load(shards, 0.0);
        for (uint32_t k = 0; k < shards; ++k) {
            const std::vector<uint32_t> sources = shard_sources(costs, {k, shards});
            EXPECT_TRUE(std::is_sorted(sources.begin(), sources.end()));
            for (uint32_t s : sources) {
                ++seen[s];
                load[k] += costs[s];
            }
            EXPECT_EQ(sources, shard_sources(costs, {k, shards})) << "deterministic";
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](uint32_t n) { return n == 1; }));
        const auto [lo, hi] = std::minmax_element(load.begin(), load.end());
        EXPECT_LE(*hi - *lo, *std::max_element(costs.begin(), costs.end())) << shards << " shards";
    }
}

TEST(SourceShards, EqualCostsGoRoundRobinNotByRange)
{
    const std::vector<double> costs(10, 1.0);
    EXPECT_EQ(shard_sources(costs, {0, 3}), (std::vector<uint32_t>{0, 3, 6, 9}));
    EXPECT_EQ(shard_sources(costs, {2, 3}), (std::vector<uint32_t>{2, 5, 8}));
    EXPECT_TRUE(shard_sources(costs, {11, 12}).empty());
}

} // namespace
} // namespace pvs::test
