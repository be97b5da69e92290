// Writing a Quake 2 map's visibility lump (IBSP 38): what a Quake 2 vis leaves in the map.
//
// The lump: numclusters, then per cluster the byte offsets (from the lump's start) of its PVS row
// and its PHS row, then the rows, each compressed as Quake's (visibility/codec/quake_rle.h), every
// cluster's PVS row and then its PHS row, in cluster order. A row identical to one already written
// is not written again: its offset points at the first (the engine reads rows by offset).
//
// The file: the header and the 19-lump directory, then the lumps in the order the input stored
// them, each at a 4-byte boundary, the visibility lump replaced and every other lump's bytes
// copied unchanged (only their offsets move). Throws FileError (read_ibsp38's) for a file it
// cannot read, and std::invalid_argument when the rows do not match the cluster count.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake2 {

// pvs_rows, phs_rows: `clusters` rows of words_for(clusters) words.
std::vector<uint8_t> encode_visibility_lump(std::span<const uint64_t> pvs_rows, std::span<const uint64_t> phs_rows,
                                            uint32_t clusters);

// The map's bytes with `visibility` as its visibility lump.
std::vector<uint8_t> with_visibility_lump(std::span<const uint8_t> map, std::span<const uint8_t> visibility,
                                          const std::string& file);

} // namespace pvs::quake2
