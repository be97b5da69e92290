#include "ui/gui/pvs_rows.h"

#include "visibility/eval/pvs_gap.h"

#include <algorithm>
#include <bit>
#include <iterator>

namespace pvs::gui {

std::vector<uint32_t> pvs_row_regions(const Pvs& pvs, uint32_t region)
{
    std::vector<uint32_t> regions;
    if (region >= pvs.region_count())
        return regions;
    std::vector<uint64_t> words(pvs.words_per_row(), 0);
    pvs.decode_row(region, words);
    for (size_t w = 0; w < words.size(); ++w)
        for (uint64_t bits = words[w]; bits; bits &= bits - 1) {
            const auto r = uint32_t(w * 64 + size_t(std::countr_zero(bits)));
            if (r < pvs.region_count()) // padding bits past the last region mean nothing
                regions.push_back(r);
        }
    return regions;
}

void PvsColumnScan::restart(uint32_t column)
{
    region = column;
    next_row = 0;
    regions.clear();
}

bool PvsColumnScan::step(const Pvs& pvs, uint32_t max_rows)
{
    // Bit by bit (Pvs::visible reads one bit of a compressed row without decoding the rest).
    const uint32_t end = uint32_t(std::min<uint64_t>(pvs.row_count(), uint64_t(next_row) + max_rows));
    for (; next_row < end; ++next_row)
        if (pvs.visible(next_row, region))
            regions.push_back(next_row);
    return next_row >= pvs.row_count();
}

std::vector<uint32_t> portal_neighbours(const PortalSet& portals, uint32_t region)
{
    std::vector<uint32_t> regions;
    for (const Portal& p : portals.portals) {
        if (p.regions[0] == int32_t(region) && p.regions[1] >= 0)
            regions.push_back(uint32_t(p.regions[1]));
        else if (p.regions[1] == int32_t(region) && p.regions[0] >= 0)
            regions.push_back(uint32_t(p.regions[0]));
    }
    std::sort(regions.begin(), regions.end());
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
    return regions;
}

RegionDiff diff_regions(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b)
{
    RegionDiff diff;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff.only_a));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(diff.only_b));
    return diff;
}

PvsDiffCounts diff_pvs(const Pvs& a, const Pvs& b)
{
    if (a.region_count() != b.region_count() || a.row_count() != b.row_count())
        return {};
    const PvsGap gap = pvs_gap(&a, b); // b the reference: a's excess is only in a
    return {gap.excess_bits, gap.missing_bits};
}

} // namespace pvs::gui
