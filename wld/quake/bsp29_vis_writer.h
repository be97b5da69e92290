// A new PVS into a Quake BSP file (29, BSP2 or 2PSB: bsp_layout.h): what a vis tool does to the
// map qbsp wrote (../shared/formats/quake-doom-hepvs.md §1.10, §3.6), and, when given, the leaves'
// ambient sound levels it writes too (ambient_sounds.h).
//
// Input: the original file's bytes and a Pvs over its regions, numbered as bsp29_reader.h maps
// them (region r = BSP leaf r+1 = PVS bit r, for leaves 1..models[0].visleafs), so the Pvs must
// have exactly visleafs regions.
//
// Output: a new file in which
//  - the VISIBILITY lump holds one Quake-RLE row (visibility/codec/quake_rle.h) of visleafs bits
//    per region, in region order, except that a row identical to an earlier one is not written
//    again: its leaf points at the earlier copy (as id's and ericw's vis do);
//  - leaf r+1's visofs is the byte offset of region r's row in that lump, or -1 when the Pvs
//    row is missing (Pvs::row_missing: the engine shows everything there, as the reader reads
//    -1); leaf 0 (the shared solid leaf) and the leaves after visleafs (brush entities', never
//    looked up for vis) get -1;
//  - with `ambient` (one entry per vis leaf), leaf r+1's four ambient bytes are ambient[r];
//    without, they keep the file's;
//  - every other byte of every other lump is unchanged, including the rest of each leaf record.
//    The version field or variant tag is kept.
//    Lumps keep their order in the file, each starts on a 4-byte boundary right after the
//    previous one (padding is zero), and the header's lump directory is rewritten. Bytes of the
//    original that no lump covers (padding, garbage) are not kept.
// Errors: a header or lump range the reader would refuse, or a leafs/models lump too short for
// visleafs, throws FileError naming the file, the offset and the problem; a Pvs whose region
// count is not visleafs throws std::invalid_argument. A visibility lump over 2 GiB (int32
// offsets) throws std::invalid_argument.
#pragma once

#include "visibility/pvs.h"
#include "wld/quake/ambient_sounds.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake {

struct Bsp29VisStats {
    uint32_t rows = 0;        // regions given a row (not missing)
    uint32_t unique_rows = 0; // rows actually stored in the lump
    size_t visdata_bytes = 0; // the new VISIBILITY lump's length
};

std::vector<uint8_t> write_bsp29_vis(std::span<const uint8_t> original, const Pvs& pvs,
                                     const std::string& file_for_errors, Bsp29VisStats* stats = nullptr,
                                     std::span<const AmbientLevels> ambient = {});

} // namespace pvs::quake
