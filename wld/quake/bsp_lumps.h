// The lump table of a Quake BSP of any variant bsp_layout.h knows (29, BSP2, 2PSB): the header
// read and checked once, then record addresses by lump and index. What the reader, the vis
// writer and the ambient sounds share.
#pragma once

#include "wld/common/byte_reader.h"
#include "wld/quake/bsp_layout.h"

#include <cstdint>

namespace pvs::quake {

enum BspLump : int {
    kLumpEntities = 0, kLumpPlanes, kLumpTextures, kLumpVertexes, kLumpVisibility, kLumpNodes, kLumpTexinfo,
    kLumpFaces, kLumpLighting, kLumpClipnodes, kLumpLeafs, kLumpMarksurfaces, kLumpEdges, kLumpSurfedges,
    kLumpModels, kBspLumpCount
};

const char* bsp_lump_name(BspLump lump);

struct BspLumpSpan {
    uint64_t offset = 0;
    uint64_t length = 0;
    uint32_t count = 0; // records
};

struct BspLumps {
    BspLayout layout;
    BspLumpSpan lumps[kBspLumpCount];

    uint32_t record_size(BspLump lump) const;
    uint64_t record(BspLump lump, uint32_t index) const
    {
        return lumps[lump].offset + uint64_t{index} * record_size(lump);
    }
    // Throws FileError (at `at`) unless 0 <= index < the lump's record count.
    void check_index(const ByteReader& in, BspLump lump, int64_t index, uint64_t at, const char* what) const;
};

// Reads the variant and the lump directory. Throws FileError for a file that is not one of the
// variants (naming what its header says: a Quake 2 or Quake 3 IBSP, Half-Life's 30, ...), a lump
// outside the file, or a fixed-size lump whose length is not a multiple of its record size.
BspLumps read_bsp_lumps(const ByteReader& in);

} // namespace pvs::quake
