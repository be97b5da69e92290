#include "wld/quake/bsp29_vis_writer.h"

#include "visibility/codec/quake_rle.h"
#include "wld/common/byte_reader.h"
#include "wld/quake/bsp_lumps.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace pvs::quake {

namespace {

constexpr uint64_t kHeaderBytes = 4 + 8 * kBspLumpCount;
constexpr uint64_t kLeafVisofs = 4;

uint32_t read_visleafs(const ByteReader& in, const BspLumps& bsp)
{
    if (bsp.lumps[kLumpModels].count == 0)
        in.fail(bsp.lumps[kLumpModels].offset, "the models lump is empty (no world model)");
    const uint64_t at = bsp.record(kLumpModels, 0) + 52;
    const auto visleafs = in.read<int32_t>(at, "model visleafs");
    if (visleafs < 0 || uint64_t(visleafs) >= std::max<uint64_t>(bsp.lumps[kLumpLeafs].count, 1))
        in.fail(at, "world visleafs " + std::to_string(visleafs) + " must be below the leaf count " +
                        std::to_string(bsp.lumps[kLumpLeafs].count));
    return uint32_t(visleafs);
}

// The new visibility lump and each region's row offset in it (-1: missing row).
struct VisData {
    std::vector<uint8_t> bytes;
    std::vector<int32_t> row_offset;
    uint32_t unique_rows = 0;
};

VisData encode_rows(const Pvs& pvs)
{
    const uint32_t regions = pvs.region_count();
    VisData vis;
    vis.row_offset.assign(regions, -1);
    std::vector<uint64_t> row(pvs.words_per_row());
    std::vector<uint8_t> encoded;
    std::unordered_map<std::string_view, int32_t> offset_of_row; // keys view into `rows_seen`
    std::vector<std::string> rows_seen;
    rows_seen.reserve(regions); // no reallocation: the map's keys stay valid
    for (uint32_t r = 0; r < regions; ++r) {
        if (pvs.row_missing(r))
            continue;
        pvs.decode_row(r, row);
        encoded.clear();
        encode_quake_rle(row, regions, encoded);
        std::string key(encoded.begin(), encoded.end());
        if (const auto found = offset_of_row.find(key); found != offset_of_row.end()) {
            vis.row_offset[r] = found->second;
            continue;
        }
        if (vis.bytes.size() > size_t(std::numeric_limits<int32_t>::max()) - encoded.size())
            throw std::invalid_argument("the visibility lump would exceed 2 GiB");
        vis.row_offset[r] = int32_t(vis.bytes.size());
        vis.bytes.insert(vis.bytes.end(), encoded.begin(), encoded.end());
        rows_seen.push_back(std::move(key));
        offset_of_row.emplace(rows_seen.back(), vis.row_offset[r]);
        ++vis.unique_rows;
    }
    return vis;
}

void put_i32(std::vector<uint8_t>& out, uint64_t at, int32_t value) { std::memcpy(out.data() + at, &value, 4); }

} // namespace

std::vector<uint8_t> write_bsp29_vis(std::span<const uint8_t> original, const Pvs& pvs,
                                     const std::string& file_for_errors, Bsp29VisStats* stats,
                                     std::span<const AmbientLevels> ambient)
{
    const ByteReader in(original, file_for_errors);
    const BspLumps bsp = read_bsp_lumps(in);
    const uint32_t visleafs = read_visleafs(in, bsp);
    if (pvs.region_count() != visleafs)
        throw std::invalid_argument("the PVS has " + std::to_string(pvs.region_count()) + " regions but " +
                                    file_for_errors + " has " + std::to_string(visleafs) + " vis leaves");
    if (!ambient.empty() && ambient.size() != visleafs)
        throw std::invalid_argument("ambient levels for " + std::to_string(ambient.size()) + " leaves, " +
                                    std::to_string(visleafs) + " vis leaves in " + file_for_errors);
    const VisData vis = encode_rows(pvs);

    // Lumps in their order in the original file (ties by index), packed on 4-byte boundaries.
    std::array<int, kBspLumpCount> order;
    for (int i = 0; i < kBspLumpCount; ++i)
        order[size_t(i)] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return bsp.lumps[a].offset < bsp.lumps[b].offset; });
    std::vector<uint8_t> out(kHeaderBytes, 0);
    std::memcpy(out.data(), original.data(), 4); // the version or variant tag
    uint64_t leafs_at = 0;
    for (const int lump : order) {
        out.resize((out.size() + 3) & ~size_t{3}, 0);
        const uint64_t at = out.size();
        const std::span<const uint8_t> body =
            lump == kLumpVisibility ? std::span<const uint8_t>(vis.bytes)
                                    : original.subspan(bsp.lumps[lump].offset, bsp.lumps[lump].length);
        if (at + body.size() > uint64_t(std::numeric_limits<int32_t>::max()))
            throw std::invalid_argument("the new file would exceed 2 GiB");
        out.insert(out.end(), body.begin(), body.end());
        put_i32(out, 4 + 8 * uint64_t(lump), int32_t(at));
        put_i32(out, 8 + 8 * uint64_t(lump), int32_t(body.size()));
        if (lump == kLumpLeafs)
            leafs_at = at;
    }
    out.resize((out.size() + 3) & ~size_t{3}, 0);

    const uint64_t leaf_bytes = bsp.layout.leaf_size;
    for (uint64_t leaf = 0; leaf < bsp.lumps[kLumpLeafs].count; ++leaf) {
        const bool region_leaf = leaf >= 1 && leaf <= visleafs;
        const uint64_t record = leafs_at + leaf * leaf_bytes;
        put_i32(out, record + kLeafVisofs, region_leaf ? vis.row_offset[leaf - 1] : -1);
        if (region_leaf && !ambient.empty())
            std::memcpy(out.data() + record + bsp.layout.leaf_ambient, ambient[leaf - 1].data(), 4);
    }
    if (stats) {
        stats->rows = uint32_t(std::count_if(vis.row_offset.begin(), vis.row_offset.end(), [](int32_t o) { return o >= 0; }));
        stats->unique_rows = vis.unique_rows;
        stats->visdata_bytes = vis.bytes.size();
    }
    return out;
}

} // namespace pvs::quake
