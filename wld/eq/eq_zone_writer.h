// Zone model -> EverQuest zone archive (.s3d): the WLD a zone's visibility needs plus its
// textures, written so that every reader ../shared/formats/eq-s3d-wld.md examined parses it
// alike (§7.2 order, §7.3 counting, §7.4 checklist). load_eq_zone (eq_zone_reader.h) reads it
// back; docs/formats-eq.md "EverQuest zones ↔ the zone model" has the reasons for each choice.
//
// The archive holds `<zone_name>.wld` and one 24-bit BMP per material that has pixels. The WLD,
// in the canonical order of §7.2:
//  - per material, in zone order: 0x03 (the texture file name) -> 0x04 (one frame) -> 0x05 ->
//    0x30, each type grouped; a visible material's render method is diffuse (0x80000001), sky
//    dome (0x8000000D) for a kMaterialSky one, and 0 for a kMaterialInvisible one (WQ and ZU
//    both read render method 0 as invisible; the sprite chain is kept so the name survives).
//  - one 0x31 palette listing every material, so palette index = zone material index.
//  - one 0x36 per region whose faces have triangles: the region's faces (each face's triangles)
//    sorted by material into face groups, the vertices they use copied (one copy per zone
//    vertex, or per zone vertex and uv shift, below), a normal per vertex (the area-weighted
//    mean of its triangles' normals), no colours. Positions are stored relative to the center
//    (the middle of the region's vertex bounds, rounded to whole units) at the finest scale
//    that fits; the writer moves them onto that grid first (until they stay put), so that
//    write -> read -> write is byte-identical. Old-version uvs (i16 / 256) hold [-128, 128):
//    a face whose uvs do not fit is moved by whole texture repeats (the same picture).
//  - the 0x21 tree: internal nodes in preorder (front first) with their planes (n, d = -dist);
//    a region leaf is an EQ leaf node (region id + 1, no children); a solid or outside leaf is
//    child 0 (WQ and ZU read a missing child as "no region").
//  - one 0x22 per region, in region order, in the §4.7 interoperable subset: its VISLIST is the
//    baked PVS row with the region's own bit set (a missing row: every region), or empty
//    (range_count 0) for every region when the zone has no baked PVS. Its sphere bounds the
//    region's mesh vertices; a region without a mesh gets a sphere whose bounding box holds the
//    region's bounds (center and radius on a 1/64 grid: the reader takes that box back).
//  - 0x29 per region type present, named WT_ZONE (water), LA_ZONE (lava), SLN_ZONE (slime),
//    DRP_ZONE (PvP), DRN_ZONE (ice), VWN_ZONE (vwater), then one per zone line i named
//    DRNTP00255<i, 6 digits>_ZONE: zone 255, zone point i (the target's name is not kept).
// Deterministic: the same zone and options give the same bytes.
#pragma once

#include "visibility/zone.h"
#include "wld/eq/wld_file.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pvs::eq {

struct EqWriteOptions {
    // kWldVersionOld (uvs as i16 / 256, readable by LQ too, §7.4.1) or kWldVersionNew (f32 uvs).
    uint32_t wld_version = kWldVersionOld;
    int zlib_level = 9; // write_pfs's; fixed so the bytes are reproducible
};

struct EqZoneArchive {
    std::vector<uint8_t> bytes;
    // What the archive cannot keep of the zone (sky flags, the tie rule, zone-line targets,
    // alpha, faces written into several regions, ...), one sentence each.
    std::vector<std::string> notes;
};

// Throws std::invalid_argument for a zone the format cannot express or that is inconsistent:
// a region that is not exactly one leaf of the tree (none, or two), a region mesh that would
// need more than 65535 vertices or faces (u16 counts: refused, not split), a face whose uvs
// span more than the old form's 256 repeats, a VISLIST over 65535 bytes, a zone line index over
// 999999, and out-of-range indices anywhere in the zone.
EqZoneArchive write_eq_zone_archive(const Zone& zone, const std::string& zone_name, const EqWriteOptions& options = {});

// The first face whose uvs the old WLD form cannot hold (they span more than its 256 repeats),
// or nothing: such a zone must be written with kWldVersionNew.
std::optional<uint32_t> face_beyond_old_wld_form(const Zone& zone);

// write_eq_zone_archive(...).bytes.
std::vector<uint8_t> write_eq_zone(const Zone& zone, const std::string& zone_name, const EqWriteOptions& options = {});

// The archive member each material's texture is written as (and the name its 0x03 stores): the
// material name lowercased, characters other than [a-z0-9_.-] replaced by '_', ".bmp" appended
// if missing, made unique (and CRC-unique) with "_2", "_3"... before the extension. "" becomes
// "texture.bmp". load_eq_zone names the materials it reads by these file names.
std::vector<std::string> eq_texture_file_names(const Zone& zone);

// The WLD member name for a zone name: lowercased, sanitized like the textures, + ".wld".
std::string eq_zone_wld_name(const std::string& zone_name);

} // namespace pvs::eq
