// A PVS into a Doom map's GL nodes, as glVIS does (../shared/formats/quake-doom-hepvs.md §4.1,
// §4.3-§4.5): the GL_PVS lump of the map's GL group and, on request, a REJECT rebuilt from it.
//
// Input: a Pvs over the map's GL subsectors (rows = regions = subsectors, numbered as GL_SSECT
// numbers them) and the MapSource that read_doom_map filled (doom_map.h).
//
// Output, in the file holding the GL group (source.gl_path, a .gwa or the WAD itself):
//  - GL_PVS at gl_marker + 5, right after GL_NODES: numsubsectors uncompressed rows
//    (visibility/codec/glvis_rows.h). A lump named GL_PVS there (glBSP's empty placeholder, an
//    older glVIS run) is replaced; otherwise one is inserted (ZDBSP writes none), which moves
//    every later lump one index up.
//  - With rebuild_reject, the map's REJECT in source.wad_path (the lump named REJECT after
//    map_marker and before the next map marker) becomes ceil(n^2/8) bytes for n sectors: all
//    1s (everything rejected, padding bits included, as glVIS starts), then bit
//    sec_i * n + sec_j (LSB first) cleared whenever subsector j is visible from subsector i.
//  - Everything else is kept: lump order, names (with their case), every other lump's bytes.
//    The directory is rewritten, each lump on a 4-byte boundary (write_wad); bytes no lump
//    covers are dropped. When the WAD and the GL file are one file, both lumps land in one
//    rewrite.
// Files are replaced atomically (a temporary beside the file, then rename). With backup the
// original bytes are kept first as <stem>.~gw for a .gwa and <stem>.~wa for anything else
// (glVIS's names), replacing an older backup.
//
// Errors. FileError (naming the file and the directory entry) when the file no longer matches
// the MapSource: gl_marker is not a lump named GL_... followed by GL_VERT, GL_SEGS, GL_SSECT and
// GL_NODES; map_marker is not followed by THINGS and LINEDEFS; the map has no REJECT; its
// SECTORS does not hold sector_count records; GL_SSECT's size fits no GL version. The write
// also fails with FileError when a file cannot be read or replaced (nothing is half-written).
// std::invalid_argument when the Pvs is not square or its size is not the file's subsector
// count, when (with rebuild_reject) sector_of_subsector does not have one sector below
// sector_count per subsector, or when a file would outgrow the WAD's 2 GiB offsets.
// MapSource::gl_pvs_present is not consulted: the file decides whether GL_PVS is replaced.
#pragma once

#include "visibility/pvs.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/wad_file.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs::doom {

struct GlPvsWriteOptions {
    bool rebuild_reject = false; // also rewrite the map's REJECT lump from the PVS (glVIS's default; §4.5)
    bool backup = true;          // keep the old file as .~gw (a .gwa) / .~wa (a .wad) as glVIS does, overwriting an older backup
};

struct GlPvsWriteResult {
    std::string gl_file;         // the file that got GL_PVS (source.gl_path)
    std::string backup_file;     // its backup, empty without one
    bool inserted = false;       // GL_PVS was inserted (there was none at gl_marker + 5)
    bool reject_written = false; // REJECT was rewritten
    // When REJECT went to a WAD other than gl_file: that WAD's backup (empty otherwise).
    std::string wad_backup_file;
};

// Writes `pvs` as the GL_PVS lump of the map `source` describes, and its REJECT with
// options.rebuild_reject (sector_of_subsector and sector_count are only read then).
GlPvsWriteResult write_gl_pvs(const MapSource& source, const Pvs& pvs, std::span<const uint32_t> sector_of_subsector,
                              uint32_t sector_count, const GlPvsWriteOptions& options = {});

// The in-memory core, for tests and fuzzing: the new bytes of `file` with GL_PVS set to
// `gl_pvs_lump` in the group at gl_marker / REJECT set to `reject_lump` in the map at
// map_marker. Same checks (FileError) and same preservation rules as above.
std::vector<uint8_t> with_gl_pvs(const WadFile& file, size_t gl_marker, std::span<const uint8_t> gl_pvs_lump);
std::vector<uint8_t> with_reject(const WadFile& file, size_t map_marker, std::span<const uint8_t> reject_lump);

// The GL_PVS lump bytes of a square Pvs (std::invalid_argument otherwise).
std::vector<uint8_t> gl_pvs_lump(const Pvs& pvs);
// The REJECT lump glVIS derives from a subsector PVS (see above). std::invalid_argument when
// the Pvs is not square, sector_of_subsector.size() != pvs.region_count(), or a sector is
// >= sector_count.
std::vector<uint8_t> reject_from_pvs(const Pvs& pvs, std::span<const uint32_t> sector_of_subsector,
                                     uint32_t sector_count);

// The number of subsectors in the GL group at gl_marker (from GL_SSECT's size and the group's
// version: V1/V2 4-byte records, V3 "gNd3" + 8-byte, V5 8-byte). Throws FileError as above.
size_t gl_subsector_count(const WadFile& file, size_t gl_marker);

// Where glVIS keeps the previous version of `path`: .gwa -> .~gw, anything else -> .~wa.
std::string gl_pvs_backup_path(const std::string& path);

} // namespace pvs::doom
