#include "wld/quake2/phs.h"

#include "visibility/bit_row.h"

#include <algorithm>

namespace pvs::quake2 {

std::vector<uint64_t> compute_phs(std::span<const uint64_t> pvs_rows, uint32_t clusters, PhsRule rule)
{
    const size_t words = bits::words_for(clusters);
    // ericw ORs whole 8-byte words of an unpadded row of (clusters + 7) / 8 bytes.
    const size_t or_words = rule == PhsRule::Quake2 ? words : ((size_t(clusters) + 7) / 8) / 8;
    std::vector<uint64_t> phs(pvs_rows.begin(), pvs_rows.begin() + std::ptrdiff_t(size_t(clusters) * words));
    for (uint32_t c = 0; c < clusters; ++c) {
        const std::span<const uint64_t> own = pvs_rows.subspan(size_t(c) * words, words);
        uint64_t* out = phs.data() + size_t(c) * words;
        bits::for_each_set(own, [&](size_t seen) {
            const uint64_t* theirs = pvs_rows.data() + seen * words;
            for (size_t w = 0; w < or_words; ++w)
                out[w] |= theirs[w];
        });
    }
    return phs;
}

} // namespace pvs::quake2
