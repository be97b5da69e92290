#include "wld/quake/bsp29_vis_writer.h"

#include "visibility/codec/quake_rle.h"
#include "wld/common/byte_reader.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace pvs::quake {

namespace {

// The lump table of BSP 29 (same numbering as bsp29_reader.cpp).
constexpr int kLumpCount = 15;
constexpr int kVisibilityLump = 4;
constexpr int kLeafsLump = 10;
constexpr int kModelsLump = 14;
constexpr uint64_t kHeaderBytes = 4 + 8 * kLumpCount;
constexpr uint64_t kLeafBytes = 28;
constexpr uint64_t kLeafVisofs = 4;
constexpr uint64_t kModelBytes = 64;
constexpr uint64_t kModelVisleafs = 52;

struct LumpRange {
    uint64_t offset = 0;
    uint64_t length = 0;
};

std::array<LumpRange, kLumpCount> read_directory(const ByteReader& in)
{
    const auto version = in.read<int32_t>(0, "header version");
    if (version != 29)
        in.fail(0, "not a Quake BSP 29 file: version is " + std::to_string(version));
    in.require(0, kHeaderBytes, "header");
    std::array<LumpRange, kLumpCount> lumps;
    for (int i = 0; i < kLumpCount; ++i) {
        const uint64_t at = 4 + 8 * uint64_t(i);
        const auto offset = in.read<int32_t>(at, "lump offset");
        const auto length = in.read<int32_t>(at + 4, "lump length");
        if (offset < 0 || length < 0)
            in.fail(at, "lump " + std::to_string(i) + " has a negative offset or length");
        in.require(uint64_t(offset), uint64_t(length), ("lump " + std::to_string(i)).c_str());
        lumps[size_t(i)] = {uint64_t(offset), uint64_t(length)};
    }
    return lumps;
}

uint32_t read_visleafs(const ByteReader& in, const std::array<LumpRange, kLumpCount>& lumps)
{
    const LumpRange& models = lumps[kModelsLump];
    if (models.length < kModelBytes)
        in.fail(models.offset, "the models lump is empty (no world model)");
    const auto visleafs = in.read<int32_t>(models.offset + kModelVisleafs, "model visleafs");
    const uint64_t leaf_count = lumps[kLeafsLump].length / kLeafBytes;
    if (lumps[kLeafsLump].length % kLeafBytes != 0)
        in.fail(4 + 8 * kLeafsLump + 4, "leafs lump length " + std::to_string(lumps[kLeafsLump].length) +
                                            " is not a multiple of its record size 28");
    if (visleafs < 0 || uint64_t(visleafs) >= std::max<uint64_t>(leaf_count, 1))
        in.fail(models.offset + kModelVisleafs, "world visleafs " + std::to_string(visleafs) +
                                                    " must be below the leaf count " + std::to_string(leaf_count));
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
                                     const std::string& file_for_errors, Bsp29VisStats* stats)
{
    const ByteReader in(original, file_for_errors);
    const std::array<LumpRange, kLumpCount> lumps = read_directory(in);
    const uint32_t visleafs = read_visleafs(in, lumps);
    if (pvs.region_count() != visleafs)
        throw std::invalid_argument("the PVS has " + std::to_string(pvs.region_count()) + " regions but " +
                                    file_for_errors + " has " + std::to_string(visleafs) + " vis leaves");
    const VisData vis = encode_rows(pvs);

    // Lumps in their order in the original file (ties by index), packed on 4-byte boundaries.
    std::array<int, kLumpCount> order;
    for (int i = 0; i < kLumpCount; ++i)
        order[size_t(i)] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return lumps[size_t(a)].offset < lumps[size_t(b)].offset; });
    std::vector<uint8_t> out(kHeaderBytes, 0);
    std::memcpy(out.data(), original.data(), 4); // version 29
    uint64_t leafs_at = 0;
    for (const int lump : order) {
        out.resize((out.size() + 3) & ~size_t{3}, 0);
        const uint64_t at = out.size();
        const std::span<const uint8_t> body =
            lump == kVisibilityLump ? std::span<const uint8_t>(vis.bytes)
                                    : original.subspan(lumps[size_t(lump)].offset, lumps[size_t(lump)].length);
        if (at + body.size() > uint64_t(std::numeric_limits<int32_t>::max()))
            throw std::invalid_argument("the new file would exceed 2 GiB");
        out.insert(out.end(), body.begin(), body.end());
        put_i32(out, 4 + 8 * uint64_t(lump), int32_t(at));
        put_i32(out, 8 + 8 * uint64_t(lump), int32_t(body.size()));
        if (lump == kLeafsLump)
            leafs_at = at;
    }
    out.resize((out.size() + 3) & ~size_t{3}, 0);

    const uint64_t leaf_count = lumps[kLeafsLump].length / kLeafBytes;
    for (uint64_t leaf = 0; leaf < leaf_count; ++leaf) {
        const bool region_leaf = leaf >= 1 && leaf <= visleafs;
        put_i32(out, leafs_at + leaf * kLeafBytes + kLeafVisofs, region_leaf ? vis.row_offset[leaf - 1] : -1);
    }
    if (stats) {
        stats->rows = uint32_t(std::count_if(vis.row_offset.begin(), vis.row_offset.end(), [](int32_t o) { return o >= 0; }));
        stats->unique_rows = vis.unique_rows;
        stats->visdata_bytes = vis.bytes.size();
    }
    return out;
}

} // namespace pvs::quake
