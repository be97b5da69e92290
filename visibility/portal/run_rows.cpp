// Bit rows as runs of nonzero words (run_rows.h).
#include "visibility/portal/run_rows.h"

#include <algorithm>
#include <cassert>

namespace pvs::portal_vis {

void encode_runs(std::span<const uint64_t> dense, std::vector<uint64_t>& out)
{
    out.clear();
    const auto n = uint32_t(dense.size());
    // Runs first (as start | end in the header slots), then the offsets once their count is known.
    std::vector<uint64_t>& o = out;
    o.push_back(0);
    uint32_t w = 0, runs = 0;
    while (w < n) {
        while (w < n && dense[w] == 0)
            ++w;
        if (w == n)
            break;
        const uint32_t start = w;
        // Extend over nonzero words and over single zero words followed by a nonzero one.
        while (w < n && (dense[w] != 0 || (w + 1 < n && dense[w + 1] != 0)))
            ++w;
        o.push_back(uint64_t{start} | uint64_t{w} << 32);
        ++runs;
    }
    o[0] = runs;
    uint32_t offset = 1 + runs + 1; // the words start after the count and R + 1 headers
    o.push_back(0);                 // the sentinel
    for (uint32_t i = 0; i < runs; ++i) {
        const uint32_t start = uint32_t(o[1 + i]), end = uint32_t(o[1 + i] >> 32);
        o[1 + i] = uint64_t{start} | uint64_t{offset} << 32;
        o.insert(o.end(), dense.begin() + start, dense.begin() + end);
        offset += end - start;
    }
    o[1 + runs] = uint64_t{offset} << 32;
    assert(o.size() == offset);
}

const uint64_t* RowPool::append_words(std::span<const uint64_t> encoded)
{
    if (encoded.empty())
        return nullptr; // nothing to read back (and no chunk may exist yet)
    if (capacity_ - used_ < encoded.size()) {
        capacity_ = std::max(kChunkWords, encoded.size());
        chunks_.push_back(std::make_unique_for_overwrite<uint64_t[]>(capacity_));
        allocated_words_ += capacity_;
        used_ = 0;
    }
    uint64_t* row = chunks_.back().get() + used_;
    std::copy(encoded.begin(), encoded.end(), row);
    used_ += encoded.size();
    return row;
}

} // namespace pvs::portal_vis
