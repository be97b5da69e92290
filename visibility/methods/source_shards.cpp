#include "visibility/methods/source_shards.h"

#include <algorithm>
#include <numeric>
#include <queue>
#include <utility>

namespace pvs {

std::vector<uint32_t> shard_of_sources(std::span<const double> costs, uint32_t count)
{
    std::vector<uint32_t> shard_of(costs.size(), 0);
    if (count <= 1)
        return shard_of;
    std::vector<uint32_t> order(costs.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto cost = [&](uint32_t s) { return std::max(costs[s], 0.0); };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return cost(a) > cost(b); });
    // The least loaded shard on top; ties go to the lowest shard.
    using Load = std::pair<double, uint32_t>;
    std::priority_queue<Load, std::vector<Load>, std::greater<Load>> loads;
    for (uint32_t k = 0; k < count; ++k)
        loads.push({0.0, k});
    for (uint32_t s : order) {
        auto [load, k] = loads.top();
        loads.pop();
        shard_of[s] = k;
        loads.push({load + cost(s), k});
    }
    return shard_of;
}

std::vector<uint32_t> shard_sources(std::span<const double> costs, ShardSpec shard)
{
    const std::vector<uint32_t> shard_of = shard_of_sources(costs, shard.count);
    std::vector<uint32_t> sources;
    for (uint32_t s = 0; s < shard_of.size(); ++s)
        if (shard_of[s] == shard.index)
            sources.push_back(s);
    return sources;
}

} // namespace pvs
