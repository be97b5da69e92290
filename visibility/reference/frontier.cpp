#include "visibility/reference/frontier.h"

#include "visibility/bit_row.h"

#include <algorithm>

namespace pvs {

std::vector<FrontierPair> frontier_pairs(std::span<const uint64_t> rows, uint32_t regions, const PortalSampler& portals)
{
    const size_t words = bits::words_for(regions);
    std::vector<uint64_t> reach(words);
    std::vector<FrontierPair> out;
    for (uint32_t a = 0; a < regions; ++a) {
        const std::span<const uint64_t> row = rows.subspan(size_t(a) * words, words);
        std::fill(reach.begin(), reach.end(), 0);
        bits::for_each_set(row, [&](size_t x) {
            for (const PortalSampler::Link& link : portals.links(uint32_t(x)))
                bits::set(reach, link.other);
        });
        // The frontier is not symmetric (b behind a portal of what a sees does not put a behind
        // a portal of what b sees), so both sides' pairs are kept, as (low, high), then merged.
        for (size_t w = 0; w < words; ++w)
            reach[w] &= ~row[w];
        bits::for_each_set(std::span<const uint64_t>(reach), [&](size_t b) {
            out.push_back(b > a ? FrontierPair{a, uint32_t(b)} : FrontierPair{uint32_t(b), a});
        });
    }
    std::sort(out.begin(), out.end(), [](FrontierPair x, FrontierPair y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    out.erase(std::unique(out.begin(), out.end(), [](FrontierPair x, FrontierPair y) { return x.a == y.a && x.b == y.b; }),
              out.end());
    return out;
}

void frontier_portals(std::span<const uint64_t> rows, uint32_t regions, const PortalSampler& portals, uint32_t from,
                      uint32_t to, std::vector<uint32_t>& out)
{
    out.clear();
    const size_t words = bits::words_for(regions);
    const std::span<const uint64_t> row = rows.subspan(size_t(from) * words, words);
    for (const PortalSampler::Link& link : portals.links(to))
        if (bits::test(row, link.other))
            out.push_back(link.portal);
}

} // namespace pvs
