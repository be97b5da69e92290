// Quake 2 maps, IBSP version 38: the header's lump directory, the leaves' clusters and areas,
// and the visibility lump (numclusters, then per cluster the byte offsets of its PVS and PHS
// rows inside the lump, then the rows, each compressed as Quake's: visibility/codec/quake_rle.h).
//
// Contract. read_ibsp38 checks what it reads and throws FileError naming the file, the absolute
// offset and the problem: a header that is not "IBSP" 38 (a Quake 3 IBSP 46 is named as such), a
// lump outside the file, a leaf lump not a whole number of 28-byte records, a cluster count that
// does not fit the lump, a row offset outside the lump, a row that ends before it is full, a leaf
// naming a cluster past the count. An empty visibility lump (an unvised map) reads as 0 clusters
// and no rows. Rows come back decoded, one row of `clusters` bits per cluster.
#pragma once

#include "visibility/pvs.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake2 {

inline constexpr int kIbsp38LumpCount = 19;
enum Ibsp38Lump : int {
    kQ2LumpEntities = 0, kQ2LumpPlanes, kQ2LumpVertexes, kQ2LumpVisibility, kQ2LumpNodes, kQ2LumpTexinfo,
    kQ2LumpFaces, kQ2LumpLighting, kQ2LumpLeafs, kQ2LumpLeafFaces, kQ2LumpLeafBrushes, kQ2LumpEdges,
    kQ2LumpSurfEdges, kQ2LumpModels, kQ2LumpBrushes, kQ2LumpBrushSides, kQ2LumpPop, kQ2LumpAreas,
    kQ2LumpAreaPortals
};
inline constexpr uint32_t kQ2LeafBytes = 28;
inline constexpr int32_t kMaxQ2Clusters = 65536; // Quake 2's MAX_MAP_LEAFS: no map has more clusters

struct Ibsp38LumpSpan {
    uint32_t offset = 0, length = 0;
};

struct Q2Leaf {
    int32_t contents = 0;
    int16_t cluster = -1; // -1: no cluster (solid, or outside the vis)
    int16_t area = 0;
};

struct Ibsp38File {
    Ibsp38LumpSpan lumps[kIbsp38LumpCount];
    std::vector<Q2Leaf> leaves;
    uint32_t clusters = 0; // of the visibility lump (0: not vised)
    std::vector<uint32_t> pvs_offsets, phs_offsets; // per cluster, bytes into the lump
    std::vector<uint64_t> pvs_rows, phs_rows;       // decoded: clusters rows of words_for(clusters)
    // Each row's compressed length as stored (its bytes: the file at the visibility lump's offset
    // plus the row's offset), for byte-exact comparisons.
    std::vector<uint32_t> pvs_lengths, phs_lengths;
};

// Whether the bytes begin like a Quake 2 map ("IBSP", version 38).
bool looks_like_ibsp38(std::span<const uint8_t> bytes);

Ibsp38File read_ibsp38(std::span<const uint8_t> bytes, const std::string& file);

} // namespace pvs::quake2
