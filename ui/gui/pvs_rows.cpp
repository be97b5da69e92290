#include "ui/gui/pvs_rows.h"

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

std::vector<uint32_t> pvs_column_regions(const Pvs& pvs, uint32_t region)
{
    std::vector<uint32_t> regions;
    if (region >= pvs.region_count())
        return regions;
    std::vector<uint64_t> words(pvs.words_per_row(), 0);
    const size_t word = region / 64;
    const uint64_t bit = uint64_t(1) << (region % 64);
    for (uint32_t r = 0; r < pvs.region_count(); ++r) {
        std::fill(words.begin(), words.end(), 0);
        pvs.decode_row(r, words);
        if (words[word] & bit)
            regions.push_back(r);
    }
    return regions;
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
    PvsDiffCounts counts;
    if (a.region_count() != b.region_count() || a.words_per_row() != b.words_per_row())
        return counts;
    std::vector<uint64_t> row_a(a.words_per_row()), row_b(b.words_per_row());
    for (uint32_t r = 0; r < a.region_count(); ++r) {
        std::fill(row_a.begin(), row_a.end(), 0);
        std::fill(row_b.begin(), row_b.end(), 0);
        a.decode_row(r, row_a);
        b.decode_row(r, row_b);
        for (size_t w = 0; w < row_a.size(); ++w) {
            // Bits past the last region (a missing row decodes as all ones) are not regions.
            const size_t first = w * 64, end = std::min<size_t>(first + 64, a.region_count());
            const uint64_t valid = end - first == 64 ? ~uint64_t(0) : (uint64_t(1) << (end - first)) - 1;
            counts.only_a += uint64_t(std::popcount(row_a[w] & ~row_b[w] & valid));
            counts.only_b += uint64_t(std::popcount(row_b[w] & ~row_a[w] & valid));
        }
    }
    return counts;
}

} // namespace pvs::gui
