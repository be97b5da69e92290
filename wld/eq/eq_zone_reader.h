// EverQuest zone archive (.s3d) -> zone model (../shared/formats/eq-s3d-wld.md; the layers
// below are wld/eq/pfs_archive.h, wld_file.h, wld_mesh.h, wld_material.h). The writer is
// eq_zone_writer.h; docs/formats-eq.md "EverQuest zones ↔ the zone model" has the reasons.
//
// Which WLD: the member `<archive stem>.wld` (case-insensitive), else the only .wld member
// holding a 0x21 bsp tree; otherwise a FileError listing the members.
//
// Mapping to the zone model:
//  - Region k (0-based) is the (k+1)-th 0x22 fragment in file order (§7.3): 0x21 leaf region
//    k+1, 0x29 value k, VISLIST position k. Coordinates stay WLD coordinates (z up, no swap).
//  - Tree: the first 0x21 (a note when there are more). Node 1 is the root. A node with
//    region k+1 >= 1 is a leaf of region k (WQ's test, made first; children it also has are
//    ignored, with a note); a node with region 0 and no children, and every missing child (0),
//    is a kLeafOutside leaf of its own. Internal nodes keep their plane as normal = n,
//    dist = -d, so dot(n, p) - dist is the spec's s = n·p + d and s >= 0 goes front
//    (TieRule::OnPlaneGoesFront, §3.3). Zone nodes are numbered in preorder, front first.
//    parse_bsp_tree has checked children, region numbers and that no node is reached twice.
//    A region that is no leaf or several leaves is allowed (noted).
//  - Faces: each region's 0x36 (its mesh_ref) is copied into the zone mesh once, however many
//    regions name it, with the winding as stored (contested, §9.6: use two-sided). Vertices are
//    shared: each distinct (position, uv) as decoded (uv zeros when the mesh has none) is one
//    zone vertex, whichever meshes hold it. Consecutive triangles of one material that form a
//    convex planar polygon are one zone Face (convex_face_builder.h); other triangles a Face
//    each. The region lists that mesh's faces. A legacy 0x2C mesh is not read (noted).
//  - Region bounds: its mesh's vertices; without a mesh its sphere's box (center ± radius);
//    without a sphere (flag bit 0 clear, or a radius that is negative or not finite), empty.
//  - Materials: one per distinct (texture file ignoring case, visible) pair over every 0x31
//    palette in file order, named by the texture file as first stored; kMaterialInvisible when
//    material_is_visible says no, kMaterialSky for a sky-dome render method. A mesh without a
//    palette uses an invisible material named "". Pixels come from the archive member of that
//    name, decoded by its magic: DDS (dds_decode.h) or BMP (stb_image_io.h); otherwise none, and
//    a note names it with the reason. They are kept palettized when they fit (MaterialPixels).
//  - PVS: region k's first VISLIST decoded (byte or word form); no list or range_count 0 is a
//    missing row (all visible, as WQ). No row in the file at all: no baked PVS, and a note.
//    A malformed list throws FileError at the byte where decoding stopped.
//  - Flags: each 0x29's classified type (classify_region_type, the name first) ORed into its
//    regions; each zone-line 0x29 is one ZoneLine ("zone 255 point 3", "zone 45 (x, y, z)
//    heading h", or "unreadable destination"), bounded by the union of its regions' bounds,
//    and Region::zone_line of its regions (the last such fragment wins).
//  - ZoneSource: "EverQuest S3D/WLD", the WLD version, counts and notes.
// Every problem throws pvs::FileError naming the archive and member ("zone.s3d: member
// 'zone.wld'"), the offset inside that member and the fragment.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <string>

namespace pvs::eq {

// True when the bytes start like a PFS archive (the magic "PFS " at offset 4, §1.2).
bool looks_like_pfs(std::span<const uint8_t> bytes);

Zone load_eq_zone(std::span<const uint8_t> s3d, const std::string& file);

} // namespace pvs::eq
