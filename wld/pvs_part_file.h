// A shard's part file (.pvsp): the rows one shard of a bake computed (`pvscope bake --shard K/N`),
// which `pvscope merge` joins into the file a one-machine bake writes. Little-endian:
//
//   0   char[8]  "PVSPART1"
//   8   u32      version (1)
//   12  u64      zone hash: FNV-1a 64 of the files the bake read (bake_shard.h says which)
//   20  u32      shard K, 24 u32 shards N (K < N)
//   28  u32      rows (the zone's PVS rows: regions, or view cells of a grid zone)
//   32  u32      regions (bits per row)
//   36  u32      how the parts' rows join: 0, each row is in one part (its source's); 1, every
//                part holds every row and the merge ORs them (a source's work sets bits anywhere)
//   40  u32      T, then T bytes: the bake's settings as text (the method and every option that
//                changes a bit or a written byte; the merge checks that all parts agree)
//   ..  u32      S, then S u32: the rows this shard computed, ascending, each < rows
//   ..  u64      L, then L bytes: zlib of the S rows, words_for(regions) u64 each
//
// Nothing may follow, and no row sets a bit past the last region. Reading throws FileError
// naming the file, the offset and the problem; a hostile length never allocates more than the
// file could hold.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs {

enum class PartRows : uint32_t { Own = 0, Union = 1 };

struct PvsPart {
    uint64_t zone_hash = 0;
    PartRows join = PartRows::Own;
    uint32_t shard = 0, shards = 1;
    uint32_t row_count = 0, region_count = 0;
    std::string settings;
    std::vector<uint32_t> sources; // ascending
    std::vector<uint64_t> rows;    // sources.size() rows of words_for(region_count) words

    size_t words_per_row() const { return (size_t(region_count) + 63) / 64; }
};

std::vector<uint8_t> encode_pvs_part(const PvsPart& part);
PvsPart decode_pvs_part(std::span<const uint8_t> bytes, const std::string& name);

// FNV-1a 64 of `bytes`, continuing from `hash` (start: kFnvOffset).
inline constexpr uint64_t kFnvOffset = 0xcbf29ce484222325ull;
uint64_t fnv1a64(std::span<const uint8_t> bytes, uint64_t hash = kFnvOffset);

} // namespace pvs
