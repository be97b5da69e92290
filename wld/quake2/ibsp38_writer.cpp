#include "wld/quake2/ibsp38_writer.h"

#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"
#include "wld/quake2/ibsp38_file.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <numeric>
#include <stdexcept>

namespace pvs::quake2 {
namespace {

void put_u32(std::vector<uint8_t>& out, size_t at, uint32_t v)
{
    for (int k = 0; k < 4; ++k)
        out[at + size_t(k)] = uint8_t(v >> (8 * k));
}

} // namespace

std::vector<uint8_t> encode_visibility_lump(std::span<const uint64_t> pvs_rows, std::span<const uint64_t> phs_rows,
                                            uint32_t clusters)
{
    const size_t words = bits::words_for(clusters);
    if (pvs_rows.size() != size_t(clusters) * words || phs_rows.size() != size_t(clusters) * words)
        throw std::invalid_argument("visibility lump: the rows do not match " + std::to_string(clusters) + " clusters");
    std::vector<uint8_t> lump(4 + size_t(clusters) * 8, 0);
    put_u32(lump, 0, clusters);
    std::unordered_map<std::string, uint32_t> written; // a row's bytes -> its offset
    std::vector<uint8_t> row;
    auto place = [&](std::span<const uint64_t> bits) {
        row.clear();
        encode_quake_rle(bits, clusters, row);
        const auto [it, fresh] = written.emplace(std::string(row.begin(), row.end()), uint32_t(lump.size()));
        if (fresh)
            lump.insert(lump.end(), row.begin(), row.end());
        return it->second;
    };
    for (uint32_t c = 0; c < clusters; ++c) {
        put_u32(lump, 4 + size_t(c) * 8, place(pvs_rows.subspan(size_t(c) * words, words)));
        put_u32(lump, 8 + size_t(c) * 8, place(phs_rows.subspan(size_t(c) * words, words)));
    }
    return lump;
}

std::vector<uint8_t> with_visibility_lump(std::span<const uint8_t> map, std::span<const uint8_t> visibility,
                                          const std::string& file)
{
    const Ibsp38File parsed = read_ibsp38(map, file); // checks the header and every lump's span
    constexpr size_t kHeader = 8 + size_t(kIbsp38LumpCount) * 8;
    std::vector<int> order(kIbsp38LumpCount);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return parsed.lumps[a].offset < parsed.lumps[b].offset; });
    std::vector<uint8_t> out(map.begin(), map.begin() + ptrdiff_t(kHeader));
    for (const int lump : order) {
        out.resize((out.size() + 3) & ~size_t{3}, 0);
        const uint32_t offset = uint32_t(out.size());
        std::span<const uint8_t> bytes = lump == kQ2LumpVisibility
                                             ? visibility
                                             : map.subspan(parsed.lumps[lump].offset, parsed.lumps[lump].length);
        out.insert(out.end(), bytes.begin(), bytes.end());
        put_u32(out, 8 + size_t(lump) * 8, offset);
        put_u32(out, 12 + size_t(lump) * 8, uint32_t(bytes.size()));
    }
    return out;
}

} // namespace pvs::quake2
